// Error against run time: a scene run over a ladder of one discretisation parameter
// at a time; for each level the analysis wall time (median of repeats when a run is short),
// steps, Newton iterations, and the error of its load–displacement curve against a reference —
// the scene's closed form, a user's CSV curve, the limit extrapolated from the ladder's three
// finest levels, or its finest level. The observed order of convergence is the slope of
// log(max error) against log(h), h = 1/level for elements and fibres, h = increment.
// Methods compared (hinges, distributed) are each measured against their own reference, never
// one against the other's run; the distance between their limits is reported beside.
#pragma once

#include "curve_error.hpp"
#include "curve_extrapolation.hpp"

#include <string>
#include <vector>

namespace plastica {

struct Ladder {
    std::string parameter;      // elements, fibres, integration_points or increment
    std::vector<double> levels; // in the order given
};

struct StudyOptions {
    std::string scene;
    std::vector<Ladder> ladders;
    std::string reference = "finest"; // exact, extrapolated, finest, or a CSV file
    std::vector<double> at;           // displacements where the error is reported (default: quarters)
    double min_seconds = 0.3;         // repeat a level until this much time has passed (at most 7 runs)
    // A method comparison: every ladder once per way of modelling plasticity ("hinges",
    // "distributed"), each method against its own reference.
    std::vector<std::string> methods;
};

struct StudyLevel {
    std::string method; // empty unless methods are compared
    std::string parameter;
    double level = 0.0;
    double seconds = 0.0; // median wall time of the analysis
    int repeats = 0, steps = 0, iterations = 0;
    std::string status;
    bool is_reference = false;
    CurveError error;
};

struct StudyReport {
    std::string reference; // what the errors are measured against
    std::vector<double> at;
    std::vector<StudyLevel> levels;
    struct Order {
        std::string method, parameter;
        double order = 0.0;
    };
    std::vector<Order> observed_order; // per method and parameter
    // Each method's limit per ladder (extrapolated or finest), when three levels or more were run.
    struct Limit {
        std::string method, parameter;
        CurveLimit limit;
        std::vector<double> levels; // the ladder's levels the limit was made from (coarse, middle, fine)
    };
    std::vector<Limit> limits;
    // How far each method's limit lies from the last method's, per ladder (methods compared only).
    struct LimitGap {
        std::string parameter, method, against;
        CurveError gap; // relative to the peak of `against`'s limit
    };
    std::vector<LimitGap> limit_gaps;
};

// Throws SceneError for a bad scene, StudyError for a bad parameter or reference.
StudyReport run_study(const StudyOptions& options);

} // namespace plastica
