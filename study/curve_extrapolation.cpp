#include "curve_extrapolation.hpp"

#include "study_error.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace plastica {

namespace {

// The order p that explains the ratio of successive differences, e21/e32 = (h1^p − h2^p)/(h2^p − h3^p),
// for h1 > h2 > h3 (the ratio grows with p); bisection on [0.01, 8].
double observed_order(double ratio, double h1, double h2, double h3) {
    auto explained = [&](double p) {
        return (std::pow(h1, p) - std::pow(h2, p)) / (std::pow(h2, p) - std::pow(h3, p));
    };
    double lo = 0.01, hi = 8.0;
    if (ratio <= explained(lo)) return lo;
    if (ratio >= explained(hi)) return hi;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (explained(mid) < ratio ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

} // namespace

CurveLimit extrapolated_limit(const std::vector<Curve>& curves, const std::vector<double>& h, int samples) {
    if (curves.size() < 3 || curves.size() != h.size())
        throw StudyError("an extrapolated limit needs at least three levels of the ladder");
    std::vector<std::size_t> order(h.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return h[a] > h[b]; });
    const std::size_t c = order[order.size() - 3], m = order[order.size() - 2], f = order.back();
    const Curve* three[] = {&curves[c], &curves[m], &curves[f]};

    double from = -1e300, to = 1e300;
    for (const Curve* k : three) {
        if (k->displacement.size() < 2) throw StudyError("an extrapolated limit needs curves of at least two points");
        const auto [lo, hi] = std::minmax_element(k->displacement.begin(), k->displacement.end());
        from = std::max(from, *lo), to = std::min(to, *hi);
    }
    if (!(to > from)) throw StudyError("the three finest levels share no displacement: no limit to extrapolate");

    CurveLimit limit;
    std::vector<double> d, coarse, middle, fine;
    for (int i = 0; i <= samples; ++i) {
        const double x = from + (to - from) * i / samples;
        const double a = load_at(curves[c], x), b = load_at(curves[m], x), e = load_at(curves[f], x);
        if (std::isnan(a) || std::isnan(b) || std::isnan(e)) continue;
        d.push_back(x), coarse.push_back(a), middle.push_back(b), fine.push_back(e);
    }
    // Root-mean-square changes: a kink the levels sample at different steps moves the largest
    // change more than the discretisation does.
    double e21 = 0, e32 = 0;
    for (std::size_t i = 0; i < d.size(); ++i)
        e21 += (middle[i] - coarse[i]) * (middle[i] - coarse[i]), e32 += (fine[i] - middle[i]) * (fine[i] - middle[i]);
    e21 = std::sqrt(e21 / d.size()), e32 = std::sqrt(e32 / d.size());

    limit.curve.displacement = d;
    limit.used[0] = c, limit.used[1] = m, limit.used[2] = f;
    double peak = 0.0;
    for (double p : fine) peak = std::max(peak, std::abs(p));
    limit.change[0] = peak > 0 ? e21 / peak : e21, limit.change[1] = peak > 0 ? e32 / peak : e32;
    limit.order = e21 > e32 && e32 > 0.0 ? observed_order(e21 / e32, h[c], h[m], h[f]) : std::nan("");
    // Below order ½ the changes barely shrink: the ladder is not yet in its asymptotic range, and
    // extrapolating would multiply the last change by 2.4 or more (for halved steps).
    limit.extrapolated = limit.order >= minimum_order;
    if (!limit.extrapolated) {
        limit.curve.load = fine;
        return limit;
    }
    const double hp_m = std::pow(h[m], limit.order), hp_f = std::pow(h[f], limit.order);
    limit.curve.load.resize(d.size());
    for (std::size_t i = 0; i < d.size(); ++i) limit.curve.load[i] = fine[i] + (fine[i] - middle[i]) * hp_f / (hp_m - hp_f);
    return limit;
}

} // namespace plastica
