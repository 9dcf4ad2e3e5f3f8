// numpy arrays of a result series' step (xml_dataset.hpp): what Result.step(k) returns,
// from a run in memory or a VTU file read back (result_folder.cpp).
#pragma once

#include "xml_dataset.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace plastica {

namespace py = pybind11;

inline py::array to_numpy(const XmlArray& a) {
    const std::size_t tuples = a.tuples();
    std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(tuples)};
    if (a.components > 1) shape.push_back(a.components);
    if (const auto* d = std::get_if<std::vector<double>>(&a.values)) {
        py::array_t<double> out(shape);
        std::copy(d->begin(), d->end(), out.mutable_data());
        return std::move(out);
    }
    if (const auto* i = std::get_if<std::vector<std::int32_t>>(&a.values)) {
        py::array_t<std::int32_t> out(shape);
        std::copy(i->begin(), i->end(), out.mutable_data());
        return std::move(out);
    }
    return py::array(py::cast(std::get<std::vector<std::string>>(a.values)));
}

inline py::dict arrays(const std::vector<XmlArray>& list) {
    py::dict d;
    for (const XmlArray& a : list) d[py::str(a.name)] = to_numpy(a);
    return d;
}

// Points (n × 3, deformed), lines (elements' node pairs), and the point, cell and field arrays
// by the result schema's names.
inline py::dict dataset_arrays(const XmlDataset& grid) {
    py::dict out;
    py::array_t<double> points({static_cast<py::ssize_t>(grid.point_count()), py::ssize_t{3}});
    std::copy(grid.points.begin(), grid.points.end(), points.mutable_data());
    py::array_t<std::int64_t> lines({static_cast<py::ssize_t>(grid.lines.size()), py::ssize_t{2}});
    for (std::size_t e = 0; e < grid.lines.size(); ++e)
        for (int j = 0; j < 2; ++j) lines.mutable_at(e, j) = grid.lines[e][static_cast<std::size_t>(j)];
    out["points"] = points;
    out["lines"] = lines;
    out["point"] = arrays(grid.point_data);
    out["cell"] = arrays(grid.cell_data);
    out["field"] = arrays(grid.field_data);
    return out;
}

// The class ResultFolder of the module (result_folder.cpp).
void bind_result_folder(py::module_& m);

} // namespace plastica
