#include "section/section_curves.hpp"

#include <algorithm>

namespace plastica {

std::vector<CapacityRow> capacity_table(const FibreSection& section, int points) {
    const double compression = section.axial_capacity_compression(), tension = section.axial_capacity_tension();
    std::vector<CapacityRow> rows;
    rows.reserve(static_cast<std::size_t>(points));
    for (int k = 0; k < points; ++k) {
        const double N = -compression + (compression + tension) * k / (points - 1);
        rows.push_back({N, section.moment_capacity(N, 1.0), -section.moment_capacity(N, -1.0),
                        std::max(0.0, section.first_yield_moment(N)), section.hinge_moment_capacity(N, 1.0),
                        -section.hinge_moment_capacity(N, -1.0)});
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
    for (double ratio : ratios)
        curves.push_back({ratio, ratio * ny, section.moment_curvature(ratio * ny, multiple * kappa_y, points)});
    return curves;
}

} // namespace plastica
