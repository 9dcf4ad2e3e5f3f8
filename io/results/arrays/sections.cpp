// Fibre sections along members with distributed plasticity: the yielded share, curvature and
// moment at each integration point, and each member's largest yielded share.
#include "arrays/output_array.hpp"

#include <algorithm>

namespace plastica {

namespace {

using namespace result;

void fill_sections(const StepView& v, XmlDataset& out) {
    if (!v.has(name::yielded_share)) return;
    // One tuple per element, one component per integration point (ξ order); elements without
    // fibre sections along them carry zeros.
    const std::size_t ne = v.model.elements.size();
    const int points = v.model.integration_points();
    XmlArray most = real_array(name::yielded_share, ne), share = real_array(name::section_yielded_share, ne, points),
             curvature = real_array(name::section_curvature, ne, points), moment_at = real_array(name::section_moment, ne, points);
    for (std::size_t e = 0; e < ne; ++e) {
        const std::vector<SectionReport>& sections = v.result.elements[e].sections;
        const int available = std::min(points, static_cast<int>(sections.size()));
        double largest = 0.0;
        for (int k = 0; k < available; ++k) {
            const std::size_t at = e * static_cast<std::size_t>(points) + static_cast<std::size_t>(k);
            real(share)[at] = sections[k].yielded_share;
            real(curvature)[at] = sections[k].curvature;
            real(moment_at)[at] = sections[k].moment;
            largest = std::max(largest, sections[k].yielded_share);
        }
        real(most)[e] = largest;
    }
    out.cell_data.push_back(std::move(most));
    out.cell_data.push_back(std::move(share));
    out.cell_data.push_back(std::move(curvature));
    out.cell_data.push_back(std::move(moment_at));
}

} // namespace

OutputGroup section_arrays() {
    return {{
                {name::yielded_share, Where::cell, Type::float64, 1, Quantity::none, When::distributed, "largest share of a section's area at the yield stress"},
                {name::section_yielded_share, Where::cell, Type::float64, 0, Quantity::none, When::distributed, "yielded share at each integration point, ξ order"},
                {name::section_curvature, Where::cell, Type::float64, 0, Quantity::curvature, When::distributed, "κ = dθ/ds at each integration point"},
                {name::section_moment, Where::cell, Type::float64, 0, Quantity::moment, When::distributed, "bending moment at each integration point"},
            },
            fill_sections};
}

} // namespace plastica
