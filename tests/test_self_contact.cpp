// Contact between the members' own surfaces ([[self_contact]], contact/self_contact.hpp): the
// pair's force and tangent against finite differences, a cantilever pressed onto a cantilever
// against the closed form of two beams sharing a load, the crossing that stops the same scene
// without self-contact, and a steel ring flattened until its walls meet.
#include "analysis_helpers.hpp"
#include "crushed_ring.hpp"
#include "contact/self_contact.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using namespace plastica;
using namespace plastica::testing;

namespace {

// Two elements 0.1 deep: a–b from (0, 0) to (1, 0), and s–t from (sx, sy) to (tx, ty);
// `contact_keys` adds to [[self_contact]] (stiffness 250).
Model bars(double sx, double sy, double tx, double ty, const std::string& contact_keys) {
    const std::string text =
        "[scene]\nname = \"bars\"\n[[material]]\nname = \"m\"\nE = 1000.0\n"
        "[[section]]\nname = \"bar\"\nmaterial = \"m\"\nshape = \"rectangle\"\nb = 0.1\nh = 0.1\n"
        "[[node]]\nid = 1\nx = 0.0\ny = 0.0\n[[node]]\nid = 2\nx = 1.0\ny = 0.0\n"
        "[[node]]\nid = 3\nx = " + std::to_string(sx) + "\ny = " + std::to_string(sy) + "\n"
        "[[node]]\nid = 4\nx = " + std::to_string(tx) + "\ny = " + std::to_string(ty) + "\n"
        "[[element]]\nnodes = [1, 2]\nsection = \"bar\"\n[[element]]\nnodes = [3, 4]\nsection = \"bar\"\n"
        "[[support]]\nnode = 1\nfix = [\"ux\", \"uy\", \"rz\"]\n[[load]]\nnode = 4\nfy = -1.0\n"
        "[[self_contact]]\non = \"all\"\nstiffness = 250.0\n" + contact_keys +
        "[analysis]\nscheme = \"load_control\"\nincrement = 0.1\ntarget_load_factor = 1.0\n";
    return read_scene_text(text, "bars.toml");
}

// s–t upright, s near a–b.
Model two_bars(double sx, double sy) { return bars(sx, sy, sx, 1.0, ""); }

// The contacts' internal forces gathered on the full DOF vector.
Eigen::VectorXd contact_force(SelfContact& contact, const Eigen::VectorXd& u) {
    contact.evaluate(u, false, 0.0);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(u.size());
    for (const SurfaceContact& c : contact.contacts()) {
        const auto nodes = c.node_list();
        for (int k = 0; k < c.nodes(); ++k) f.segment<2>(3 * nodes[k]) += c.force.segment<2>(2 * k);
    }
    return f;
}

// The smallest distance from a node to a segment of the model that is not one of its own
// elements' neighbours (nearer than `skip` along the members), at displacement u.
double nearest_other_segment(const Model& m, const std::vector<double>& u, double skip) {
    auto at = [&](int n) {
        return Eigen::Vector2d(m.nodes[n].x + u[3 * n], m.nodes[n].y + u[3 * n + 1]);
    };
    double nearest = 1e300;
    for (std::size_t n = 0; n < m.nodes.size(); ++n)
        for (const ElementSpec& e : m.elements) {
            const Node &a0 = m.nodes[e.node_i], &b0 = m.nodes[e.node_j], &p0 = m.nodes[n];
            // The initial distance stands in for the distance along a ring's members.
            if (std::hypot(a0.x - p0.x, a0.y - p0.y) < skip || std::hypot(b0.x - p0.x, b0.y - p0.y) < skip) continue;
            const Eigen::Vector2d a = at(e.node_i), b = at(e.node_j), p = at(static_cast<int>(n));
            const double xi = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
            nearest = std::min(nearest, (p - a - xi * (b - a)).norm());
        }
    return nearest;
}

} // namespace

TEST_CASE("A pair of surfaces has the force and tangent of its penalty potential", "[contact][self_contact]") {
    // Interior (the node over the middle of the segment) and a segment end (beyond its end).
    for (const auto& place : {std::pair{0.4, 0.08}, std::pair{1.05, 0.06}}) {
        const Model m = two_bars(place.first, place.second);
        SelfContact contact(m);
        Eigen::VectorXd u = Eigen::VectorXd::Zero(m.dof_count());
        u[3 * 1 + 1] = 0.03; // b lifted: the segment slopes
        u[3 * 2] = 0.004, u[3 * 2 + 1] = 0.01;
        contact_force(contact, u);
        REQUIRE(contact.contacts().size() == 1);
        const SurfaceContact c = contact.contacts().front();
        CAPTURE(place.first, c.xi, c.gap);
        CHECK(c.nodes() == (place.first < 1.0 ? 3 : 2));
        CHECK(c.gap < 0.0);
        CHECK(c.gap > -0.1);
        // The force pushes the node away from the segment: along its normal, outward.
        CHECK(-c.force.head<2>().dot(c.normal) == Approx(250.0 * -c.gap).epsilon(1e-12));
        // Self-equilibrated: the pair exerts no net force.
        CHECK(std::abs(c.force[0] + c.force[2] + c.force[4]) < 1e-12);
        CHECK(std::abs(c.force[1] + c.force[3] + c.force[5]) < 1e-12);
        // Every column of the tangent against central differences of the force.
        const auto nodes = c.node_list();
        double worst = 0.0;
        for (int k = 0; k < c.nodes(); ++k)
            for (int d = 0; d < 2; ++d) {
                const int dof = 3 * nodes[k] + d;
                const double h = 1e-6;
                Eigen::VectorXd up = u, down = u;
                up[dof] += h, down[dof] -= h;
                const Eigen::VectorXd column = (contact_force(contact, up) - contact_force(contact, down)) / (2.0 * h);
                for (int i = 0; i < c.nodes(); ++i)
                    for (int e = 0; e < 2; ++e)
                        worst = std::max(worst, std::abs(column[3 * nodes[i] + e] - c.tangent(2 * i + e, 2 * k + d)));
            }
        CHECK(worst < 1e-6 * 250.0);
    }
}

TEST_CASE("A cantilever pressed onto a cantilever shares the load as two beams in contact", "[contact][self_contact]") {
    // Closed form (Euler–Bernoulli, small deflections): the tips meet at P0 = 3EI·g0/L³, then
    // F = (P − P0)/2 presses the lower tip and the upper deflects g0 + F·L³/3EI. The deflections
    // are 1.2 % of L: the co-rotational answer differs from the linear one by about (δ/L)² and the
    // penalty's penetration F/k is 1e-8 of g0. Measured: 2e-5 relative.
    const Run r = run_scene_file("tests/contact/parallel_cantilevers.toml");
    INFO(r.summary.reason);
    REQUIRE(r.summary.status == RunStatus::completed);
    const double E = 210.0e6, I = 0.05 * std::pow(0.01, 3) / 12.0, L = 1.0, g0 = 0.005;
    const double P0 = 3.0 * E * I * g0 / (L * L * L);
    for (const StepResult& s : r.steps) {
        const double P = s.load;
        const double F = std::max(0.0, (P - P0) / 2.0);
        CAPTURE(s.step, P, F);
        double pushed = 0.0;
        for (const SurfaceContactResult& c : s.surface_contacts) {
            pushed += std::hypot(c.force[0], c.force[1]);
            CHECK(c.gap < 0.0);
        }
        CHECK(pushed == Approx(F).margin(1e-4 * P0));
        // The lower cantilever carries nothing but the contact: its clamp holds it up with F.
        const int lower_root = static_cast<int>(std::find_if(r.model.nodes.begin(), r.model.nodes.end(), [](const Node& n) {
                                                     return n.x == 0.0 && n.y == 0.0;
                                                 }) - r.model.nodes.begin());
        CHECK(s.reaction[3 * static_cast<std::size_t>(lower_root) + 1] == Approx(F).margin(1e-4 * P0));
        const double upper_tip = -r.node_dof(s, 1.0, 0.015, 1);
        CHECK(upper_tip == Approx(P <= P0 ? P * L * L * L / (3.0 * E * I) : g0 + F * L * L * L / (3.0 * E * I)).epsilon(1e-3));
    }
    CHECK(r.steps.back().surface_contacts.size() >= 1);
    // The surfaces stay 0.01 apart (the bars' depth), within the penalty's penetration.
    CHECK(nearest_other_segment(r.model, r.steps.back().displacement, 0.01) > 0.01 * (1.0 - 1e-5));
}

TEST_CASE("Without self-contact the cantilever passes through the other and the run stops there", "[contact][self_contact][penetration]") {
    Model m = read_scene_text(scene_file_text("tests/contact/parallel_cantilevers.toml"), "parallel_cantilevers.toml");
    m.self_contact.clear();
    const Run r = run_model(std::move(m));
    CHECK(r.summary.status == RunStatus::penetration);
    CHECK_THAT(r.summary.reason, Catch::Contains("passes through"));
    // The centre lines cross once the upper tip has fallen its 0.015 onto the lower (the lower
    // does not move): the step that crossed is the last one kept, within a step's travel of it
    // (0.05 of the load moves the tip by 0.00095).
    const double tip = -r.node_dof(r.steps.back(), 1.0, 0.015, 1);
    CHECK(tip == Approx(0.015).margin(0.001));
    CHECK(r.steps.back().surface_contacts.empty());
}

TEST_CASE("A steel pipe ring flattened between plates stops where its walls meet", "[contact][self_contact][crushing]") {
    // R = 100, wall h = 5: the walls meet when the plates are h apart, a travel of 2R − h = 195.
    const Run r = run_scene_file("models/gallery/steel_pipe_flattened.toml");
    INFO(r.summary.reason);
    REQUIRE(r.summary.status == RunStatus::completed);
    const double h = 5.0;
    CHECK(r.steps.back().load_factor == Approx(195.0).epsilon(1e-9));
    // No contact between the walls while they are far apart; at the end the walls press along
    // the flats, and no node has come nearer another wall's centre line than the wall's depth
    // (within the penalty's penetration, below 1 % of h).
    for (const StepResult& s : r.steps)
        if (s.load_factor < 150.0) CHECK(s.surface_contacts.empty());
    CHECK(r.steps.back().surface_contacts.size() >= 10);
    for (const StepResult& s : r.steps)
        if (s.step % 25 == 0 || &s == &r.steps.back()) {
            CAPTURE(s.step, s.load_factor);
            CHECK(nearest_other_segment(r.model, s.displacement, 2.0 * 2.0 * h) > 0.99 * h);
        }
    // The walls' contact forces are internal (each pair exerts no net force), so the two
    // plates' forces balance on their own, whatever the walls carry between them.
    const StepResult& last = r.steps.back();
    // A pair within round-off of touching keeps its state (no flipping in Newton): its gap may
    // sit a hair above zero.
    for (const SurfaceContactResult& c : last.surface_contacts) {
        CHECK(c.gap < 1e-6 * h);
        CHECK(c.gap > -0.01 * h);
    }
    double up = 0.0, down = 0.0;
    for (const SpringResult& s : last.springs) (s.force[1] > 0.0 ? up : down) += s.force[1];
    CHECK(up > 0.0);
    CHECK(up == Approx(-down).epsilon(1e-6));
    CHECK(2.0 * up == Approx(last.load).epsilon(1e-6));
}

TEST_CASE("A ring pressed onto a ring shortens as two rings in series", "[contact][self_contact]") {
    // Each ring is pinched by two opposite forces P: δ_ring = (π/4 − 2/π)·P R³/EI (Castigliano).
    // In series with the two plates' penalty (1200, halved on the symmetry line of the half
    // model) and the rings' contact penalty (100·12EI/ℓ³ = 4800 on the half model's P/2).
    const Run two = run_scene_file("tests/contact/two_rings_stacked.toml");
    INFO(two.summary.reason);
    REQUIRE(two.summary.status == RunStatus::completed);
    const double R = 100.0, EI = 1e3, ring = (M_PI / 4.0 - 2.0 / M_PI) * R * R * R / EI;
    const double plates = 2.0 / 1200.0, contact = 1.0 / (2.0 * 4800.0);
    const StepResult& first = two.steps[1];
    REQUIRE(first.surface_contacts.size() == 1);
    // The rings touch on the symmetry line, pressed with the half model's P/2 (to the residual
    // the steps are accepted with, 1e-6 of the load per DOF, summed over the ring's 51 nodes).
    CHECK(std::hypot(first.surface_contacts[0].force[0], first.surface_contacts[0].force[1]) ==
          Approx(first.load / 2.0).epsilon(1e-4));
    // δ/R = 5e-5: the 50 chords of each half ring make a ring 8e-4 stiffer than Castigliano's;
    // the single ring between the same plates shows the same (models/gallery/ring_between_plates.toml).
    const double flexibility = first.load_factor / first.load;
    CHECK(flexibility == Approx(2.0 * ring + plates + contact).epsilon(1e-3));
    // Against that single ring, measured: the contact between the rings adds only its penalty.
    std::string one = scene_file_text("models/gallery/ring_between_plates.toml");
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"increment = 0.5", "increment = 0.005"},
                                   {"target_load_factor = 120.0", "target_load_factor = 0.005"},
                                   {"residual_tolerance = 1e-5", ""}})
        one.replace(one.find(from), from.size(), to);
    const Run single = run_scene(one);
    REQUIRE(single.summary.status == RunStatus::completed);
    const double single_ring = single.steps[1].load_factor / single.steps[1].load - plates;
    CHECK(flexibility == Approx(2.0 * single_ring + plates + contact).epsilon(1e-4));
    for (const StepResult& s : two.steps)
        if (s.step > 0) CHECK(s.load_factor / s.load == Approx(flexibility).epsilon(1e-3));
}

namespace {

// s–t above a–b, from x = 0 to 1, touching along the members: the stiffness a penalty per
// unit length.
Model parallel_bars(double ys, double yt) { return bars(0.0, ys, 1.0, yt, "acts_on = \"members\"\n"); }

} // namespace

TEST_CASE("Surfaces touching along the members press with the penalty per unit length and its exact tangent", "[contact][self_contact]") {
    // Parallel at 0.09 (the reach 0.1): the penetration 0.01 is uniform, so each bar is pressed
    // with 250·0.01 per unit length, 2.5 in all, whichever surface's points carry it.
    {
        const Model m = parallel_bars(0.09, 0.09);
        SelfContact contact(m);
        const Eigen::VectorXd f = contact_force(contact, Eigen::VectorXd::Zero(m.dof_count()));
        CHECK(f[3 * 2 + 1] + f[3 * 3 + 1] == Approx(-2.5).epsilon(1e-12)); // on the upper bar, downward internal force
        CHECK(f[3 * 0 + 1] + f[3 * 1 + 1] == Approx(2.5).epsilon(1e-12));
        // Uniform: shared equally between each bar's ends.
        CHECK(f[3 * 2 + 1] == Approx(f[3 * 3 + 1]).epsilon(1e-12));
        for (const SurfaceContact& c : contact.contacts()) CHECK(c.along_member());
    }
    // Tilted and moved: the force, and every column of the tangent against central differences
    // of the forces.
    const Model m = parallel_bars(0.085, 0.095);
    SelfContact contact(m);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(m.dof_count());
    u[3 * 1 + 1] = 0.002, u[3 * 2] = 0.01, u[3 * 3 + 1] = -0.001;
    const Eigen::VectorXd f0 = contact_force(contact, u);
    REQUIRE(contact.contacts().size() >= 6);
    // Moved, the upper bar runs from (0.01, 0.085) to (1, 0.094) and the lower from (0, 0) to
    // (1, 0.002): the penetration falls linearly from 0.015 to 0.008, and each surface's points
    // integrate half the penalty of it over their own bar exactly (lengths 0.99 and 1). Within 1 %:
    // the normals tilt by 0.009, and the lower bar's first 0.01 meets the upper bar's end.
    const double upper_pass = 0.5 * 250.0 * 0.99 * (0.01502 + 0.008) / 2.0, lower_pass = 0.5 * 250.0 * 1.0 * (0.015 + 0.008) / 2.0;
    CHECK(f0[3 * 2 + 1] + f0[3 * 3 + 1] == Approx(-(upper_pass + lower_pass)).epsilon(0.01));
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(u.size(), u.size());
    for (const SurfaceContact& c : contact.contacts()) {
        const auto nodes = c.node_list();
        for (int a = 0; a < c.nodes(); ++a)
            for (int b = 0; b < c.nodes(); ++b)
                K.block<2, 2>(3 * nodes[a], 3 * nodes[b]) += c.tangent.block<2, 2>(2 * a, 2 * b);
    }
    double worst = 0.0;
    for (int node = 0; node < 4; ++node)
        for (int d = 0; d < 2; ++d) {
            const int dof = 3 * node + d;
            const double h = 1e-7;
            Eigen::VectorXd up = u, down = u;
            up[dof] += h, down[dof] -= h;
            const Eigen::VectorXd column = (contact_force(contact, up) - contact_force(contact, down)) / (2.0 * h);
            worst = std::max(worst, (column - K.col(dof)).cwiseAbs().maxCoeff());
        }
    CHECK(worst < 1e-6 * 250.0);
}

TEST_CASE("A ring crushed onto a steel bed with contact along the members spreads its flat more smoothly than node by node", "[contact][self_contact][crushing]") {
    // tests/contact/ring_on_bed.toml: the ring meets a deep steel member through self-contact.
    // The curve's largest deviation from the mean of its 9 neighbours (0.5 mm apart) past
    // δ = 0.1 D: node by node the flat grows in steps (measured 0.75 %); with Gauss–Lobatto
    // points along the members a third of an element at a time (0.16 %; 0.61 % with a penalty
    // ten times as stiff, whose Winkler length is under an element: the points then feel the
    // corners of the chords, the wall's polygon).
    const Model along = read_scene_text(scene_file_text("tests/contact/ring_on_bed.toml"), "ring_on_bed.toml");
    Model nodes = along;
    nodes.self_contact.front().along_members = false;
    nodes.self_contact.front().stiffness = 350.0 * M_PI * 100.0 / 50.0;
    const Run smooth = run_model(along), stepped = run_model(std::move(nodes));
    REQUIRE(smooth.summary.status == RunStatus::completed);
    REQUIRE(stepped.summary.status == RunStatus::completed);
    const double along_roughness = crush_roughness(smooth, 20.0), node_roughness = crush_roughness(stepped, 20.0);
    CAPTURE(along_roughness, node_roughness);
    CHECK(node_roughness > 0.005);
    CHECK(along_roughness < 0.003);
    // The same ring either way: the loads at half the travel agree within the steps' height.
    CHECK(smooth.steps.back().load == Approx(stepped.steps.back().load).epsilon(0.01));
}
