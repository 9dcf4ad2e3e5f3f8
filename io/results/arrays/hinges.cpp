// Plastic hinges at member ends: each end's utilisation |M|/M_p(N) and state, the softer end's
// EI ratio, and at each node the largest utilisation and worst state of the ends that meet there.
#include "arrays/output_array.hpp"

#include <algorithm>

namespace plastica {

namespace {

using namespace result;

// The file's code of an end's state (the schema's codes, not the engine's enumeration).
HingeCode hinge_code(HingeState state) {
    switch (state) {
    case HingeState::elastic: return HingeCode::elastic;
    case HingeState::yielding: return HingeCode::yielding;
    case HingeState::plastic: return HingeCode::plastic;
    case HingeState::failed: return HingeCode::failed;
    }
    return HingeCode::elastic;
}

void fill_hinges(const StepView& v, XmlDataset& out) {
    if (!v.has(name::hinge_state)) return;
    const std::size_t n = v.model.nodes.size(), ne = v.model.elements.size();
    XmlArray util = real_array(name::plastic_utilisation, n), hinge = integer_array(name::hinge_state, n);
    XmlArray ei = real_array(name::ei_ratio, ne), ui = real_array(name::utilisation_i, ne), uj = real_array(name::utilisation_j, ne);
    XmlArray end_state[2] = {integer_array(name::hinge_state_i, ne), integer_array(name::hinge_state_j, ne)};
    for (std::size_t e = 0; e < ne; ++e) {
        const ElementResult& er = v.result.elements[e];
        if (!er.hinged) {
            real(ei)[e] = 1.0;
            continue;
        }
        real(ei)[e] = std::min(er.hinge[0].ei_ratio, er.hinge[1].ei_ratio);
        real(ui)[e] = er.hinge[0].utilisation;
        real(uj)[e] = er.hinge[1].utilisation;
        const int nodes[2] = {v.model.elements[e].node_i, v.model.elements[e].node_j};
        for (int end = 0; end < 2; ++end) {
            const int state = static_cast<int>(hinge_code(er.hinge[end].state));
            integer(end_state[end])[e] = state;
            real(util)[nodes[end]] = std::max(real(util)[nodes[end]], er.hinge[end].utilisation);
            integer(hinge)[nodes[end]] = std::max(integer(hinge)[nodes[end]], state);
        }
    }
    out.point_data.push_back(std::move(util));
    out.point_data.push_back(std::move(hinge));
    out.cell_data.push_back(std::move(ei));
    out.cell_data.push_back(std::move(ui));
    out.cell_data.push_back(std::move(uj));
    out.cell_data.push_back(std::move(end_state[0]));
    out.cell_data.push_back(std::move(end_state[1]));
}

} // namespace

OutputGroup hinge_arrays() {
    return {{
                {name::plastic_utilisation, Where::point, Type::float64, 1, Quantity::none, When::hinges, "largest |M|/Mp(N) of the ends at the node, each end at its own N: 0 … 1 at capacity"},
                {name::hinge_state, Where::point, Type::int32, 1, Quantity::none, When::hinges, "0 elastic, 1 yielding, 2 fully plastic, 3 failed fibre (worst end)"},
                {name::ei_ratio, Where::cell, Type::float64, 1, Quantity::none, When::hinges, "EI_T/EI of the softer end"},
                {name::utilisation_i, Where::cell, Type::float64, 1, Quantity::none, When::hinges, "|M|/Mp(N) at the first end, at its own N (1 at capacity)"},
                {name::utilisation_j, Where::cell, Type::float64, 1, Quantity::none, When::hinges, "|M|/Mp(N) at the second end, at its own N (1 at capacity)"},
                {name::hinge_state_i, Where::cell, Type::int32, 1, Quantity::none, When::hinges, "state of the first end, codes as hinge_state"},
                {name::hinge_state_j, Where::cell, Type::int32, 1, Quantity::none, When::hinges, "state of the second end"},
            },
            fill_hinges};
}

} // namespace plastica
