#include "run_report.hpp"

#include "model_description.hpp"
#include "scene_warnings.hpp"

#include "atomic_file.hpp"
#include "analysis/support_reactions.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace plastica {

namespace {

using Json = nlohmann::ordered_json;

// What ran: the program, the scene and its size.
Json header(const Model& model, const std::string& scene_file) {
    return {{"program", "plastica"},      {"version", PLASTICA_VERSION},
            {"scene", model.name},        {"title", model.title}, {"scene_file", scene_file},
            {"load_label", model.report.load_label}, {"displacement_label", model.report.displacement_label},
            {"nodes", model.nodes.size()}, {"elements", model.elements.size()},
            {"springs", model.springs.size()}, {"inelastic", model.inelastic()}};
}

} // namespace

FinalState final_state(const Model& model, const StepResult& step) {
    FinalState f;
    f.load_factor = step.load_factor;
    f.load = step.load;
    f.control_displacement = step.control_displacement;
    f.contact_count = step.contact_count;
    f.hinge_count = step.hinge_count;
    for (const ElementResult& e : step.elements)
        for (const HingeReport& h : e.hinge) f.section_failures += h.section_failures;
    if (!model.supports.empty() && !step.reaction.empty()) f.reactions = support_reactions(model, step);
    return f;
}

std::string to_json(const RunReport& r) {
    Json j = header(*r.model, r.scene_file);
    if (!r.overrides.empty()) {
        Json set = Json::object();
        for (const auto& [path, value] : r.overrides) set[path] = value;
        j["overrides"] = set;
    }
    j["status"] = to_string(r.summary.status);
    j["reason"] = r.summary.reason;
    // What looks like a unit mistake (io/scene/scene_warnings.hpp): the run went ahead.
    if (const std::vector<std::string> warnings = scene_warnings(*r.model); !warnings.empty()) j["warnings"] = warnings;
    if (!r.drawing_notes.empty()) j["drawing_notes"] = r.drawing_notes;
    j["steps"] = r.summary.steps;
    j["iterations"] = r.summary.iterations;
    j["cut_steps"] = r.summary.cut_steps;
    j["refined_steps"] = r.summary.refined_steps;
    if (r.summary.stiffened_steps > 0) j["stiffened_steps"] = r.summary.stiffened_steps;
    if (r.model) {
        // The tolerance used and why: the scene's, or the default raised to the round-off floor.
        const AnalysisSpec& a = r.model->analysis;
        Json t = {{"given", a.residual_tolerance_follows_floor ? Json(nullptr) : Json(a.residual_tolerance)},
                            {"default", AnalysisSpec::default_residual_tolerance}};
        if (a.residual_tolerance_follows_floor && r.summary.largest_residual_tolerance > a.residual_tolerance) {
            t["largest_used"] = r.summary.largest_residual_tolerance;
            t["at_step"] = r.summary.largest_tolerance_step;
            t["why"] = "the default residual_tolerance follows the model's round-off floor (its stiffest terms times the rounding of its "
                       "displacements) where that floor lies above it; give residual_tolerance to fix it";
        }
        j["residual_tolerance"] = t;
    }
    if (r.model && r.model->transient()) {
        // Motion in time: how far it went, how well its energy balanced, what damped it.
        const DampingSpec& d = r.model->dynamics.damping;
        Json dynamics = {{"time", r.summary.time},
                         {"mass", r.model->dynamics.mass == MassKind::consistent ? "consistent" : "lumped"},
                         {"largest_energy_error", r.summary.largest_energy_error},
                         {"largest_energy_error_step", r.summary.largest_energy_error_step},
                         {"time_step_cuts", r.summary.cut_steps}};
        if (d.present())
            dynamics["damping"] = {{"alpha_m", r.summary.rayleigh_alpha_m},
                                   {"beta_k", r.summary.rayleigh_beta_k},
                                   {"stiffness", d.stiffness == DampingSpec::Stiffness::initial   ? "initial"
                                                 : d.stiffness == DampingSpec::Stiffness::tangent ? "tangent"
                                                                                                  : "committed"}};
        j["dynamics"] = dynamics;
    }
    if (r.summary.negative_pivot_steps > 0) {
        j["negative_pivot_steps"] = r.summary.negative_pivot_steps;
        j["first_negative_pivot_step"] = r.summary.first_negative_pivot_step;
    }
    // Bifurcations and limit points the path passed, each located (the modes are in the VTU of
    // the step that passed it), and whether the run ended on a branch that is not stable.
    if (!r.summary.critical_points.empty()) {
        Json points = Json::array();
        for (const CriticalPoint& c : r.summary.critical_points)
            points.push_back({{"kind", to_string(c.kind)}, {"step", c.step}, {"load_factor", c.load_factor}, {"load", c.load},
                              {"load_alignment", c.load_alignment}, {"followed", c.followed}});
        j["critical_points"] = points;
        j["ends_unstable"] = r.summary.ends_unstable;
    }
    // Which rule accepted the steps: the residual within its tolerance, or round-off
    // stagnation within ten times it (never more).
    j["accepted_by"] = {{"residual", r.summary.accepted_by_residual}, {"stagnation", r.summary.accepted_by_stagnation}};
    // Section solves (SCM) that did not converge: the end kept its previous stiffness for that
    // step. Counted over the run, so a user sees it rather than a silent plastic hinge.
    if (r.model->has_plasticity(Plasticity::hinges)) {
        j["section_solve_failures"] = r.last.section_failures;
    }
    j["final"] = {{"load_factor", r.last.load_factor}, {"load", r.last.load},
                  {"control_displacement", r.last.control_displacement},
                  {"contact_count", r.last.contact_count}, {"hinge_count", r.last.hinge_count}};
    // The supports' reactions at the last step: the force each exerts on the structure, along
    // the DOFs it fixes.
    if (!r.last.reactions.empty()) {
        const char* const names[dofs_per_node] = {"fx", "fy", "mz"};
        Json reactions = Json::array();
        for (const SupportReaction& s : r.last.reactions) {
            const Node& n = r.model->nodes[s.node];
            Json one = {{"support", s.support + 1}, {"at", {n.x, n.y}}};
            for (int d = 0; d < dofs_per_node; ++d)
                if (s.reported[d]) one[names[d]] = s.force[d];
            reactions.push_back(one);
        }
        j["final"]["reactions"] = reactions;
    }
    j["peak"] = {{"load", r.peak_load}, {"control_displacement", r.peak_load_displacement}};
    // Past the first limit point a higher load is another branch's, never the capacity.
    if (r.later_maximum)
        j["later_maximum"] = {{"load", r.later_maximum->load}, {"control_displacement", r.later_maximum->control_displacement},
                              {"step", r.later_maximum->step}};
    if (!r.model->self_contact.empty()) {
        // The walls meet: what follows is the contact penalty's (the peak above is before it).
        Json contact = {{"closed", r.self_contact.first_step > 0}};
        if (r.self_contact.first_step > 0) {
            contact["first_step"] = r.self_contact.first_step;
            contact["load"] = r.self_contact.load;
            contact["control_displacement"] = r.self_contact.control_displacement;
            contact["final_force"] = r.self_contact.last_force;
            if (r.last.load != 0.0) contact["final_share_of_load"] = r.self_contact.last_force / std::abs(r.last.load);
        }
        j["self_contact"] = contact;
    }
    if (!r.model->report.load_at.empty()) {
        Json at = Json::array();
        for (std::size_t k = 0; k < r.model->report.load_at.size(); ++k) {
            Json one = {{"control_displacement", r.model->report.load_at[k]}};
            one["load"] = k < r.load_at.size() && r.load_at[k] ? Json(*r.load_at[k]) : Json(nullptr); // null: not reached
            at.push_back(one);
        }
        j["load_at"] = at;
    }
    j["model"] = describe_model(*r.model);
    Json seconds = Json::object();
    for (const auto& [stage, s] : r.stage_seconds) seconds[stage] = s;
    j["seconds"] = seconds;
    return j.dump(2) + "\n";
}

void RunReport::note(const StepResult& r) {
    last = final_state(*model, r);
    if (!model->self_contact.empty()) {
        if (!r.surface_contacts.empty() && self_contact.first_step == 0)
            self_contact = {r.step, r.load, r.control_displacement, 0.0};
        double force = 0.0;
        for (const SurfaceContactResult& c : r.surface_contacts) force += std::hypot(c.force[0], c.force[1]);
        self_contact.last_force = model->report.load_scale * force;
    }
    if (r.past_first_limit && r.load > std::max(peak_load, later_maximum ? later_maximum->load : peak_load)) {
        later_maximum = LaterMaximum{r.step, r.load, r.control_displacement};
    } else if (!r.past_first_limit && r.load > peak_load && self_contact.first_step == 0) {
        peak_load = r.load;
        peak_load_displacement = r.control_displacement;
    }
    load_at.resize(model->report.load_at.size());
    for (std::size_t k = 0; k < load_at.size(); ++k) {
        const double target = model->report.load_at[k];
        const double from = previous_displacement, to = r.control_displacement;
        if (load_at[k] || !((from - target) * (to - target) <= 0.0) || from == to) continue;
        const double t = (target - from) / (to - from);
        load_at[k] = previous_load + t * (r.load - previous_load);
    }
    previous_load = r.load;
    previous_displacement = r.control_displacement;
}

void write_run_report(const std::string& path, const RunReport& report) {
    write_file_atomically(path, to_json(report));
}

void write_run_started(const std::string& path, const Model& model, const std::string& scene_file) {
    Json j = header(model, scene_file);
    j["status"] = "running";
    write_file_atomically(path, j.dump(2) + "\n");
}

std::string recorded_scene(const std::string& run_json) {
    std::ifstream in(run_json);
    if (!in) return {};
    const Json j = Json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object() || j.value("program", "") != "plastica") return {};
    return j.value("scene", "");
}

} // namespace plastica
