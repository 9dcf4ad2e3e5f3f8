#include "section_tables.hpp"

namespace plastica {

void write_capacity_csv(std::ostream& out, const std::vector<CapacityRow>& rows) {
    out.precision(12);
    out << "axial_force,moment_positive,moment_negative,first_yield_moment,hinge_moment_positive,hinge_moment_negative,"
           "first_yield_moment_negative\n";
    for (const CapacityRow& r : rows)
        out << r.axial_force << ',' << r.moment_positive << ',' << r.moment_negative << ',' << r.first_yield_moment << ','
            << r.hinge_moment_positive << ',' << r.hinge_moment_negative << ',' << r.first_yield_moment_negative << '\n';
}

void write_moment_curvature_csv(std::ostream& out, const std::vector<MomentCurvatureCurve>& curves) {
    out.precision(12);
    out << "axial_ratio,axial_force,curvature,moment\n";
    for (const MomentCurvatureCurve& c : curves)
        for (const MomentCurvaturePoint& p : c.points)
            out << c.axial_ratio << ',' << c.axial_force << ',' << p.curvature << ',' << p.moment << '\n';
}

} // namespace plastica
