#include "dynamics/excitation.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

namespace {
constexpr double pi = 3.14159265358979323846;
} // namespace

double series_value(const TimeSeriesSpec& s, double t) {
    switch (s.kind) {
    case TimeSeriesSpec::Kind::harmonic:
        return t < s.start ? 0.0 : s.amplitude * std::sin(2.0 * pi * (t - s.start) / s.period + s.phase);
    case TimeSeriesSpec::Kind::pulse: {
        if (t < s.start || t > s.start + s.width) return 0.0;
        const double x = (t - s.start) / s.width;
        switch (s.shape) {
        case TimeSeriesSpec::Shape::rectangular: return s.amplitude;
        case TimeSeriesSpec::Shape::triangular: return s.amplitude * (1.0 - std::abs(2.0 * x - 1.0));
        case TimeSeriesSpec::Shape::half_sine: return s.amplitude * std::sin(pi * x);
        }
        return 0.0;
    }
    case TimeSeriesSpec::Kind::table: {
        if (s.times.empty() || t > s.times.back()) return 0.0;
        if (t <= s.times.front()) return s.times.front() == 0.0 ? s.values.front() : s.values.front() * t / s.times.front();
        const auto after = std::upper_bound(s.times.begin(), s.times.end(), t);
        const std::size_t k = static_cast<std::size_t>(after - s.times.begin());
        const double w = (t - s.times[k - 1]) / (s.times[k] - s.times[k - 1]);
        return (1.0 - w) * s.values[k - 1] + w * s.values[k];
    }
    }
    return 0.0;
}

double ground_acceleration(const GroundMotionSpec& g, double t) {
    const std::size_t n = g.acceleration.size();
    if (n == 0 || t < 0.0) return 0.0;
    const double position = t / g.time_step;
    const double k = std::floor(position + 1e-9);
    if (k >= static_cast<double>(n - 1)) return k > static_cast<double>(n - 1) ? 0.0 : g.acceleration.back();
    const std::size_t i = static_cast<std::size_t>(k);
    const double w = std::max(0.0, position - k);
    return (1.0 - w) * g.acceleration[i] + w * g.acceleration[i + 1];
}

} // namespace plastica
