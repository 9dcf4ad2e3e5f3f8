// An output array is declared where it is filled: each file of io/results/arrays/ holds a group of the
// result schema's rows (result_schema.hpp) and the function that fills them from one step, and
// io/results/arrays/output_arrays.cpp lists the groups in the order a VTU lays them out. A new array is
// a row and its lines of code in a group; a new group one file and one line in that list.
#pragma once

#include "analysis/step_result.hpp"
#include "model/model.hpp"
#include "result_schema.hpp"
#include "xml_dataset.hpp"

#include <set>
#include <string>
#include <vector>

namespace plastica {

// One step as an array group sees it: the model, the step's results, its time in the series,
// the units of the reported load and displacement, and which of the schema's arrays the scene
// writes (decided once per series).
struct StepView {
    const Model& model;
    const StepResult& result;
    double time;
    const std::string& load_unit;
    const std::string& displacement_unit;
    const std::set<std::string>& present;

    bool has(const char* array) const { return present.count(array) > 0; }
};

struct OutputGroup {
    std::vector<result::Array> arrays;
    // Appends the group's arrays that the scene writes to the dataset's point, cell and field
    // data, each list in the order of `arrays`. Null for base.vtp's group (base_lines.hpp).
    void (*fill)(const StepView& step, XmlDataset& out) = nullptr;
};

// Every group, in the order their arrays are laid out.
const std::vector<OutputGroup>& output_groups();

// Helpers of the groups: a real array's tuple of three.
inline void set3(XmlArray& a, std::size_t tuple, double x, double y, double z) {
    double* v = &real(a)[3 * tuple];
    v[0] = x;
    v[1] = y;
    v[2] = z;
}

// Appends a force vector and a moment per node from a nodal vector of three DOFs per node.
void push_force_and_moment(XmlDataset& out, const char* force_name, const char* moment_name, const std::vector<double>& nodal);

} // namespace plastica
