#include "section/section_curves.hpp"

#include "section/strain_limit_capacity.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

std::vector<CapacityRow> capacity_table(const FibreSection& section, int points) {
    const double compression = section.axial_capacity_compression(), tension = section.axial_capacity_tension();
    std::vector<CapacityRow> rows;
    rows.reserve(static_cast<std::size_t>(points));
    for (int k = 0; k < points; ++k) {
        const double N = -compression + (compression + tension) * k / (points - 1);
        double yield_upper = section.first_yield_moment(N, 1.0), yield_lower = -section.first_yield_moment(N, -1.0);
        // Where N alone yields a fibre whatever the moment, no elastic range is left.
        if (!(yield_upper > yield_lower)) yield_upper = yield_lower = std::nan("");
        rows.push_back({N, section.moment_bound(N, 1.0), section.moment_bound(N, -1.0), yield_upper, section.hinge_moment_bound(N, 1.0),
                        section.hinge_moment_bound(N, -1.0), yield_lower});
    }
    return rows;
}

double first_yield_curvature(const FibreSection& section) {
    return section.first_yield_moment(0.0) / section.elastic_ei();
}

std::vector<MomentCurvatureCurve> moment_curvature_family(const FibreSection& section, const std::vector<double>& ratios,
                                                          double multiple, int points) {
    const double ny = section.axial_capacity_tension(), kappa_y = first_yield_curvature(section);
    std::vector<MomentCurvatureCurve> curves;
    const std::vector<LimitState> limits = section.has_strain_limits() ? strain_limit_states(section)[0] : std::vector<LimitState>{};
    if (limits.empty()) {
        for (double ratio : ratios)
            curves.push_back({ratio, false, ratio * ny, section.moment_curvature(ratio * ny, multiple * kappa_y, points)});
        return curves;
    }
    for (double ratio : ratios) {
        const double N = -ratio * section.axial_capacity_compression();
        // The limit state at this axial force with the largest curvature: crushing in bending.
        double crushing = 0.0, nearest = HUGE_VAL;
        for (const LimitState& s : limits)
            if (std::abs(s.N - N) < nearest) nearest = std::abs(s.N - N), crushing = std::abs(s.curvature);
        curves.push_back({ratio, true, N, section.moment_curvature(N, 1.5 * crushing, points)});
    }
    return curves;
}

} // namespace plastica
