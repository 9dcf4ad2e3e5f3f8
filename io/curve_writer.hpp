// Observer that appends one row per converged step to curve.csv: step, load_factor, load,
// control_displacement, iterations, contact_count, hinge_count, plastic_hinge_count,
// base_reaction, contact_length, negative_pivots, accepted_by, residual, then one column per
// DOF a [[support]] fixes (support1_fx, support1_fy, support2_mz, …: the force the support
// exerts on the structure). The file is flushed after every row so a run stopped half-way
// leaves a complete prefix.
#pragma once

#include "analysis/step_result.hpp"
#include "model/model.hpp"

#include <fstream>
#include <string>

namespace plastica {

class CurveWriter {
public:
    CurveWriter(const std::string& path, const Model& model);
    void operator()(const StepResult& r);

private:
    std::ofstream out_;
    const Model* model_;
};

} // namespace plastica
