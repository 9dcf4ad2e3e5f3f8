// A serialiser of VTK's XML formats as VTK 9.1 writes them (version 0.1, little endian, UInt64
// headers, appended raw data): UnstructuredGrid (.vtu) of line cells and PolyData (.vtp) of
// vertices and lines. Arrays are written as they are, or in compressed blocks of 32 kB with
// LZ4 or zlib, the layout of vtkXMLWriter with vtkLZ4DataCompressor / vtkZLibDataCompressor.
// The files read back through VTK's own XML readers to the last bit (tests/test_vtu_series.cpp).
#pragma once

#include "xml_dataset.hpp"

#include <string>
#include <vector>

namespace plastica {

// ParaView 5.11 reads all three; the default is chosen by measurement (docs/performance.md).
enum class Compression { none, lz4, zlib };

std::string unstructured_grid_xml(const XmlDataset& data, Compression compression = Compression::none);

// Where an array's values lie in a file's appended block.
struct ArraySlot {
    const char* section = ""; // "PointData", "CellData", "FieldData", "Points", "Cells"
    std::string name;
    const char* type = ""; // VTK's name of the value type: "Float64", "Int32", "String", …
    int components = 1;
    std::size_t tuples = 0;
    std::size_t bytes = 0;
    std::size_t offset = 0; // of the array's header; its values follow it
};

// An uncompressed grid file kept from step to step of a series.
struct UncompressedGridFile {
    std::string bytes;           // the file
    std::size_t block_start = 0; // where its appended block begins
    std::vector<ArraySlot> slots; // each array's place in the block, in the order written
    std::string active_vectors;
};

// The uncompressed file of `data`, in `file`: where `file` holds the same arrays in the same order
// (what their tags say: element, name, type, components, tuples; and their byte counts), as a
// series' steps do, only their values are overwritten, and the text, which would come out the
// same, is not written again; otherwise it is written whole.
const std::string& write_unstructured_grid(const XmlDataset& data, UncompressedGridFile& file);
std::string poly_data_xml(const XmlDataset& data, Compression compression = Compression::none);

} // namespace plastica
