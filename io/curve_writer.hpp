// Observer that appends one row per converged step to curve.csv:
// step, load_factor, load, control_displacement, iterations, contact_count, hinge_count.
// The file is flushed after every row so a run stopped half-way leaves a complete prefix.
#pragma once

#include "analysis/step_result.hpp"

#include <fstream>
#include <string>

namespace plastica {

class CurveWriter {
public:
    explicit CurveWriter(const std::string& path);
    void operator()(const StepResult& r);

private:
    std::ofstream out_;
};

} // namespace plastica
