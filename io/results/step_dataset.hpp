// What one step of a result series holds, as named arrays (xml_dataset.hpp): the deformed
// points, the elements as lines, and the result schema's point, cell and field arrays that the
// scene has (result_schema.hpp), each group filled by its file in io/results/arrays/. The series writer serialises it to a VTU file; the Python
// module hands its arrays to numpy.
#pragma once

#include "analysis/step_result.hpp"
#include "model/model.hpp"
#include "xml_dataset.hpp"

#include <set>
#include <string>
#include <utility>

namespace plastica {

// The units of the reported load (a force, a moment, a pressure, or none for the load factor)
// and of the control displacement (a length, or radians for a rotation), from the scene's
// [units] or [report]; empty where it names none.
std::pair<std::string, std::string> reported_units(const Model& m);

class StepDataset {
public:
    explicit StepDataset(const Model& model);
    // The step's dataset; time is its TimeValue (the series' time of the step).
    XmlDataset operator()(const StepResult& r, double time) const;
    // The schema's arrays this scene writes.
    const std::set<std::string>& arrays() const { return arrays_; }

private:
    const Model* model_;
    struct Units {
        std::string load, displacement; // of the reported load and control displacement
    } units_;
    std::set<std::string> arrays_; // the schema's arrays this scene writes, decided once
};

} // namespace plastica
