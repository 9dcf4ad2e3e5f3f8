#include "section/section_capacity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <mutex>
#include <numeric>

namespace plastica {

namespace {

struct Point2 {
    double n, m;
};

// Counter-clockwise convex hull (monotone chain), collinear points dropped.
std::vector<Point2> convex_hull(std::vector<Point2> points) {
    std::sort(points.begin(), points.end(),
              [](const Point2& a, const Point2& b) { return a.n < b.n || (a.n == b.n && a.m < b.m); });
    auto cross = [](const Point2& o, const Point2& a, const Point2& b) {
        return (a.n - o.n) * (b.m - o.m) - (a.m - o.m) * (b.n - o.n);
    };
    if (points.size() < 3) return points;
    std::vector<Point2> hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 1e-13) --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 1e-13) --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    return hull;
}

// Fibres at one height with equal limits act as one: a breakpoint between them is a plastic
// state on a straight side, which the hull would keep or drop by round-off, making the hinge's
// curve of a symmetric section differ between +N and −N (a tube's paired fibres: 0.8 %).
std::vector<CapacityFibre> merged_by_height(std::vector<CapacityFibre> fibres) {
    std::sort(fibres.begin(), fibres.end(), [](const CapacityFibre& a, const CapacityFibre& b) {
        return a.y < b.y || (a.y == b.y && (a.limit_tension < b.limit_tension ||
                                            (a.limit_tension == b.limit_tension && a.limit_compression < b.limit_compression)));
    });
    double span = 0.0;
    for (const CapacityFibre& f : fibres) span = std::max(span, std::abs(f.y));
    std::vector<CapacityFibre> out;
    for (const CapacityFibre& f : fibres) {
        if (!out.empty() && std::abs(out.back().y - f.y) <= 1e-12 * span && out.back().limit_tension == f.limit_tension &&
            out.back().limit_compression == f.limit_compression) {
            out.back().y = (out.back().y * out.back().area + f.y * f.area) / (out.back().area + f.area);
            out.back().area += f.area;
        } else {
            out.push_back(f);
        }
    }
    return out;
}

void build_polylines(const std::vector<CapacityFibre>& fibres, SectionCapacity& capacity) {
    // Fully plastic state: with positive bending the fibres below the neutral axis are in
    // tension (+fy) and those above in compression (−fy); the fibre the axis crosses carries
    // whatever stress balances N. As that fibre's stress runs from −fy to +fy, N and M both
    // change linearly, so M_p(N) is exactly the polyline through the states where the axis
    // lies between two fibres: breakpoint k has the k lowest fibres on the "below" side.
    std::vector<std::size_t> order(fibres.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return fibres[a].y < fibres[b].y; });
    for (int side = 0; side < 2; ++side) {
        const double below_sign = side == 0 ? 1.0 : -1.0;
        std::vector<CapacityPoint>& curve = capacity.polyline[side];
        curve.clear();
        const std::size_t n = order.size();
        const auto contribution = [&](std::size_t m, double sign) {
            const CapacityFibre& f = fibres[order[m]];
            const double s = sign * (sign > 0.0 ? f.limit_tension : f.limit_compression);
            return CapacityPoint{s * f.area, -s * f.area * f.y};
        };
        if (n <= direct_capacity_sum_limit) {
            // Each breakpoint summed over the fibres in order.
            for (std::size_t k = 0; k <= n; ++k) {
                CapacityPoint p;
                for (std::size_t m = 0; m < n; ++m) {
                    const CapacityPoint c = contribution(m, m < k ? below_sign : -below_sign);
                    p.N += c.N;
                    p.M += c.M;
                }
                curve.push_back(p);
            }
        } else {
            // A prefix and a suffix sum: O(n) instead of O(n²), so that a section of 10⁵ fibres
            // is set up in milliseconds, not minutes. The breakpoints agree with the sums above
            // to round-off.
            std::vector<CapacityPoint> below(n + 1), above(n + 1);
            for (std::size_t m = 0; m < n; ++m) {
                const CapacityPoint c = contribution(m, below_sign);
                below[m + 1] = {below[m].N + c.N, below[m].M + c.M};
            }
            for (std::size_t m = n; m-- > 0;) {
                const CapacityPoint c = contribution(m, -below_sign);
                above[m] = {above[m + 1].N + c.N, above[m + 1].M + c.M};
            }
            for (std::size_t k = 0; k <= n; ++k) curve.push_back({below[k].N + above[k].N, below[k].M + above[k].M});
        }
        std::sort(curve.begin(), curve.end(), [](const CapacityPoint& a, const CapacityPoint& b) { return a.N < b.N; });
    }
}

void build_hinge_curves(SectionCapacity& capacity) {
    // The fibres' capacity polygon (convex hull of both curves' breakpoints): its upper chain
    // carries positive bending, its lower chain negative; each becomes a smooth curve.
    std::vector<Point2> points;
    for (const auto& curve : capacity.polyline)
        for (const CapacityPoint& c : curve) points.push_back({c.N, c.M});
    const std::vector<Point2> hull = convex_hull(points);
    if (hull.empty()) return;
    std::size_t lowest = 0, highest = 0;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        if (hull[i].n < hull[lowest].n) lowest = i;
        if (hull[i].n > hull[highest].n) highest = i;
    }
    // Counter-clockwise: from the lowest N to the highest runs the lower chain, back the upper.
    for (int side = 0; side < 2; ++side) {
        std::vector<double> N, M;
        const std::size_t from = side == 0 ? highest : lowest;
        const std::size_t to = side == 0 ? lowest : highest;
        for (std::size_t i = from;; i = (i + 1) % hull.size()) {
            N.push_back(hull[i].n);
            M.push_back(side == 0 ? hull[i].m : -hull[i].m); // s·M: below zero off an eccentric section's side
            if (i == to) break;
        }
        if (side == 0) {
            std::reverse(N.begin(), N.end());
            std::reverse(M.begin(), M.end());
        }
        capacity.hinge[side] = CapacityCurve(std::move(N), std::move(M));
    }
}


// The capacities built so far, by a hash of their fibres; each entry keeps its fibres, so that a
// hit is checked whole, and lives only while a section holds its capacity.
struct CacheEntry {
    std::vector<CapacityFibre> fibres;
    std::weak_ptr<const SectionCapacity> capacity;
};

bool same_fibres(const std::vector<CapacityFibre>& a, const std::vector<CapacityFibre>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(CapacityFibre)) == 0);
}

std::uint64_t fibres_hash(const std::vector<CapacityFibre>& fibres) {
    std::uint64_t h = 1469598103934665603ull; // FNV-1a over the bytes
    const auto* bytes = reinterpret_cast<const unsigned char*>(fibres.data());
    for (std::size_t i = 0; i < fibres.size() * sizeof(CapacityFibre); ++i) h = (h ^ bytes[i]) * 1099511628211ull;
    return h;
}

} // namespace

std::shared_ptr<const SectionCapacity> capacity_through_points(std::array<std::vector<CapacityPoint>, 2> polylines) {
    auto built = std::make_shared<SectionCapacity>();
    for (auto& curve : polylines)
        std::sort(curve.begin(), curve.end(), [](const CapacityPoint& a, const CapacityPoint& b) { return a.N < b.N; });
    built->polyline = std::move(polylines);
    build_hinge_curves(*built);
    return built;
}

std::shared_ptr<const SectionCapacity> section_capacity(const std::vector<CapacityFibre>& fibres) {
    static std::mutex mutex;
    static std::multimap<std::uint64_t, CacheEntry> cache;
    const std::uint64_t key = fibres_hash(fibres);
    {
        const std::lock_guard<std::mutex> lock(mutex);
        for (auto [at, end] = cache.equal_range(key); at != end; ++at)
            if (auto held = at->second.capacity.lock(); held && same_fibres(at->second.fibres, fibres)) return held;
    }
    auto built = std::make_shared<SectionCapacity>();
    build_polylines(merged_by_height(fibres), *built);
    build_hinge_curves(*built);
    const std::lock_guard<std::mutex> lock(mutex);
    for (auto at = cache.begin(); at != cache.end();) at = at->second.capacity.expired() ? cache.erase(at) : std::next(at);
    cache.emplace(key, CacheEntry{fibres, built});
    return built;
}

} // namespace plastica
