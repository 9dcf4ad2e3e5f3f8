#include "curve_error.hpp"

#include "study_error.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace plastica {

double load_at(const Curve& c, double d) {
    for (std::size_t k = 1; k < c.displacement.size(); ++k) {
        const double d0 = c.displacement[k - 1], d1 = c.displacement[k];
        if ((d0 - d) * (d1 - d) <= 0.0 && d0 != d1)
            return c.load[k - 1] + (c.load[k] - c.load[k - 1]) * (d - d0) / (d1 - d0);
    }
    return std::numeric_limits<double>::quiet_NaN();
}

CurveError curve_error(const Curve& curve, const Curve& reference, const std::vector<double>& at, int samples) {
    CurveError e;
    auto range = [](const Curve& c) {
        const auto [lo, hi] = std::minmax_element(c.displacement.begin(), c.displacement.end());
        return std::make_pair(*lo, *hi);
    };
    if (curve.displacement.size() < 2 || reference.displacement.size() < 2) {
        e.max = e.rms = std::numeric_limits<double>::quiet_NaN();
        return e;
    }
    const auto [a0, a1] = range(curve);
    const auto [b0, b1] = range(reference);
    e.from = std::max(a0, b0);
    e.to = std::min(a1, b1);
    double peak = 0.0;
    for (double p : reference.load) peak = std::max(peak, std::abs(p));
    double sum = 0.0;
    int n = 0;
    for (int i = 0; i <= samples; ++i) {
        const double d = e.from + (e.to - e.from) * i / samples;
        const double p = load_at(curve, d), q = load_at(reference, d);
        if (std::isnan(p) || std::isnan(q)) continue;
        const double r = std::abs(p - q) / peak;
        e.max = std::max(e.max, r);
        sum += r * r;
        ++n;
    }
    if (n == 0) e.max = std::numeric_limits<double>::quiet_NaN(); // no displacement in common
    e.rms = n ? std::sqrt(sum / n) : std::numeric_limits<double>::quiet_NaN();
    for (double d : at) {
        const double p = load_at(curve, d), q = load_at(reference, d);
        e.at.push_back(std::abs(p - q) / peak);
    }
    return e;
}

Curve read_curve_csv(const std::string& file) {
    std::ifstream in(file);
    if (!in) throw StudyError(file + ": cannot open the reference curve");
    Curve c;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (line.empty() || line[0] == '#') continue;
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream fields(line);
        double d, p;
        if (!(fields >> d >> p)) {
            if (c.displacement.empty() && number == 1) continue; // the header
            throw StudyError(file + ":" + std::to_string(number) + ": expected two numbers 'displacement,load'");
        }
        c.displacement.push_back(d);
        c.load.push_back(p);
    }
    if (c.displacement.size() < 2) throw StudyError(file + ": a reference curve needs at least two points");
    return c;
}

} // namespace plastica
