// The scene's [analysis], [[stage]]s, load patterns and [report] (io/scene/scene_builder.hpp).
#include "scene_builder.hpp"

#include "dynamics_reader.hpp"
#include "member_geometry.hpp"
#include "model_building.hpp"
#include "section_shapes.hpp"

#include "material/material_registry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace plastica::detail {

// The load pattern a load, pressure, prescribed displacement or moving base belongs to
// ('pattern', default "main"), registered in Model::patterns on first use.
int SceneBuilder::pattern_of(TomlTableReader& r) {
    const std::string name = r.string("pattern");
    if (name.empty() || name.size() > 32 ||
        !std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; }))
        r.fail("pattern", "expected 1 to 32 letters, digits, '_' or '-' (it names a curve column)");
    const auto known = std::find(model_.patterns.begin(), model_.patterns.end(), name);
    if (known != model_.patterns.end()) return static_cast<int>(known - model_.patterns.begin());
    model_.patterns.push_back(name);
    return static_cast<int>(model_.patterns.size() - 1);
}

// The pattern a stage drives: one with loads, pressures, prescribed displacements or a moving base.
int SceneBuilder::driven_pattern(TomlTableReader& r) {
    const std::string name = r.string("pattern");
    const auto known = std::find(model_.patterns.begin(), model_.patterns.end(), name);
    const int p = static_cast<int>(known - model_.patterns.begin());
    // A scene with nothing to drive at all is told so once it is read (build()).
    if (!model_.loaded() && !model_.has_moving_base()) return 0;
    if (known == model_.patterns.end() || (!model_.loaded(p) && !model_.has_moving_base(p))) {
        std::string names;
        for (std::size_t k = 0; k < model_.patterns.size(); ++k)
            if (model_.loaded(static_cast<int>(k)) || model_.has_moving_base(static_cast<int>(k)))
                names += (names.empty() ? "'" : ", '") + model_.patterns[k] + "'";
        r.fail("pattern", "no load, pressure, prescribed displacement or moving base belongs to pattern '" + name +
                              "'" + (r.has("pattern") ? "" : " (the default)") + "; the scene's patterns: " + names);
    }
    return p;
}

// Stages after [analysis]'s, each under load or displacement control toward a target on
// either side of where the previous one ended (unload to λ = 0, reload, reverse).
void SceneBuilder::read_stages(TomlTableReader& top) {
    const Tables list = array_of_tables(top, "stage");
    const AnalysisSpec& a = model_.analysis;
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, file_, indexed("stage", i), scene_table("stage"), units());
        StageSpec s;
        const bool transient = r.choice("scheme") == "transient";
        // Patterns with a [[time_series]] follow it in a transient stage; the rest hold.
        s.pattern = transient && !r.has("pattern") ? (model_.stages.empty() ? a.pattern : model_.stages.back().pattern)
                                                   : driven_pattern(r);
        s.control = model_.stages.empty() ? a.control : model_.stages.back().control;
        if (r.has("control_at") || r.has("control_node")) {
            s.control = read_control(r, s.pattern);
        } else {
            for (const char* key : {"control_dof", "control_sign"})
                if (r.has(key)) r.fail(key, "name the controlled point as well ('control_at' or 'control_node')");
        }
        const std::string scheme = r.choice("scheme");
        s.scheme = scheme == "load_control" ? Scheme::load_control
                 : scheme == "transient" ? Scheme::transient : Scheme::displacement_control;
        if (s.scheme == Scheme::transient) {
            s.transient = read_transient(r);
            check_transient_step(r, s.transient, model_);
            // Each stage is held to 10⁷ steps, and so are all of them together.
            double steps = s.transient.duration / s.transient.time_step;
            if (a.scheme == Scheme::transient) steps += a.transient.duration / a.transient.time_step;
            for (const StageSpec& before : model_.stages)
                if (before.scheme == Scheme::transient) steps += before.transient.duration / before.transient.time_step;
            if (steps > 1e7)
                r.fail("duration", "the transient stages take " + std::to_string(static_cast<long long>(steps)) +
                                       " steps in all, more than 10⁷: lengthen the steps or shorten the durations");
            r.finish();
            model_.stages.push_back(s);
            continue;
        }
        for (const char* key : {"time_step", "duration", "integrator", "alpha"})
            if (r.has(key)) r.fail(key, "a key of scheme = \"transient\"");
        const Dimension controlled = control_dimension(s.control);
        s.increment = r.number("increment", s.scheme == Scheme::displacement_control ? controlled : dimension::none);
        s.adaptive = r.boolean("adaptive");
        if (r.has("target_load_factor") && r.has("target_displacement"))
            r.fail("target_displacement", "give one stop, 'target_load_factor' or 'target_displacement', not both");
        if (r.has("target_load_factor")) s.target_load_factor = r.number("target_load_factor");
        if (r.has("target_displacement")) s.target_displacement = r.number("target_displacement", controlled);
        if (!s.target_load_factor && !s.target_displacement)
            r.fail("", "missing a stop: 'target_load_factor' or 'target_displacement'");
        if (s.scheme == Scheme::load_control && s.target_displacement)
            r.fail("target_displacement", "a load-controlled stage stops at a 'target_load_factor'");
        if (s.scheme == Scheme::displacement_control && s.target_load_factor)
            r.fail("target_load_factor", "a displacement-controlled stage stops at a 'target_displacement'");
        if (s.scheme == Scheme::displacement_control) {
            const std::string named = r.has("control_at") || r.has("control_node") ? "" : " (an earlier stage or [analysis] names it)";
            for (const Support& sup : model_.supports)
                if (sup.node == s.control.node && sup.fixed[s.control.dof])
                    r.fail("scheme", "the controlled DOF is supported" + named);
            for (const PrescribedDisplacement& p : model_.prescribed)
                if (p.node == s.control.node && p.dof == s.control.dof)
                    r.fail("scheme", "the controlled DOF has a prescribed displacement" + named);
        }
        r.finish();
        model_.stages.push_back(s);
    }
}

// A pattern no stage drives would never act: most likely a misspelt name.
void SceneBuilder::check_patterns_driven(TomlTableReader& top) {
    std::vector<bool> driven(model_.patterns.size(), false);
    driven[static_cast<std::size_t>(model_.analysis.pattern)] = true;
    for (const StageSpec& st : model_.stages) driven[static_cast<std::size_t>(st.pattern)] = true;
    // In time, a pattern follows its series; from t = 0, every pattern acts.
    if (model_.transient())
        for (const TimeSeriesSpec& ts : model_.dynamics.series) driven[static_cast<std::size_t>(ts.pattern)] = true;
    if (model_.analysis.scheme == Scheme::transient) std::fill(driven.begin(), driven.end(), true);
    for (std::size_t p = 0; p < driven.size(); ++p)
        if (!driven[p] && (model_.loaded(static_cast<int>(p)) || model_.has_moving_base(static_cast<int>(p))))
            top.fail("stage", "load pattern '" + model_.patterns[p] +
                                  "' is driven by neither [analysis] nor a [[stage]] ('pattern = \"" + model_.patterns[p] +
                                  "\"'), so its loads would never act");
}

void SceneBuilder::read_analysis(TomlTableReader& top) {
    const toml::table* t = top.table("analysis");
    if (!t) top.fail("", "missing required table [analysis]");
    TomlTableReader r(*t, file_, "analysis", scene_table("analysis"), units());
    AnalysisSpec& a = model_.analysis;
    const std::string scheme = r.choice("scheme");
    a.scheme = scheme == "arc_length" ? Scheme::arc_length
             : scheme == "load_control" ? Scheme::load_control
             : scheme == "transient" ? Scheme::transient : Scheme::displacement_control;
    model_.dynamics.mass = r.choice("mass") == "lumped" ? MassKind::lumped : MassKind::consistent;
    a.geometry = r.choice("geometry") == "first_order" ? Geometry::first_order : Geometry::large_displacement;
    if (a.scheme == Scheme::transient) {
        read_transient_analysis(r);
        return;
    }
    for (const char* key : {"time_step", "duration", "integrator", "alpha"})
        if (r.has(key)) r.fail(key, "a key of scheme = \"transient\"");
    // Displacement control steps the controlled DOF; load control and arc length step λ.
    const Dimension controlled = r.choice("control_dof") == "rz" ? dimension::none : dimension::length;
    const Dimension step = a.scheme == Scheme::displacement_control ? controlled : dimension::none;
    a.initial_increment = r.number("increment", step);
    a.min_increment = r.number_or("min_increment", a.initial_increment * 1e-6, step);
    a.max_increment = r.number_or("max_increment", 0.0 + a.initial_increment * 10.0, step);
    a.adaptive = r.boolean_or("adaptive", a.scheme != Scheme::load_control);
    a.bifurcation = r.choice("bifurcation") == "switch" ? BifurcationRule::switch_branch : BifurcationRule::report;
    // Fibre branches along a member settle in about three extra iterations at any step
    // size (Newton freezes them from its third iteration): a plastic zone asks for more.
    a.desired_iterations = r.integer_or("desired_iterations", model_.has_plasticity(Plasticity::distributed) ? 8 : 5);
    a.max_iterations = r.integer("max_iterations");
    if (a.max_increment > 0.0 && a.min_increment > a.max_increment)
        r.fail("min_increment", "must not exceed max_increment");
    if (a.min_increment > a.initial_increment) r.fail("min_increment", "must not exceed the first increment");
    if (r.has("max_increment") && a.max_increment < a.initial_increment)
        r.fail("max_increment", "must not be below the first increment");
    a.max_steps = r.integer("max_steps");
    a.residual_tolerance_follows_floor = !r.has("residual_tolerance");
    a.residual_tolerance = r.number_or("residual_tolerance", AnalysisSpec::default_residual_tolerance);
    a.displacement_tolerance = r.number("displacement_tolerance");
    a.allow_crossing = r.boolean("allow_crossing");
    if (r.has("target_load_factor") && r.has("target_displacement"))
        r.fail("target_displacement", "give one stop, 'target_load_factor' or 'target_displacement', not both");
    if (r.has("target_load_factor"))
        a.target_load_factor = r.number("target_load_factor"); // a load the other way: reverse the [[load]]
    if (r.has("target_displacement")) a.target_displacement = r.number("target_displacement", controlled);
    a.pattern = driven_pattern(r);
    if (r.has("control_at") || r.has("control_node")) {
        a.control = read_control(r, a.pattern);
    } else if (a.scheme == Scheme::displacement_control || a.target_displacement) {
        r.fail("", "missing 'control_at' (the point whose displacement controls or stops the analysis)");
    } else if (const auto first = std::find_if(model_.loads.begin(), model_.loads.begin() + nodal_loads_,
                                               [&](const NodalLoad& l) { return l.pattern == a.pattern; });
               first != model_.loads.begin() + nodal_loads_) {
        a.control.node = first->node; // report the first load's point
        a.control.dof = 1;
    } else if (model_.prescribed.empty() && (!model_.loads.empty() || !model_.pressures.empty())) {
        r.fail("", "missing 'control_at': a scene loaded only by [[distributed_load]]s names the point whose displacement it reports");
    }
    if (!a.target_load_factor && !a.target_displacement)
        r.fail("", "missing a stop: 'target_load_factor' or 'target_displacement'");
    for (const Support& s : model_.supports)
        if (a.scheme == Scheme::displacement_control && s.node == a.control.node && s.fixed[a.control.dof])
            r.fail("control_dof", "the controlled DOF is supported");
    for (const PrescribedDisplacement& p : model_.prescribed)
        if (a.scheme == Scheme::displacement_control && p.node == a.control.node && p.dof == a.control.dof)
            r.fail("control_dof", "the controlled DOF has a prescribed displacement");
    // Nothing to solve when every DOF is held.
    std::vector<bool> held(static_cast<std::size_t>(model_.dof_count()), false);
    for (const Support& s : model_.supports)
        for (int d = 0; d < dofs_per_node; ++d)
            if (s.fixed[d]) held[static_cast<std::size_t>(dofs_per_node * s.node + d)] = true;
    for (const PrescribedDisplacement& p : model_.prescribed)
        held[static_cast<std::size_t>(dofs_per_node * p.node + p.dof)] = true;
    if (std::all_of(held.begin(), held.end(), [](bool h) { return h; }))
        r.fail("", "every degree of freedom is supported or prescribed: nothing can move (see the [[support]] tables)");
    r.finish();
}

// [analysis] scheme = "transient": the structure moves from rest (or its initial
// velocities) at t = 0; patterns with a [[time_series]] follow it, the others act at factor 1.
void SceneBuilder::read_transient_analysis(TomlTableReader& r) {
    AnalysisSpec& a = model_.analysis;
    a.transient = read_transient(r);
    check_transient_step(r, a.transient, model_);
    a.max_iterations = r.integer("max_iterations");
    a.max_steps = std::max(r.integer("max_steps"), static_cast<int>(std::ceil(a.transient.duration / a.transient.time_step - 1e-9)) + 1);
    a.residual_tolerance_follows_floor = !r.has("residual_tolerance");
    a.residual_tolerance = r.number_or("residual_tolerance", AnalysisSpec::default_residual_tolerance);
    a.displacement_tolerance = r.number("displacement_tolerance");
    a.allow_crossing = r.boolean("allow_crossing");
    a.pattern = r.has("pattern") ? driven_pattern(r) : 0;
    if (r.has("control_at") || r.has("control_node")) {
        a.control = read_control(r, a.pattern);
    } else if (!model_.loads.empty()) {
        a.control.node = model_.loads.front().node;
    } else if (!model_.dynamics.initial_velocities.empty()) {
        a.control.node = model_.dynamics.initial_velocities.front().node;
    }
    r.finish();
}

// A controlled (and reported) DOF: 'control_at' or 'control_node', 'control_dof' (default
// "uy") and 'control_sign'. The displacement runs with the driven pattern's load on that DOF:
// by default its sign is the load's, and a sign against the load is refused.
DofRef SceneBuilder::read_control(TomlTableReader& r, int pattern) {
    DofRef c;
    c.node = node_ref(r, "control_node", "control_at");
    c.dof = dof_index(r, "control_dof", r.choice("control_dof"));
    double load_on_control = 0.0;
    for (const NodalLoad& l : model_.loads)
        if (l.node == c.node && l.pattern == pattern) load_on_control += l.value[c.dof];
    const double along_load = load_on_control < 0.0 ? -1.0 : 1.0;
    c.sign = along_load;
    if (r.has("control_sign")) {
        const double sign = r.number("control_sign");
        if (sign != 1.0 && sign != -1.0) r.fail("control_sign", "expected 1 or -1");
        if (load_on_control != 0.0 && sign != along_load)
            r.fail("control_sign", "the load on the controlled DOF points the other way: with control_sign = " +
                                       std::string(sign > 0 ? "1" : "-1") + " the structure would be pushed against it; use " +
                                       std::string(along_load > 0 ? "1" : "-1") + " (or leave it out)");
        c.sign = sign;
    }
    return c;
}

void SceneBuilder::read_report(TomlTableReader& top) {
    const toml::table* t = top.table("report");
    // Loads in more than one direction have no total an engineer would call the load:
    // then the load factor is reported, and labelled so.
    const bool parallel = model_.loads_parallel();
    infer_report_measure(model_);
    if (!t) return;
    TomlTableReader r(*t, file_, "report", scene_table("report"), units());
    if (r.has("load")) {
        const std::string measure = r.choice("load");
        if (measure == "total" && !parallel)
            r.fail("load", "the loads are not parallel, so their total has no direction: report the load factor (load = \"factor\")");
        if (measure == "factor") {
            model_.report.measure = ReportSpec::Measure::factor;
            model_.report.load_label = "load factor";
        } else if (model_.report.measure != ReportSpec::Measure::platen) {
            model_.report.measure = ReportSpec::Measure::total;
        }
    }
    model_.report.load_scale = r.number("load_scale");
    model_.report.load_label = r.string_or("load_label", model_.report.load_label);
    model_.report.displacement_label = r.string_or("displacement_label", model_.report.displacement_label);
    model_.report.exact = r.choice_or("exact", "");
    if (r.has("mirror_x")) model_.report.mirror_x = r.number("mirror_x");
    if (const toml::array* at = r.array("load_at")) {
        for (const toml::node& item : *at) {
            const std::optional<double> value = item.value<double>();
            if (!value || !std::isfinite(*value))
                r.fail("load_at", "expected a list of numbers: control displacements, in the control's units");
            model_.report.load_at.push_back(*value);
        }
        if (model_.report.load_at.size() > 100) r.fail("load_at", "expected at most 100 displacements");
    }
    for (const auto& [key, unit] : {std::pair{"length_unit", &model_.report.length_unit}, std::pair{"force_unit", &model_.report.force_unit}}) {
        *unit = r.string_or(key, *unit); // [units] names them unless [report] relabels
        if (unit->size() > 16 || unit->find_first_of("\n\r\t") != std::string::npos)
            r.fail(key, "expected a short unit name such as \"mm\" or \"kN\"");
    }
    if (model_.report.exact == "cantilever_tip_load" && !is_cantilever_with_tip_load(model_))
        r.fail("exact", "cantilever_tip_load is the closed form of a straight elastic cantilever, clamped at one end, "
                        "with one transverse load at the other and nothing else; this scene is not one");
    if (model_.report.mirror_x) {
        // A half model lies on one side of its symmetry line.
        const double x0 = *model_.report.mirror_x, tol = 1e-9 * mesh_.size_scale();
        bool left = false, right = false;
        for (const Node& n : model_.nodes) left = left || n.x < x0 - tol, right = right || n.x > x0 + tol;
        if (left && right) r.fail("mirror_x", "the structure lies on both sides of this line: a half model lies on one side");
    }
    r.finish();
}

} // namespace plastica::detail
