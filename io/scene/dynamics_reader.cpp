// [[mass]], [damping], [[time_series]], [[initial_velocity]] and the transient keys
// (io/scene/dynamics_reader.hpp); [[ground_motion]] in ground_motion_reader.cpp.
#include "dynamics_reader.hpp"

#include "scene_error.hpp"
#include "scene_schema.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

namespace {

std::vector<double> list_of_numbers(TomlTableReader& r, const std::string& key) {
    const toml::array* a = r.array(key);
    if (!a || a->empty()) r.fail(key, "expected a list of numbers");
    std::vector<double> out;
    for (const toml::node& n : *a) {
        const std::optional<double> v = n.value<double>();
        if (!v || !std::isfinite(*v)) r.fail(key, "expected a list of finite numbers");
        out.push_back(*v);
    }
    return out;
}

int pattern_named(TomlTableReader& r, const Model& model) {
    const std::string name = r.string("pattern");
    const auto known = std::find(model.patterns.begin(), model.patterns.end(), name);
    if (known == model.patterns.end()) {
        std::string names;
        for (const std::string& p : model.patterns) names += (names.empty() ? "'" : ", '") + p + "'";
        r.fail("pattern", "no load belongs to pattern '" + name + "'; the scene's patterns: " + names);
    }
    return static_cast<int>(known - model.patterns.begin());
}

void read_masses(TomlTableReader& top, const SceneContext& c, Model& model) {
    const Tables list = tables_of(top, "mass");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, c.file, indexed("mass", i), scene_table("mass"), c.units);
        NodalMass m;
        m.node = c.node_ref(r);
        m.mass = r.number("m");
        m.rotational = r.number("rotational");
        r.finish();
        model.dynamics.masses.push_back(m);
    }
}

void read_damping(TomlTableReader& top, const SceneContext& c, Model& model) {
    const toml::table* t = top.table("damping");
    if (!t) return;
    TomlTableReader r(*t, c.file, "damping", scene_table("damping"), c.units);
    DampingSpec& d = model.dynamics.damping;
    if (r.has("ratio") && (r.has("alpha_m") || r.has("beta_k")))
        r.fail("ratio", "give either 'ratio' (with 'modes') or 'alpha_m' and 'beta_k', not both");
    if (r.has("ratio")) d.ratio = r.number("ratio");
    if (const toml::array* modes = r.array("modes")) {
        if (!d.ratio) r.fail("modes", "'modes' go with 'ratio'");
        if (modes->size() != 2 || !(*modes)[0].is_integer() || !(*modes)[1].is_integer())
            r.fail("modes", "expected two mode numbers, such as [1, 3]");
        for (int k = 0; k < 2; ++k) {
            const int64_t m = *(*modes)[static_cast<std::size_t>(k)].value<int64_t>();
            if (m < 1 || m > 1000) r.fail("modes", "expected mode numbers from 1 to 1000");
            d.modes[static_cast<std::size_t>(k)] = static_cast<int>(m);
        }
        if (d.modes[0] == d.modes[1]) r.fail("modes", "expected two different modes");
    }
    d.alpha_m = r.number("alpha_m");
    d.beta_k = r.number("beta_k");
    const std::string k = r.choice("stiffness");
    d.stiffness = k == "initial" ? DampingSpec::Stiffness::initial
                : k == "tangent" ? DampingSpec::Stiffness::tangent : DampingSpec::Stiffness::committed;
    if (!d.present()) r.fail("", "expected 'ratio', or 'alpha_m' or 'beta_k' above zero");
    r.finish();
}

void read_time_series(TomlTableReader& top, const SceneContext& c, Model& model) {
    const Tables list = tables_of(top, "time_series");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, c.file, indexed("time_series", i), scene_table("time_series"), c.units);
        TimeSeriesSpec s;
        const std::string kind = r.choice("kind");
        r.choose_group(kind);
        s.pattern = pattern_named(r, model);
        for (const TimeSeriesSpec& other : model.dynamics.series)
            if (other.pattern == s.pattern) r.fail("pattern", "pattern '" + model.patterns[static_cast<std::size_t>(s.pattern)] + "' already follows a series");
        if (kind == "harmonic") {
            s.kind = TimeSeriesSpec::Kind::harmonic;
            s.amplitude = r.number("amplitude");
            s.period = r.number("period");
            s.phase = r.number("phase");
            s.start = r.number("start");
        } else if (kind == "pulse") {
            s.kind = TimeSeriesSpec::Kind::pulse;
            s.amplitude = r.number("amplitude");
            s.start = r.number("start");
            s.width = r.number("width");
            const std::string shape = r.choice("shape");
            s.shape = shape == "rectangular" ? TimeSeriesSpec::Shape::rectangular
                    : shape == "triangular" ? TimeSeriesSpec::Shape::triangular : TimeSeriesSpec::Shape::half_sine;
        } else {
            s.kind = TimeSeriesSpec::Kind::table;
            s.times = list_of_numbers(r, "times");
            s.values = list_of_numbers(r, "values");
            if (s.values.size() != s.times.size()) r.fail("values", "expected as many values as times (" + std::to_string(s.times.size()) + ")");
            for (std::size_t k = 1; k < s.times.size(); ++k)
                if (!(s.times[k] > s.times[k - 1])) r.fail("times", "expected increasing times (item " + std::to_string(k + 1) + ")");
            if (s.times.front() < 0.0) r.fail("times", "expected times from 0 on");
        }
        r.finish();
        model.dynamics.series.push_back(std::move(s));
    }
}

void read_initial_velocities(TomlTableReader& top, const SceneContext& c, Model& model) {
    const Tables list = tables_of(top, "initial_velocity");
    std::vector<bool> given(model.nodes.size(), false);
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, c.file, indexed("initial_velocity", i), scene_table("initial_velocity"), c.units);
        std::vector<int> nodes;
        if (r.has("on")) {
            if (r.has("at") || r.has("node")) r.fail("on", "give 'on' (members) or 'at'/'node' (one node), not both");
            const toml::node* on = r.node("on");
            std::vector<std::string> names;
            if (const toml::array* a = on->as_array()) {
                for (const toml::node& n : *a)
                    if (n.is_string()) names.push_back(*n.value<std::string>());
            } else if (on->is_string()) {
                names.push_back(*on->value<std::string>());
            }
            if (names.empty()) r.fail("on", "expected \"all\", a member's name or a list of names");
            std::vector<bool> taken(model.nodes.size(), false);
            for (const std::string& name : names) {
                std::vector<int> all;
                for (std::size_t e = 0; e < model.elements.size(); ++e) all.push_back(static_cast<int>(e));
                const auto m = c.members->find(name);
                if (name != "all" && m == c.members->end())
                    r.fail("on", "expected \"all\" or the name of a [[line]] or [[arc]], got '" + name + "'");
                for (int e : name == "all" ? all : m->second) {
                    taken[static_cast<std::size_t>(model.elements[static_cast<std::size_t>(e)].node_i)] = true;
                    taken[static_cast<std::size_t>(model.elements[static_cast<std::size_t>(e)].node_j)] = true;
                }
            }
            for (std::size_t n = 0; n < taken.size(); ++n)
                if (taken[n]) nodes.push_back(static_cast<int>(n));
        } else {
            nodes.push_back(c.node_ref(r));
        }
        const std::array<double, 2> v = r.has("v") ? r.point("v") : std::array<double, 2>{0.0, 0.0};
        const double spin = r.number("spin");
        const std::array<double, 2> about = r.has("about") ? r.point("about") : std::array<double, 2>{0.0, 0.0};
        if (v[0] == 0.0 && v[1] == 0.0 && spin == 0.0) r.fail("v", "expected a velocity 'v' or a 'spin' other than zero");
        for (int n : nodes) {
            if (given[static_cast<std::size_t>(n)]) r.fail("", "a node of these already has an initial velocity");
            given[static_cast<std::size_t>(n)] = true;
            const Node& p = model.nodes[static_cast<std::size_t>(n)];
            InitialVelocity iv;
            iv.node = n;
            iv.velocity = {v[0] - spin * (p.y - about[1]), v[1] + spin * (p.x - about[0])};
            iv.rotation_rate = spin;
            model.dynamics.initial_velocities.push_back(iv);
        }
        r.finish();
    }
}

} // namespace

Tables tables_of(TomlTableReader& top, const std::string& key) {
    Tables out;
    const toml::node* n = top.node(key);
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a || !a->is_array_of_tables()) top.fail(key, "expected an array of tables, written [[" + key + "]]");
    for (const toml::node& item : *a) out.emplace_back(item.as_table(), line_of(item));
    return out;
}

TransientSpec read_transient(TomlTableReader& r) {
    TransientSpec t;
    for (const char* key : {"increment", "target_load_factor", "target_displacement", "adaptive", "min_increment", "max_increment"})
        if (r.has(key)) r.fail(key, "a transient stage steps in time ('time_step', 'duration'); it has no '" + std::string(key) + "'");
    t.time_step = r.number("time_step");
    t.duration = r.number("duration");
    if (t.time_step > t.duration) r.fail("time_step", "the step is longer than the stage's 'duration'");
    if (t.duration / t.time_step > 1e7) r.fail("time_step", "more than 10⁷ steps: lengthen the step or shorten the duration");
    t.integrator = r.choice("integrator") == "hht" ? Integrator::hht : Integrator::newmark;
    t.alpha = t.integrator == Integrator::hht ? r.number("alpha") : 0.0;
    if (t.integrator == Integrator::newmark && r.has("alpha")) r.fail("alpha", "'alpha' is HHT's: set integrator = \"hht\"");
    return t;
}

void read_dynamics(TomlTableReader& top, const SceneContext& context, Model& model) {
    read_masses(top, context, model);
    read_damping(top, context, model);
    read_time_series(top, context, model);
    read_ground_motions(top, context, model);
    read_initial_velocities(top, context, model);
}

} // namespace plastica
