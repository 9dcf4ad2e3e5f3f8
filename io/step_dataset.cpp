#include "step_dataset.hpp"

#include "result_schema.hpp"

#include <algorithm>

namespace plastica {

namespace {

// force·length, force/length: the compound units of moments and pressures.
std::string compound(const std::string& a, const char* op, const std::string& b) {
    if (a.empty() || b.empty()) return {};
    return a + op + b;
}

// The units of the reported load (a force, a moment, a pressure, or none for the load factor)
// and of the control displacement (a length, or radians for a rotation).
std::pair<std::string, std::string> reported_units(const Model& m) {
    const std::string& force = m.report.force_unit;
    const std::string& length = m.report.length_unit;
    std::string load = force;
    if (m.report.measure == ReportSpec::Measure::factor) {
        load.clear();
    } else if (m.uniform_pressure_only()) {
        load = compound(force, "/", length);
    } else {
        bool any = false, moments_only = true;
        for (const NodalLoad& l : m.loads)
            if (l.pattern == m.reported_pattern()) any = true, moments_only = moments_only && l.value[0] == 0.0 && l.value[1] == 0.0;
        if (any && moments_only) load = compound(force, "·", length);
    }
    return {load, m.reported_control().dof == 2 ? "rad" : length};
}

} // namespace

StepDataset::StepDataset(const Model& model) : model_(&model) {
    const auto [load_unit, displacement_unit] = reported_units(model);
    units_ = {load_unit, displacement_unit};
    for (const result::Array& a : result::arrays())
        if (result::present(a, model)) arrays_.emplace(a.name);
}

namespace {

// The file's code of an end's state (the schema's codes, not the engine's enumeration).
result::HingeCode hinge_code(HingeState state) {
    switch (state) {
    case HingeState::elastic: return result::HingeCode::elastic;
    case HingeState::yielding: return result::HingeCode::yielding;
    case HingeState::plastic: return result::HingeCode::plastic;
    case HingeState::failed: return result::HingeCode::failed;
    }
    return result::HingeCode::elastic;
}

void set3(XmlArray& a, std::size_t tuple, double x, double y, double z) {
    double* v = &real(a)[3 * tuple];
    v[0] = x;
    v[1] = y;
    v[2] = z;
}

} // namespace

XmlDataset StepDataset::operator()(const StepResult& r, double time) const {
    namespace name = result::name;
    const Model& m = *model_;
    const auto has = [this](const char* array) { return this->has(array); };
    const std::size_t n = m.nodes.size(), ne = m.elements.size();
    XmlDataset grid;
    grid.points.resize(3 * n);
    grid.lines.reserve(ne);
    for (const ElementSpec& e : m.elements) grid.lines.push_back({e.node_i, e.node_j});
    XmlArray displacement = real_array(name::displacement, n, 3), rotation = real_array(name::rotation, n),
             initial = real_array(name::initial_position, n, 3);
    for (std::size_t i = 0; i < n; ++i) {
        const double ux = r.displacement[3 * i], uy = r.displacement[3 * i + 1];
        grid.points[3 * i] = m.nodes[i].x + ux;
        grid.points[3 * i + 1] = m.nodes[i].y + uy;
        set3(displacement, i, ux, uy, 0.0);
        real(rotation)[i] = r.displacement[3 * i + 2];
        set3(initial, i, m.nodes[i].x, m.nodes[i].y, 0.0);
    }
    std::vector<XmlArray>& pd = grid.point_data;
    std::vector<XmlArray>& cd = grid.cell_data;
    pd.reserve(arrays_.size()); // at most every array of the scene in one place: no reallocation
    cd.reserve(arrays_.size());
    pd.push_back(std::move(displacement));
    grid.active_vectors = name::displacement;
    pd.push_back(std::move(rotation));
    pd.push_back(std::move(initial));

    // Nodal bending moment: the mean of the element-end moments meeting at the node.
    XmlArray moment = real_array(name::bending_moment, n);
    std::vector<int> count(n, 0);
    XmlArray axial = real_array(name::axial_force, ne), mi = real_array(name::moment_i, ne), mj = real_array(name::moment_j, ne),
             shear = real_array(name::shear, ne);
    for (std::size_t e = 0; e < ne; ++e) {
        const BeamForces& f = r.elements[e].forces;
        real(axial)[e] = f.axial;
        real(mi)[e] = f.moment_i;
        real(mj)[e] = f.moment_j;
        real(shear)[e] = f.shear;
        // A released end carries no moment: the node's moment is its other members'.
        const ElementSpec& spec = m.elements[e];
        if (!spec.released[0]) real(moment)[spec.node_i] += f.moment_i, ++count[spec.node_i];
        if (!spec.released[1]) real(moment)[spec.node_j] += f.moment_j, ++count[spec.node_j];
    }
    for (std::size_t i = 0; i < n; ++i)
        if (count[i] > 0) real(moment)[i] /= count[i];
    pd.push_back(std::move(moment));
    cd.push_back(std::move(axial));
    cd.push_back(std::move(mi));
    cd.push_back(std::move(mj));
    cd.push_back(std::move(shear));
    if (has(name::released)) {
        XmlArray released = integer_array(name::released, ne);
        for (std::size_t e = 0; e < ne; ++e)
            integer(released)[e] = (m.elements[e].released[0] ? 1 : 0) + (m.elements[e].released[1] ? 2 : 0);
        cd.push_back(std::move(released));
    }

    // What holds and what pushes: reactions at supported and prescribed DOFs (the force on the
    // structure), which DOFs each node's support fixes, and the applied load λF (with pressure
    // as it follows the members). Forces are vectors, moments scalars of their own.
    const auto force_and_moment = [&](const char* force_name, const char* moment_name, const std::vector<double>& nodal) {
        XmlArray force = real_array(force_name, n, 3), moment_of = real_array(moment_name, n);
        for (std::size_t i = 0; i < n; ++i) {
            set3(force, i, nodal[3 * i], nodal[3 * i + 1], 0.0);
            real(moment_of)[i] = nodal[3 * i + 2];
        }
        pd.push_back(std::move(force));
        pd.push_back(std::move(moment_of));
    };
    if (has(name::reaction)) force_and_moment(name::reaction, name::reaction_moment, r.reaction);
    if (has(name::support)) {
        XmlArray fixed = integer_array(name::support, n);
        for (const Support& s : m.supports)
            integer(fixed)[s.node] |= (s.fixed[0] ? result::fixes_ux : 0) | (s.fixed[1] ? result::fixes_uy : 0) |
                                      (s.fixed[2] ? result::fixes_rz : 0);
        pd.push_back(std::move(fixed));
    }
    if (has(name::applied_load)) force_and_moment(name::applied_load, name::applied_moment, r.applied_load);
    if (has(name::spring_force)) {
        std::vector<double> nodal(3 * n, 0.0);
        for (const SpringResult& s : r.springs)
            if (!s.unilateral)
                for (int k = 0; k < 3; ++k) nodal[3 * static_cast<std::size_t>(s.node) + k] = s.force[k];
        force_and_moment(name::spring_force, name::spring_moment, nodal);
    }
    if (has(name::contact_force)) {
        XmlArray contact = real_array(name::contact_force, n, 3), gap = real_array(name::gap, n),
                 state = integer_array(name::contact, n);
        // A node may face more than one base (a ring between plates): its forces add up, its
        // gap is to the nearest base, and it is in contact when any base holds it.
        std::vector<bool> seen(n, false);
        for (const SpringResult& s : r.springs) {
            if (!s.unilateral) continue;
            double* f = &real(contact)[3 * static_cast<std::size_t>(s.node)];
            f[0] += s.force[0];
            f[1] += s.force[1];
            double& g = real(gap)[s.node];
            g = seen[s.node] ? std::min(g, s.gap) : s.gap;
            seen[s.node] = true;
            if (s.active) integer(state)[s.node] = static_cast<int>(result::ContactCode::closed);
        }
        pd.push_back(std::move(contact));
        pd.push_back(std::move(gap));
        pd.push_back(std::move(state));
    }
    if (has(name::surface_contact_force)) {
        // Each pair presses its node one way and the segment's ends the other, shared as the
        // segment's linear shape functions share the point where it is touched.
        XmlArray surface = real_array(name::surface_contact_force, n, 3);
        for (const SurfaceContactResult& c : r.surface_contacts) {
            const double shares[2] = {c.segment[0] == c.segment[1] ? 1.0 : 1.0 - c.xi, c.segment[0] == c.segment[1] ? 0.0 : c.xi};
            for (int d = 0; d < 2; ++d) {
                real(surface)[3 * static_cast<std::size_t>(c.node) + d] += c.force[d];
                for (int end = 0; end < 2; ++end)
                    real(surface)[3 * static_cast<std::size_t>(c.segment[end]) + d] -= shares[end] * c.force[d];
            }
        }
        pd.push_back(std::move(surface));
    }
    if (has(name::yielded_share)) {
        // One tuple per element, one component per integration point (ξ order); elements
        // without fibre sections along them carry zeros.
        const int points = m.integration_points();
        XmlArray most = real_array(name::yielded_share, ne), share = real_array(name::section_yielded_share, ne, points),
                 curvature = real_array(name::section_curvature, ne, points),
                 moment_at = real_array(name::section_moment, ne, points);
        for (std::size_t e = 0; e < ne; ++e) {
            const std::vector<SectionReport>& sections = r.elements[e].sections;
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
        cd.push_back(std::move(most));
        cd.push_back(std::move(share));
        cd.push_back(std::move(curvature));
        cd.push_back(std::move(moment_at));
    }
    if (has(name::hinge_state)) {
        XmlArray util = real_array(name::plastic_utilisation, n), hinge = integer_array(name::hinge_state, n);
        XmlArray ei = real_array(name::ei_ratio, ne), ui = real_array(name::utilisation_i, ne),
                 uj = real_array(name::utilisation_j, ne);
        XmlArray end_state[2] = {integer_array(name::hinge_state_i, ne), integer_array(name::hinge_state_j, ne)};
        for (std::size_t e = 0; e < ne; ++e) {
            const ElementResult& er = r.elements[e];
            if (!er.hinged) {
                real(ei)[e] = 1.0;
                continue;
            }
            real(ei)[e] = std::min(er.hinge[0].ei_ratio, er.hinge[1].ei_ratio);
            real(ui)[e] = er.hinge[0].utilisation;
            real(uj)[e] = er.hinge[1].utilisation;
            const int nodes[2] = {m.elements[e].node_i, m.elements[e].node_j};
            for (int end = 0; end < 2; ++end) {
                const int state = static_cast<int>(hinge_code(er.hinge[end].state));
                integer(end_state[end])[e] = state;
                real(util)[nodes[end]] = std::max(real(util)[nodes[end]], er.hinge[end].utilisation);
                integer(hinge)[nodes[end]] = std::max(integer(hinge)[nodes[end]], state);
            }
        }
        pd.push_back(std::move(util));
        pd.push_back(std::move(hinge));
        cd.push_back(std::move(ei));
        cd.push_back(std::move(ui));
        cd.push_back(std::move(uj));
        cd.push_back(std::move(end_state[0]));
        cd.push_back(std::move(end_state[1]));
    }

    std::vector<XmlArray>& fd = grid.field_data;
    fd.reserve(arrays_.size());
    fd.push_back(field_value(name::time_value, time));
    fd.push_back(field_value(name::load_factor, r.load_factor));
    fd.push_back(field_value(name::load, r.load));
    fd.push_back(field_value(name::control_displacement, r.control_displacement));
    fd.push_back(field_value(name::step, r.step));
    fd.push_back(field_value(name::iterations, r.iterations));
    fd.push_back(field_value(name::contact_count, r.contact_count));
    if (has(name::surface_contact_count)) fd.push_back(field_value(name::surface_contact_count, static_cast<int>(r.surface_contacts.size())));
    fd.push_back(field_value(name::hinge_count, r.hinge_count));
    if (has(name::stage)) fd.push_back(field_value(name::stage, r.stage));
    if (has(name::pattern_factors)) {
        const std::vector<int> patterns = result::active_patterns(m);
        XmlArray factors = real_array(name::pattern_factors, patterns.size());
        std::string names;
        for (std::size_t k = 0; k < patterns.size(); ++k) {
            const std::size_t p = static_cast<std::size_t>(patterns[k]);
            real(factors)[k] = p < r.pattern_factors.size() ? r.pattern_factors[p] : 0.0;
            names += (k ? "," : "") + m.patterns[p];
        }
        fd.push_back(std::move(factors));
        fd.push_back(field_text(name::pattern_names, names));
    }
    if (has(name::mirror_x)) fd.push_back(field_value(name::mirror_x, *m.report.mirror_x));
    // Names for pictures: the render stage reads them from here, not from the scene file.
    fd.push_back(field_text(name::scene, m.name));
    fd.push_back(field_text(name::title, m.title));
    fd.push_back(field_text(name::load_label, m.report.load_label));
    fd.push_back(field_text(name::displacement_label, m.report.displacement_label));
    // Units, when the scene names them: those of the reported load and displacement follow from
    // what they measure.
    if (has(name::length_unit)) {
        fd.push_back(field_text(name::length_unit, m.report.length_unit));
        fd.push_back(field_text(name::force_unit, m.report.force_unit));
        fd.push_back(field_text(name::load_unit, units_.load));
        fd.push_back(field_text(name::displacement_unit, units_.displacement));
    }

    return grid;
}

} // namespace plastica
