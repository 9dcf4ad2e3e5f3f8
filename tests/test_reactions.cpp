// Support reactions against statics: the forces the supports exert balance the applied loads
// and the springs, in force and in moment about a point, in the deformed configuration.
#include "analysis_helpers.hpp"
#include "analysis/support_reactions.hpp"
#include "curve_writer.hpp"
#include "step_dataset.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace plastica;
using namespace plastica::testing;

namespace {

// Σ over the nodes of (applied load + reaction + spring force): force x, force y, and moment
// about the origin at the deformed positions. Zero at equilibrium.
std::array<double, 3> unbalance(const Model& m, const StepResult& s) {
    std::vector<double> total(s.applied_load);
    for (std::size_t i = 0; i < total.size(); ++i) total[i] += s.reaction[i];
    for (const SpringResult& spring : s.springs)
        for (int d = 0; d < 3; ++d) total[3 * spring.node + d] += spring.force[d];
    std::array<double, 3> sum{0.0, 0.0, 0.0};
    for (std::size_t k = 0; k < m.nodes.size(); ++k) {
        const double x = m.nodes[k].x + s.displacement[3 * k], y = m.nodes[k].y + s.displacement[3 * k + 1];
        const double fx = total[3 * k], fy = total[3 * k + 1];
        sum[0] += fx;
        sum[1] += fy;
        sum[2] += total[3 * k + 2] + x * fy - y * fx;
    }
    return sum;
}

double largest_applied(const StepResult& s) {
    double a = 0.0;
    for (double v : s.applied_load) a = std::max(a, std::abs(v));
    return a;
}

} // namespace

TEST_CASE("A clamp holds a cantilever bent far by a tip load: P up, P × the tip's arm", "[reactions]") {
    // PL²/EI = 10 bends the tip in to x = 0.4 L or so; the clamp's moment is P times the tip's
    // horizontal distance in the deformed state (statics, to the Newton tolerance).
    const double L = 10.0, EI = 100.0, P = 10.0 * EI / (L * L);
    const Run r = run_scene(cantilever(L, 20, 100.0, 1.0e4, 1.0, "[[load]]\nat = [10.0, 0.0]\nfy = " + num(-P) + "\n",
                                       "scheme = \"load_control\"\nincrement = 0.05\nadaptive = false\ntarget_load_factor = 1.0\n"
                                       "control_at = [10.0, 0.0]\n"));
    REQUIRE(r.summary.status == RunStatus::completed);
    const StepResult& s = r.steps.back();
    const std::vector<SupportReaction> clamp = support_reactions(r.model, s);
    REQUIRE(clamp.size() == 1);
    const double tip_x = L + r.node_dof(s, L, 0.0, 0);
    CHECK(tip_x < 0.9 * L); // far from linear
    CHECK(std::abs(clamp[0].force[0]) < 1e-9 * P);
    CHECK(clamp[0].force[1] == Approx(P).epsilon(1e-9));
    CHECK(clamp[0].force[2] == Approx(P * tip_x).epsilon(1e-6));
}

TEST_CASE("Reactions, springs and loads balance in force and moment", "[reactions]") {
    // The portal frame of the gallery (two clamped feet, gravity and sway loads), the pipe on
    // tensionless soil (supports on a symmetry line, springs, a point load) and the ring under
    // follower pressure (three point supports): the unbalance is the sum of the Newton residual's
    // components, within the residual tolerance of the loads (measured: below 4e-7).
    for (const char* scene : {"models/gallery/portal_frame.toml", "models/gallery/pipe_on_soil.toml",
                              "models/gallery/ring_external_pressure.toml"}) {
        INFO(scene);
        const Run r = run_scene_file(scene);
        REQUIRE(r.summary.status == RunStatus::completed);
        double extent = 0.0;
        for (const Node& a : r.model.nodes)
            for (const Node& b : r.model.nodes) extent = std::max(extent, std::hypot(a.x - b.x, a.y - b.y));
        for (std::size_t k = r.steps.size() / 2; k < r.steps.size(); k += std::max<std::size_t>(1, r.steps.size() / 6)) {
            const StepResult& s = r.steps[k];
            const std::array<double, 3> out = unbalance(r.model, s);
            const double scale = largest_applied(s) * r.model.nodes.size();
            CHECK(std::abs(out[0]) <= 1e-6 * scale);
            CHECK(std::abs(out[1]) <= 1e-6 * scale);
            CHECK(std::abs(out[2]) <= 1e-6 * scale * extent);
        }
    }
}

TEST_CASE("Each fixed DOF is one reaction column, reported by the first support that fixes it", "[reactions]") {
    std::string scene = cantilever(10.0, 4, 1.0e4, 1.0e2, 1.0, "[[support]]\nat = [0.0, 0.0]\nfix = [\"uy\"]\n[[support]]\nat = [5.0, 0.0]\nfix = [\"uy\"]\n[[load]]\nat = [10.0, 0.0]\nfy = -1.0\n",
                                   "scheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\n");
    const Model m = read_scene_text(scene, "beam.toml");
    CHECK(reaction_columns(m) == std::vector<std::string>{"support1_fx", "support1_fy", "support1_mz", "support3_fy"});
}

namespace {

// A fixed-base portal pushed sideways by λ (and pressed by 10 λ on each column), its right base pinned.
std::string side_loaded_portal() {
    return R"([scene]
name = "portal"
[[material]]
name = "m"
E = 1.0e3
[[section]]
name = "s"
material = "m"
A = 1.0e5
I = 1.0
[[line]]
start = [0.0, 0.0]
end = [0.0, 4.0]
elements = 4
section = "s"
[[line]]
start = [0.0, 4.0]
end = [6.0, 4.0]
elements = 4
section = "s"
[[line]]
start = [6.0, 4.0]
end = [6.0, 0.0]
elements = 4
section = "s"
[[support]]
at = [0.0, 0.0]
fix = ["ux", "uy", "rz"]
[[support]]
at = [6.0, 0.0]
fix = ["ux", "uy"]
[[load]]
at = [0.0, 4.0]
fx = 1.0
[[load]]
at = [0.0, 4.0]
fy = -10.0
[[load]]
at = [6.0, 4.0]
fy = -10.0
[analysis]
scheme = "load_control"
increment = 0.5
target_load_factor = 2.0
control_at = [0.0, 4.0]
control_dof = "ux"
)";
}

} // namespace

TEST_CASE("curve.csv's base shear is the sum of the supports' x reactions, the side load a frame carries", "[reactions]") {
    // A fixed-base portal pushed sideways by λ (and pressed by 10 λ on each column): the
    // supports hold the whole side load, so the base shear is λ at every step.
    const Run r = run_scene(side_loaded_portal());
    REQUIRE(r.summary.status == RunStatus::completed);
    const std::string header = curve_header(r.model);
    std::vector<std::string> columns;
    for (std::size_t at = 0, end; at < header.size(); at = end + 1) {
        end = header.find_first_of(",\n", at);
        columns.push_back(header.substr(at, end - at));
    }
    const auto column = [&](const std::string& name) {
        const auto it = std::find(columns.begin(), columns.end(), name);
        REQUIRE(it != columns.end());
        return static_cast<std::size_t>(it - columns.begin());
    };
    for (const StepResult& s : r.steps) {
        const std::string row = curve_row(r.model, s);
        std::vector<double> cells;
        for (std::size_t at = 0, end; at < row.size(); at = end + 1) {
            end = row.find_first_of(",\n", at);
            const std::string cell = row.substr(at, end - at);
            cells.push_back(cell.empty() || !(std::isdigit(static_cast<unsigned char>(cell[0])) || cell[0] == '-') ? NAN : std::stod(cell));
        }
        const double shear = cells[column("base_shear")];
        CHECK(shear == Approx(-(cells[column("support1_fx")] + cells[column("support2_fx")])).margin(1e-9));
        CHECK(shear == Approx(s.load_factor).epsilon(1e-9).margin(1e-12));
    }
}

TEST_CASE("Global end forces balance the loads and reactions at every node and give the documented shear", "[reactions]") {
    // The VTU's end_forces are what the nodes exert on each element: at a node, their sum over the
    // elements meeting there is the load applied there plus the support's reaction.
    const Run r = run_scene(side_loaded_portal());
    REQUIRE(r.summary.status == RunStatus::completed);
    const StepDataset dataset(r.model);
    const XmlDataset d = dataset(r.steps.back(), 0.0);
    const auto array = [](const std::vector<XmlArray>& list, const char* name) -> const std::vector<double>& {
        const auto it = std::find_if(list.begin(), list.end(), [&](const XmlArray& a) { return a.name == name; });
        REQUIRE(it != list.end());
        return std::get<std::vector<double>>(it->values);
    };
    const std::vector<double>& ends = array(d.cell_data, "end_forces");
    const std::vector<double>& load = array(d.point_data, "applied_load");
    const std::vector<double>& moment = array(d.point_data, "applied_moment");
    const std::vector<double>& reaction = array(d.point_data, "reaction");
    const std::vector<double>& reaction_moment = array(d.point_data, "reaction_moment");
    std::vector<double> sum(3 * r.model.nodes.size(), 0.0);
    for (std::size_t e = 0; e < r.model.elements.size(); ++e)
        for (int k = 0; k < 3; ++k) {
            sum[3 * r.model.elements[e].node_i + k] += ends[6 * e + k];
            sum[3 * r.model.elements[e].node_j + k] += ends[6 * e + 3 + k];
        }
    // The documented shear, (moment_j − moment_i)/L over the current length, is the end forces'
    // component across the chord; N is their component along it.
    const std::vector<double>& shear = array(d.cell_data, "shear");
    const std::vector<double>& axial = array(d.cell_data, "axial_force");
    const std::vector<double>& mi = array(d.cell_data, "moment_i");
    const std::vector<double>& mj = array(d.cell_data, "moment_j");
    const StepResult& last = r.steps.back();
    for (std::size_t e = 0; e < r.model.elements.size(); ++e) {
        const ElementSpec& el = r.model.elements[e];
        const double dx = r.model.nodes[el.node_j].x + last.displacement[3 * el.node_j] - r.model.nodes[el.node_i].x - last.displacement[3 * el.node_i];
        const double dy = r.model.nodes[el.node_j].y + last.displacement[3 * el.node_j + 1] - r.model.nodes[el.node_i].y - last.displacement[3 * el.node_i + 1];
        const double L = std::hypot(dx, dy), c = dx / L, s = dy / L;
        CAPTURE(e);
        CHECK(shear[e] == Approx((mj[e] - mi[e]) / L).margin(1e-9));
        CHECK(-ends[6 * e] * s + ends[6 * e + 1] * c == Approx(shear[e]).margin(1e-9));
        CHECK(-(ends[6 * e] * c + ends[6 * e + 1] * s) == Approx(axial[e]).margin(1e-9));
    }
    for (std::size_t n = 0; n < r.model.nodes.size(); ++n) {
        CAPTURE(n);
        CHECK(sum[3 * n] == Approx(load[3 * n] + reaction[3 * n]).margin(1e-8));
        CHECK(sum[3 * n + 1] == Approx(load[3 * n + 1] + reaction[3 * n + 1]).margin(1e-8));
        CHECK(sum[3 * n + 2] == Approx(moment[n] + reaction_moment[n]).margin(1e-8));
    }
}
