// A serialiser of VTK's XML formats as VTK 9.1 writes them (version 0.1, little endian, UInt64
// headers, appended raw data): UnstructuredGrid (.vtu) of line cells and PolyData (.vtp) of
// vertices and lines. Arrays are written as they are, or in compressed blocks of 32 kB with
// LZ4 or zlib, the layout of vtkXMLWriter with vtkLZ4DataCompressor / vtkZLibDataCompressor.
// The files read back through VTK's own XML readers to the last bit (tests/test_vtu_series.cpp).
#pragma once

#include "xml_dataset.hpp"

#include <string>

namespace plastica {

// ParaView 5.11 reads all three; the default is chosen by measurement (README, Performance).
enum class Compression { none, lz4, zlib };

std::string unstructured_grid_xml(const XmlDataset& data, Compression compression = Compression::none);
std::string poly_data_xml(const XmlDataset& data, Compression compression = Compression::none);

} // namespace plastica
