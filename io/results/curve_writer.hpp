// Observer that appends one row per converged step to curve.csv: step, load_factor, load,
// control_displacement, iterations, contact_count, hinge_count, plastic_hinge_count,
// base_reaction, contact_length, negative_pivots, accepted_by, residual, then one column per
// DOF a [[support]] fixes (support1_fx, support1_fy, support2_mz, …: the force the support
// exerts on the structure), and for an elastic path critical_point (bifurcation, limit_point or
// empty) and critical_load_factor (where it lies; empty elsewhere). Each row goes out in one write, so a run stopped half-way leaves a
// complete prefix; a row that cannot be written whole (a full disk) is taken back.
#pragma once

#include "analysis/step_result.hpp"
#include "model/model.hpp"

#include <string>

namespace plastica {

// The header line and a step's row, as the writer writes them (the Python module's curve).
std::string curve_header(const Model& model);
std::string curve_row(const Model& model, const StepResult& r);

class CurveWriter {
public:
    CurveWriter(const std::string& path, const Model& model);
    ~CurveWriter();
    CurveWriter(const CurveWriter&) = delete;
    CurveWriter& operator=(const CurveWriter&) = delete;

    void operator()(const StepResult& r);
    // Removes the last row (its step could not be written elsewhere), so every output of a
    // run ends at the same step.
    void take_back_last_row();

private:
    void truncate_to(long long size);

    std::string path_;
    const Model* model_;
    int fd_ = -1;
    long long size_ = 0, before_last_row_ = 0;
};

} // namespace plastica
