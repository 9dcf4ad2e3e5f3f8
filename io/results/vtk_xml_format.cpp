#include "vtk_xml_format.hpp"

#include "xml_text.hpp"

#include <lz4.h>
#include <zlib.h>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <stdexcept>

namespace plastica {

namespace {

constexpr std::size_t block_size = 32768; // vtkXMLWriter's default

// The appended block: each array is its header (a byte count, or the block table of a
// compressed array) followed by its bytes; the XML refers to it by its offset in the block.
class Appended {
public:
    // `bytes`: the arrays' raw size, which an uncompressed block holds with a header each.
    Appended(Compression compression, std::size_t bytes) : compression_(compression) {
        if (compression_ == Compression::none) block_.reserve(bytes + 64 * sizeof(std::uint64_t));
    }

    std::size_t add(const void* data, std::size_t bytes) {
        const std::size_t offset = block_.size();
        if (compression_ == Compression::none) {
            put(bytes);
            block_.append(static_cast<const char*>(data), bytes);
        } else {
            add_compressed(static_cast<const char*>(data), bytes);
        }
        return offset;
    }
    const std::string& bytes() const { return block_; }

private:
    void put(std::uint64_t value) { block_.append(reinterpret_cast<const char*>(&value), sizeof value); }

    // [blocks, block size, size of a partial last block (0 if none), compressed size of each
    // block], then the compressed blocks.
    void add_compressed(const char* data, std::size_t bytes) {
        const std::size_t full = bytes / block_size, last = bytes % block_size;
        const std::size_t blocks = full + (last > 0 ? 1 : 0);
        put(blocks);
        put(block_size);
        put(last);
        const std::size_t table = block_.size();
        block_.append(blocks * sizeof(std::uint64_t), '\0');
        for (std::size_t b = 0; b < blocks; ++b) {
            const std::size_t size = std::min(block_size, bytes - b * block_size);
            const std::uint64_t packed = compress(data + b * block_size, size);
            std::copy_n(reinterpret_cast<const char*>(&packed), sizeof packed, &block_[table + b * sizeof packed]);
        }
    }

    std::size_t compress(const char* data, std::size_t size) {
        const std::size_t at = block_.size();
        if (compression_ == Compression::lz4) {
            block_.resize(at + static_cast<std::size_t>(LZ4_compressBound(static_cast<int>(size))));
            const int packed = LZ4_compress_default(data, &block_[at], static_cast<int>(size), static_cast<int>(block_.size() - at));
            if (packed <= 0) throw std::runtime_error("LZ4 could not compress an array");
            block_.resize(at + static_cast<std::size_t>(packed));
            return static_cast<std::size_t>(packed);
        }
        uLongf packed = compressBound(static_cast<uLong>(size));
        block_.resize(at + packed);
        if (compress2(reinterpret_cast<Bytef*>(&block_[at]), &packed, reinterpret_cast<const Bytef*>(data), static_cast<uLong>(size), 5) != Z_OK)
            throw std::runtime_error("zlib could not compress an array");
        block_.resize(at + packed);
        return packed;
    }

    Compression compression_;
    std::string block_;
};


// The XML is appended piece by piece: a step's file has some forty tags, and building each from
// temporary strings cost the writer's thread more allocations than the rest of the step.
struct Writer {
    std::string xml;
    Appended appended;
    // Where each array's values lie in the appended block, filled as arrays are added when
    // `record_slots` (a file to be kept for refilling; other files need no record).
    std::vector<ArraySlot> slots;
    bool record_slots = false;
    // A file whose values are overwritten in place (write_unstructured_grid): no text is written,
    // and each array's values go to its slot while the arrays match the slots.
    UncompressedGridFile* refill = nullptr;
    bool refill_fits = true;
    std::size_t refilled = 0; // arrays met while refilling
    std::size_t block_start = 0; // where the appended block begins in the finished file
    const char* section = "";    // the element the arrays being added belong to

    explicit Writer(Compression c, std::size_t array_bytes) : appended(c, array_bytes) { xml.reserve(8192); }
    explicit Writer(UncompressedGridFile& file) : appended(Compression::none, 0), refill(&file) {}

    void piece(const char* text) {
        if (!refill) xml += text;
    }
    void piece(const std::string& text) {
        if (!refill) xml += text;
    }
    void piece(std::size_t number) {
        if (refill) return;
        char digits[24];
        xml.append(digits, std::to_chars(digits, digits + sizeof digits, number).ptr);
    }
    template <class... Pieces>
    void put(const Pieces&... pieces) {
        (piece(pieces), ...);
    }
    void name(const std::string& text) {
        if (!refill) append_xml_escaped(xml, text);
    }

    // The array's values into the appended block; its offset there.
    std::size_t add(const std::string& array_name, const char* type, int components, std::size_t tuples, const void* data,
                    std::size_t bytes) {
        if (!refill) {
            const std::size_t offset = appended.add(data, bytes);
            if (record_slots) slots.push_back({section, array_name, type, components, tuples, bytes, offset});
            return offset;
        }
        const std::size_t index = refilled++;
        if (!refill_fits || index >= refill->slots.size()) {
            refill_fits = false;
            return 0;
        }
        const ArraySlot& slot = refill->slots[index];
        // What the array's tag says (the rest of the text follows from the tags and byte counts).
        if (slot.bytes != bytes || slot.tuples != tuples || slot.components != components || std::strcmp(slot.type, type) != 0 ||
            std::strcmp(slot.section, section) != 0 || slot.name != array_name) {
            refill_fits = false;
            return 0;
        }
        // After the array's header, its byte count.
        std::copy_n(static_cast<const char*>(data), bytes, &refill->bytes[refill->block_start + slot.offset + sizeof(std::uint64_t)]);
        return slot.offset;
    }

    void data_array(const XmlArray& array, const char* indent, bool tuples_attribute) {
        if (const auto* text = std::get_if<std::vector<std::string>>(&array.values)) {
            // Strings: each value's characters and a terminating NUL, in one block.
            std::string bytes;
            for (const std::string& s : *text) bytes.append(s).push_back('\0');
            const std::size_t offset = add(array.name, "String", 1, text->size(), bytes.data(), bytes.size());
            put(indent, "<Array type=\"String\" Name=\"");
            name(array.name);
            put("\" NumberOfTuples=\"", text->size(), "\" format=\"appended\" offset=\"", offset, "\"/>\n");
            return;
        }
        const char* type = nullptr;
        std::size_t offset = 0;
        if (const auto* real = std::get_if<std::vector<double>>(&array.values)) {
            type = "Float64";
            offset = add(array.name, type, array.components, array.tuples(), real->data(), real->size() * sizeof(double));
        } else {
            const auto& integer = std::get<std::vector<std::int32_t>>(array.values);
            type = "Int32";
            offset = add(array.name, type, array.components, array.tuples(), integer.data(), integer.size() * sizeof(std::int32_t));
        }
        put(indent, "<DataArray type=\"", type, "\" Name=\"");
        name(array.name);
        put("\"");
        if (array.components != 1) put(" NumberOfComponents=\"", static_cast<std::size_t>(array.components), "\"");
        if (tuples_attribute) put(" NumberOfTuples=\"", array.tuples(), "\"");
        put(" format=\"appended\" offset=\"", offset, "\"/>\n");
    }

    void attribute_data(const std::vector<XmlArray>& arrays, const char* tag, const std::string& vectors) {
        section = tag;
        put("      <", tag);
        if (!vectors.empty()) {
            put(" Vectors=\"");
            name(vectors);
            put("\"");
        }
        put(">\n");
        for (const XmlArray& a : arrays) data_array(a, "        ", false);
        put("      </", tag, ">\n");
    }

    void header(const char* type, Compression compression, const XmlDataset& data) {
        put("<?xml version=\"1.0\"?>\n<VTKFile type=\"", type, "\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt64\"");
        if (compression == Compression::lz4) put(" compressor=\"vtkLZ4DataCompressor\"");
        if (compression == Compression::zlib) put(" compressor=\"vtkZLibDataCompressor\"");
        put(">\n  <", type, ">\n");
        if (!data.field_data.empty()) {
            section = "FieldData";
            put("    <FieldData>\n");
            for (const XmlArray& a : data.field_data) data_array(a, "      ", true);
            put("    </FieldData>\n");
        }
    }

    void points(const XmlDataset& data) {
        section = "Points";
        put("      <Points>\n");
        data_array({"Points", 3, data.points}, "        ", false);
        put("      </Points>\n");
    }

    // A cell block: connectivity and offsets as Int64 (and the cell types as UInt8 in a grid).
    void cells(const char* tag, const std::vector<std::int64_t>& connectivity, int points_per_cell, bool with_types, std::uint8_t type) {
        const std::size_t count = connectivity.size() / static_cast<std::size_t>(points_per_cell);
        std::vector<std::int64_t> offsets(count);
        for (std::size_t c = 0; c < count; ++c) offsets[c] = static_cast<std::int64_t>((c + 1) * static_cast<std::size_t>(points_per_cell));
        section = tag;
        const std::size_t at_connectivity =
            add("connectivity", "Int64", 1, connectivity.size(), connectivity.data(), connectivity.size() * sizeof(std::int64_t));
        const std::size_t at_offsets = add("offsets", "Int64", 1, count, offsets.data(), offsets.size() * sizeof(std::int64_t));
        put("      <", tag, ">\n",
            "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" offset=\"", at_connectivity, "\"/>\n",
            "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"", at_offsets, "\"/>\n");
        if (with_types) {
            const std::vector<std::uint8_t> types(count, type);
            const std::size_t at_types = add("types", "UInt8", 1, count, types.data(), types.size());
            put("        <DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"", at_types, "\"/>\n");
        }
        put("      </", tag, ">\n");
    }

    std::string finish(const char* type) {
        static const char tail[] = "\n  </AppendedData>\n</VTKFile>\n";
        put("    </Piece>\n  </", type, ">\n  <AppendedData encoding=\"raw\">\n   _");
        xml.reserve(xml.size() + appended.bytes().size() + sizeof tail);
        block_start = xml.size();
        xml += appended.bytes();
        xml += tail;
        return std::move(xml);
    }
};

std::vector<std::int64_t> flat(const std::vector<std::array<std::int64_t, 2>>& lines) {
    std::vector<std::int64_t> ids;
    ids.reserve(2 * lines.size());
    for (const auto& l : lines) ids.insert(ids.end(), l.begin(), l.end());
    return ids;
}

constexpr std::uint8_t vtk_line = 3; // VTK_LINE

// About the arrays' raw bytes, the appended block less its headers (a string counts as its
// object's size), so that the block is allocated once.
std::size_t raw_bytes(const XmlDataset& data) {
    std::size_t bytes = (data.points.size() + 2 * data.vertices.size() + 3 * data.lines.size()) * sizeof(double) + data.lines.size();
    for (const std::vector<XmlArray>* arrays : {&data.point_data, &data.cell_data, &data.field_data})
        for (const XmlArray& a : *arrays) bytes += std::visit([](const auto& v) { return v.size() * sizeof v.front(); }, a.values);
    return bytes;
}

// A grid's file through `w`: its text and arrays, or (refilling) its arrays' values only.
void write_grid(Writer& w, const XmlDataset& data, Compression compression) {
    if (!data.vertices.empty()) throw std::logic_error("unstructured_grid_xml: a grid of this series holds line cells only");
    w.header("UnstructuredGrid", compression, data);
    w.put("    <Piece NumberOfPoints=\"", data.point_count(), "\" NumberOfCells=\"", data.lines.size(), "\">\n");
    w.attribute_data(data.point_data, "PointData", data.active_vectors);
    w.attribute_data(data.cell_data, "CellData", "");
    w.points(data);
    w.cells("Cells", flat(data.lines), 2, true, vtk_line);
}

} // namespace

std::string unstructured_grid_xml(const XmlDataset& data, Compression compression) {
    Writer w(compression, raw_bytes(data));
    write_grid(w, data, compression);
    return w.finish("UnstructuredGrid");
}

const std::string& write_unstructured_grid(const XmlDataset& data, UncompressedGridFile& file) {
    if (!file.bytes.empty() && file.active_vectors == data.active_vectors) {
        Writer refill(file);
        write_grid(refill, data, Compression::none);
        if (refill.refill_fits && refill.refilled == file.slots.size()) return file.bytes;
    }
    Writer w(Compression::none, raw_bytes(data));
    w.record_slots = true;
    write_grid(w, data, Compression::none);
    file.slots = std::move(w.slots);
    file.active_vectors = data.active_vectors;
    file.bytes = w.finish("UnstructuredGrid");
    file.block_start = w.block_start;
    return file.bytes;
}

std::string poly_data_xml(const XmlDataset& data, Compression compression) {
    Writer w(compression, raw_bytes(data));
    w.header("PolyData", compression, data);
    w.put("    <Piece NumberOfPoints=\"", data.point_count(), "\" NumberOfVerts=\"", data.vertices.size(), "\" NumberOfLines=\"",
          data.lines.size(), "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n");
    w.attribute_data(data.point_data, "PointData", data.active_vectors);
    w.attribute_data(data.cell_data, "CellData", ""); // vertices' values first, then the lines'
    w.points(data);
    w.cells("Verts", data.vertices, 1, false, 0);
    w.cells("Lines", flat(data.lines), 2, false, 0);
    w.cells("Strips", {}, 1, false, 0);
    w.cells("Polys", {}, 1, false, 0);
    return w.finish("PolyData");
}

} // namespace plastica
