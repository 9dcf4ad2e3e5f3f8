// The error of a load–displacement curve against a reference curve, over the displacement range
// both cover: P interpolated at the same displacements, relative to the reference's largest |P|
// (a relative error at each point would blow up near the origin).
#pragma once

#include <string>
#include <vector>

namespace plastica {

struct Curve {
    std::vector<double> displacement, load; // in the order of the path
};

struct CurveError {
    double max = 0.0, rms = 0.0;     // relative to the reference's peak |P|
    std::vector<double> at;          // relative error at each requested displacement (NaN outside)
    double from = 0.0, to = 0.0;     // the common range compared
};

CurveError curve_error(const Curve& curve, const Curve& reference, const std::vector<double>& at, int samples = 400);

// Linear interpolation of the load at a displacement (the first crossing); NaN outside.
double load_at(const Curve& curve, double displacement);

// A `displacement,load` CSV (a header line is skipped); throws StudyError naming file and line.
Curve read_curve_csv(const std::string& file);

} // namespace plastica
