// The size of the next increment: landing on a stage's target, halving after a failure,
// taking a step again smaller when it carried a hinge section too far into its yielding range,
// adapting toward the desired iteration count, and recovering after cuts when increments are
// fixed. It keeps only the counts these rules need; path_following.cpp asks it and does the rest.
#pragma once

#include "model/model.hpp"
#include "solver/newton_solver.hpp"

#include <cmath>

namespace plastica {

class StepController {
public:
    // How far into its yielding range (in |M|/M_p) one adaptive increment may carry a hinge section.
    static constexpr double max_yield_advance = 0.05;

    // The increment to try: h, shortened to `remaining` where it would pass the target.
    static double landing(double h, double remaining) { return std::abs(h) > std::abs(remaining) ? remaining : h; }

    // The increment that failed is halved: the next one to try.
    double after_failure(double tried);
    // Whether a converged step that carried a section `advance` into its yielding range is
    // taken again smaller, and if so the increment to take it with (else 0). Not where the last
    // smaller step carried it as far (a jump of the section's state, as a member reaching its
    // squash load, which no increment makes smaller), nor where its half is below `smallest`.
    double refined(double tried, double advance, double smallest);
    // After a converged step tried with `tried` of the increment h: the next increment.
    double after_success(const AnalysisSpec& a, double h, double tried, const NewtonResult& outcome, double advance);

private:
    int steps_since_cut_ = 0;      // converged steps at the increment a cut left (fixed increments)
    double refined_advance_ = 0.0; // yield advance of this step's last attempt taken again smaller
};

} // namespace plastica
