#include "vtu_reader.hpp"

#include <lz4.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>

namespace plastica {

namespace {

// What the XML holds before the appended block: the tags, and the block's start.
struct Tag {
    std::string element;
    std::string text; // the attributes
};

std::string unescaped(const std::string& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] != '&') {
            out += s[i];
            continue;
        }
        static const std::pair<const char*, char> entities[] = {{"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
        bool known = false;
        for (const auto& [entity, c] : entities)
            if (s.compare(i, std::strlen(entity), entity) == 0) {
                out += c;
                i += std::strlen(entity) - 1;
                known = true;
                break;
            }
        if (!known) out += '&';
    }
    return out;
}

std::optional<std::string> attribute(const Tag& tag, const std::string& key) {
    const std::string pattern = " " + key + "=\"";
    const std::size_t at = tag.text.find(pattern);
    if (at == std::string::npos) return std::nullopt;
    const std::size_t start = at + pattern.size(), end = tag.text.find('"', start);
    if (end == std::string::npos) return std::nullopt;
    return unescaped(tag.text.substr(start, end - start));
}

class Reader {
public:
    Reader(const std::string& text, const std::string& name) : text_(text), name_(name) {
        const std::size_t appended = text.find("<AppendedData encoding=\"raw\">");
        if (appended == std::string::npos) fail("no appended data");
        const std::size_t underscore = text.find('_', appended);
        if (underscore == std::string::npos) fail("no appended data");
        block_ = underscore + 1;
        header_ = text.substr(0, appended);
        const std::size_t file = header_.find("<VTKFile");
        if (file == std::string::npos || header_.find("type=\"UnstructuredGrid\"") == std::string::npos) fail("not an UnstructuredGrid VTK file");
        if (header_.find("header_type=\"UInt64\"") == std::string::npos || header_.find("byte_order=\"LittleEndian\"") == std::string::npos)
            fail("not written with UInt64 headers, little endian");
        const std::size_t file_end = header_.find('>', file);
        const std::string file_tag = header_.substr(file, file_end - file);
        if (file_tag.find("vtkLZ4DataCompressor") != std::string::npos) compression_ = 1;
        else if (file_tag.find("vtkZLibDataCompressor") != std::string::npos) compression_ = 2;
        else if (file_tag.find("compressor=") != std::string::npos) fail("an unknown compressor");
    }

    XmlDataset read() {
        XmlDataset data;
        std::string section;
        Tag piece;
        for (std::size_t at = header_.find('<'); at != std::string::npos; at = header_.find('<', at + 1)) {
            const std::size_t end = header_.find('>', at);
            if (end == std::string::npos) fail("a tag is not closed");
            const std::string inside = header_.substr(at + 1, end - at - 1);
            const std::size_t space = inside.find(' ');
            const Tag tag{inside.substr(0, space), space == std::string::npos ? "" : inside.substr(space)};
            if (tag.element == "FieldData" || tag.element == "PointData" || tag.element == "CellData" || tag.element == "Points" ||
                tag.element == "Cells") {
                section = tag.element;
                if (section == "PointData") data.active_vectors = attribute(tag, "Vectors").value_or("");
            } else if (tag.element == "DataArray" || tag.element == "Array") {
                array(tag, section, data);
            } else if (tag.element == "Piece") {
                piece = tag;
            }
        }
        // VTK's reader allocates what the piece claims before it reads a value (1e12 points:
        // std::bad_alloc): the claim must be what the arrays hold.
        for (const auto& [key, held] : {std::pair<const char*, std::size_t>{"NumberOfPoints", data.point_count()},
                                        std::pair<const char*, std::size_t>{"NumberOfCells", data.lines.size()}}) {
            const std::string claimed = attribute(piece, key).value_or("");
            if (claimed != std::to_string(held)) fail(std::string("the piece's ") + key + " is '" + claimed + "', its arrays hold " + std::to_string(held));
        }
        if (data.points.empty() && !data.lines.empty()) fail("cells without points");
        for (const auto& line : data.lines)
            for (std::int64_t p : line)
                if (p < 0 || static_cast<std::size_t>(p) >= data.point_count()) fail("a cell names a point the file does not hold");
        return data;
    }

private:
    [[noreturn]] void fail(const std::string& why) const { throw VtuReadError(name_ + ": " + why); }

    std::uint64_t word(std::size_t at) const {
        if (at > text_.size() || text_.size() - at < sizeof(std::uint64_t)) fail("an array runs past the end of the file");
        std::uint64_t v;
        std::memcpy(&v, text_.data() + at, sizeof v);
        return v;
    }

    // The bytes of the array at `offset` in the appended block.
    std::string bytes_at(std::size_t offset) const {
        const std::size_t at = block_ + offset;
        if (offset > text_.size() || at > text_.size()) fail("an array's offset lies past the end of the file");
        if (compression_ == 0) {
            const std::uint64_t size = word(at);
            if (size > text_.size() - at - sizeof size) fail("an array runs past the end of the file");
            return text_.substr(at + sizeof size, size);
        }
        const std::uint64_t blocks = word(at), block_size = word(at + 8), last = word(at + 16);
        if (blocks > text_.size() / 8 || block_size == 0 || block_size > (1u << 30) || last > block_size) fail("a compressed array's table is not valid");
        std::size_t packed_at = at + 24 + blocks * 8;
        std::string out;
        for (std::uint64_t b = 0; b < blocks; ++b) {
            const std::uint64_t packed = word(at + 24 + b * 8);
            const std::uint64_t size = (b + 1 == blocks && last > 0) ? last : block_size;
            if (packed_at > text_.size() || packed > text_.size() - packed_at) fail("a compressed block runs past the end of the file");
            if (out.size() + size > text_.size() * 300 + (1u << 20)) fail("an array inflates beyond reason");
            const std::size_t start = out.size();
            out.resize(start + size);
            if (compression_ == 1) {
                const int got = LZ4_decompress_safe(text_.data() + packed_at, &out[start], static_cast<int>(packed), static_cast<int>(size));
                if (got < 0 || static_cast<std::uint64_t>(got) != size) fail("an LZ4 block does not decompress");
            } else {
                uLongf got = static_cast<uLongf>(size);
                if (uncompress(reinterpret_cast<Bytef*>(&out[start]), &got, reinterpret_cast<const Bytef*>(text_.data() + packed_at),
                               static_cast<uLong>(packed)) != Z_OK || got != size)
                    fail("a zlib block does not decompress");
            }
            packed_at += packed;
        }
        return out;
    }

    template <class T>
    std::vector<T> values(const std::string& bytes, const std::string& array_name) const {
        if (bytes.size() % sizeof(T) != 0) fail("array '" + array_name + "' holds a partial value");
        std::vector<T> v(bytes.size() / sizeof(T));
        if (!v.empty()) std::memcpy(v.data(), bytes.data(), bytes.size());
        return v;
    }

    void array(const Tag& tag, const std::string& section, XmlDataset& data) const {
        const std::string type = attribute(tag, "type").value_or(""), array_name = attribute(tag, "Name").value_or("");
        if (attribute(tag, "format").value_or("") != "appended") fail("array '" + array_name + "' is not appended data");
        const std::string offset_text = attribute(tag, "offset").value_or("");
        std::size_t offset = 0;
        try {
            offset = std::stoull(offset_text);
        } catch (const std::exception&) {
            fail("array '" + array_name + "' has no offset");
        }
        int components = 1;
        if (const auto c = attribute(tag, "NumberOfComponents")) {
            components = std::atoi(c->c_str());
            if (components < 1 || components > 64) fail("array '" + array_name + "' has " + *c + " components");
        }
        const std::string bytes = bytes_at(offset);
        if (section == "Points") {
            if (type != "Float64") fail("points are not Float64");
            data.points = values<double>(bytes, array_name);
            if (data.points.size() % 3 != 0) fail("points are not triples");
            return;
        }
        if (section == "Cells") {
            if (array_name != "connectivity") return; // offsets and types follow from lines of two points
            if (type != "Int64") fail("connectivity is not Int64");
            const std::vector<std::int64_t> ids = values<std::int64_t>(bytes, array_name);
            if (ids.size() % 2 != 0) fail("a cell is not a line of two points");
            for (std::size_t k = 0; k + 1 < ids.size(); k += 2) data.lines.push_back({ids[k], ids[k + 1]});
            return;
        }
        XmlArray a;
        a.name = array_name;
        a.components = components;
        if (type == "Float64") a.values = values<double>(bytes, array_name);
        else if (type == "Int32") a.values = values<std::int32_t>(bytes, array_name);
        else if (type == "String") {
            std::vector<std::string> strings;
            std::size_t start = 0;
            for (std::size_t k = 0; k < bytes.size(); ++k)
                if (bytes[k] == '\0') {
                    strings.push_back(bytes.substr(start, k - start));
                    start = k + 1;
                }
            if (start != bytes.size()) fail("string array '" + array_name + "' is not terminated");
            a.values = std::move(strings);
        } else {
            fail("array '" + array_name + "' has type '" + type + "'");
        }
        if (a.tuples() * static_cast<std::size_t>(components) != std::visit([](const auto& v) { return v.size(); }, a.values) &&
            !std::holds_alternative<std::vector<std::string>>(a.values))
            fail("array '" + array_name + "' does not hold whole tuples");
        std::vector<XmlArray>& list = section == "FieldData" ? data.field_data : section == "PointData" ? data.point_data : data.cell_data;
        if (section != "FieldData" && section != "PointData" && section != "CellData") fail("array '" + array_name + "' outside a data section");
        list.push_back(std::move(a));
    }

    const std::string& text_;
    std::string name_;
    std::string header_;
    std::size_t block_ = 0;
    int compression_ = 0; // 0 none, 1 LZ4, 2 zlib
};

} // namespace

XmlDataset parse_unstructured_grid(const std::string& text, const std::string& name) { return Reader(text, name).read(); }

} // namespace plastica
