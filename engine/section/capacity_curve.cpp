#include "section/capacity_curve.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

CapacityCurve::CapacityCurve(std::vector<double> N, std::vector<double> M) {
    // Strictly increasing N (a vertical side of the polygon contributes its outer point).
    for (std::size_t i = 0; i < N.size(); ++i) {
        if (!N_.empty() && N[i] <= N_.back()) {
            M_.back() = std::max(M_.back(), M[i]);
            continue;
        }
        N_.push_back(N[i]);
        M_.push_back(M[i]);
    }
    slope_.assign(N_.size(), 0.0);
    const std::size_t n = N_.size();
    if (n < 2) return;
    std::vector<double> side(n - 1);
    for (std::size_t i = 0; i + 1 < n; ++i) side[i] = (M_[i + 1] - M_[i]) / (N_[i + 1] - N_[i]);
    slope_.front() = side.front();
    slope_.back() = side.back();
    for (std::size_t i = 1; i + 1 < n; ++i) slope_[i] = 0.5 * (side[i - 1] + side[i]);
}

double CapacityCurve::bound(double N) const {
    if (N_.size() < 2 || N < N_.front() || N > N_.back()) return 0.0;
    if (N == N_.front()) return M_.front();
    if (N == N_.back()) return M_.back();
    return hermite(N).moment;
}

CapacityValue CapacityCurve::at(double N) const {
    if (N_.size() < 2 || N <= N_.front() || N >= N_.back()) {
        // Outside the squash range: no moment; the slope continues the end side so that a
        // linearisation there still points back inside.
        CapacityValue v;
        if (N_.size() >= 2) v.slope = N <= N_.front() ? slope_.front() : slope_.back();
        return v;
    }
    CapacityValue v = hermite(N);
    v.moment = std::max(v.moment, 0.0);
    return v;
}

CapacityValue CapacityCurve::hermite(double N) const {
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(N_.begin(), N_.end(), N) - N_.begin()) - 1;
    const double h = N_[k + 1] - N_[k];
    const double t = (N - N_[k]) / h;
    const double m0 = M_[k], m1 = M_[k + 1], d0 = slope_[k] * h, d1 = slope_[k + 1] * h;
    const double t2 = t * t, t3 = t2 * t;
    CapacityValue v;
    v.moment = (2 * t3 - 3 * t2 + 1) * m0 + (t3 - 2 * t2 + t) * d0 + (-2 * t3 + 3 * t2) * m1 + (t3 - t2) * d1;
    v.slope = ((6 * t2 - 6 * t) * m0 + (3 * t2 - 4 * t + 1) * d0 + (-6 * t2 + 6 * t) * m1 + (3 * t2 - 2 * t) * d1) / h;
    v.curvature = ((12 * t - 6) * m0 + (6 * t - 4) * d0 + (-12 * t + 6) * m1 + (6 * t - 2) * d1) / (h * h);
    return v;
}

} // namespace plastica
