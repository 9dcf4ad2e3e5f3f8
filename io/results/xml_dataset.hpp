// What one VTK XML file of a result series holds, in plain containers: points, line and vertex
// cells, and named arrays of point, cell and field data. The series writer fills it and
// vtk_xml_format.hpp serialises it, so writing results needs no VTK library at run time.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace plastica {

struct XmlArray {
    std::string name;
    int components = 1;
    std::variant<std::vector<double>, std::vector<std::int32_t>, std::vector<std::string>> values;

    std::size_t tuples() const;
};

// The values of an array known to be real, or integer.
inline std::vector<double>& real(XmlArray& a) { return std::get<std::vector<double>>(a.values); }
inline std::vector<std::int32_t>& integer(XmlArray& a) { return std::get<std::vector<std::int32_t>>(a.values); }

// A real array of `tuples` × `components` zeros.
XmlArray real_array(std::string name, std::size_t tuples, int components = 1);
// An integer array of `tuples` zeros.
XmlArray integer_array(std::string name, std::size_t tuples);
// A one-value field array.
XmlArray field_value(std::string name, double value);
XmlArray field_text(std::string name, std::string value);

struct XmlDataset {
    std::vector<double> points;                      // x, y, z of each point
    std::vector<std::int64_t> vertices;              // one point each (poly data only)
    std::vector<std::array<std::int64_t, 2>> lines;  // two points each
    std::vector<XmlArray> point_data, cell_data, field_data;
    std::string active_vectors;                      // a point array's name, or empty

    std::size_t point_count() const { return points.size() / 3; }
};

} // namespace plastica
