#include "raw_vtu_format.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace plastica {

namespace {

// The appended block: each array is a UInt64 byte count followed by its bytes; the XML refers
// to it by its offset in the block.
class Appended {
public:
    std::size_t add(const void* data, std::size_t bytes) {
        const std::size_t offset = block_.size();
        const std::uint64_t count = bytes;
        block_.append(reinterpret_cast<const char*>(&count), sizeof count);
        block_.append(static_cast<const char*>(data), bytes);
        return offset;
    }
    const std::string& bytes() const { return block_; }

private:
    std::string block_;
};

// XML attribute text: names come from the result schema and scene names, but say it safely.
std::string escaped(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

void data_array(std::string& xml, Appended& appended, vtkAbstractArray* array, const char* indent, bool tuples_attribute) {
    const std::string name = escaped(array->GetName() ? array->GetName() : "");
    const vtkIdType values = array->GetNumberOfTuples() * array->GetNumberOfComponents();
    std::string type;
    std::size_t offset = 0;
    if (auto* d = vtkDoubleArray::SafeDownCast(array)) {
        type = "Float64";
        offset = appended.add(d->GetPointer(0), static_cast<std::size_t>(values) * sizeof(double));
    } else if (auto* i = vtkIntArray::SafeDownCast(array)) {
        type = "Int32";
        offset = appended.add(i->GetPointer(0), static_cast<std::size_t>(values) * sizeof(int));
    } else if (auto* s = vtkStringArray::SafeDownCast(array)) {
        // Strings: each value's characters and a terminating NUL, in one block.
        std::string text;
        for (vtkIdType k = 0; k < s->GetNumberOfValues(); ++k) text += s->GetValue(k) + std::string(1, '\0');
        offset = appended.add(text.data(), text.size());
        xml += std::string(indent) + "<Array type=\"String\" Name=\"" + name + "\" NumberOfTuples=\"" +
               std::to_string(s->GetNumberOfTuples()) + "\" format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
        return;
    } else {
        throw std::logic_error(std::string("raw_vtu: array '") + name + "' has a type the writer does not know");
    }
    xml += std::string(indent) + "<DataArray type=\"" + type + "\" Name=\"" + name + "\"";
    if (array->GetNumberOfComponents() != 1) xml += " NumberOfComponents=\"" + std::to_string(array->GetNumberOfComponents()) + "\"";
    if (tuples_attribute) xml += " NumberOfTuples=\"" + std::to_string(array->GetNumberOfTuples()) + "\"";
    xml += " format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
}

void attribute_data(std::string& xml, Appended& appended, vtkFieldData* data, const char* tag, const std::string& vectors) {
    xml += std::string("      <") + tag;
    if (!vectors.empty()) xml += " Vectors=\"" + escaped(vectors) + "\"";
    xml += ">\n";
    for (int k = 0; k < data->GetNumberOfArrays(); ++k)
        data_array(xml, appended, data->GetAbstractArray(k), "        ", false);
    xml += std::string("      </") + tag + ">\n";
}

} // namespace

std::string raw_vtu(vtkUnstructuredGrid* grid) {
    Appended appended;
    std::string xml;
    xml.reserve(8192);
    xml += "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
           "  <UnstructuredGrid>\n";
    vtkFieldData* fd = grid->GetFieldData();
    if (fd->GetNumberOfArrays() > 0) {
        xml += "    <FieldData>\n";
        for (int k = 0; k < fd->GetNumberOfArrays(); ++k) data_array(xml, appended, fd->GetAbstractArray(k), "      ", true);
        xml += "    </FieldData>\n";
    }
    const vtkIdType points = grid->GetNumberOfPoints(), cells = grid->GetNumberOfCells();
    xml += "    <Piece NumberOfPoints=\"" + std::to_string(points) + "\" NumberOfCells=\"" + std::to_string(cells) + "\">\n";
    vtkDataArray* vectors = grid->GetPointData()->GetVectors();
    attribute_data(xml, appended, grid->GetPointData(), "PointData", vectors && vectors->GetName() ? vectors->GetName() : "");
    attribute_data(xml, appended, grid->GetCellData(), "CellData", "");
    xml += "      <Points>\n";
    data_array(xml, appended, grid->GetPoints()->GetData(), "        ", false);
    xml += "      </Points>\n";
    // Cells: connectivity and offsets as Int64, types as UInt8.
    std::vector<std::int64_t> connectivity, offsets;
    std::vector<std::uint8_t> types;
    connectivity.reserve(static_cast<std::size_t>(2 * cells));
    for (vtkIdType c = 0; c < cells; ++c) {
        vtkIdType count = 0;
        const vtkIdType* ids = nullptr;
        grid->GetCellPoints(c, count, ids);
        for (vtkIdType k = 0; k < count; ++k) connectivity.push_back(ids[k]);
        offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
        types.push_back(static_cast<std::uint8_t>(grid->GetCellType(c)));
    }
    const std::size_t at_connectivity = appended.add(connectivity.data(), connectivity.size() * sizeof(std::int64_t));
    const std::size_t at_offsets = appended.add(offsets.data(), offsets.size() * sizeof(std::int64_t));
    const std::size_t at_types = appended.add(types.data(), types.size());
    xml += "      <Cells>\n"
           "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" offset=\"" + std::to_string(at_connectivity) + "\"/>\n"
           "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"" + std::to_string(at_offsets) + "\"/>\n"
           "        <DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"" + std::to_string(at_types) + "\"/>\n"
           "      </Cells>\n"
           "    </Piece>\n"
           "  </UnstructuredGrid>\n"
           "  <AppendedData encoding=\"raw\">\n   _";
    xml += appended.bytes();
    xml += "\n  </AppendedData>\n</VTKFile>\n";
    return xml;
}

} // namespace plastica
