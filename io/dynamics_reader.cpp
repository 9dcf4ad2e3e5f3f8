#include "dynamics_reader.hpp"

#include "bounded_file.hpp"
#include "scene_error.hpp"
#include "scene_schema.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace plastica {

namespace {

using Tables = std::vector<std::pair<const toml::table*, int>>;

Tables tables_of(TomlTableReader& top, const std::string& key) {
    Tables out;
    const toml::node* n = top.node(key);
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a || !a->is_array_of_tables()) top.fail(key, "expected an array of tables, written [[" + key + "]]");
    for (const toml::node& item : *a) out.emplace_back(item.as_table(), line_of(item));
    return out;
}

std::string indexed(const std::string& key, std::size_t i) { return key + "[" + std::to_string(i + 1) + "]"; }

// Numbers separated by blanks or commas; false if a token is not one.
bool numbers_in(const std::string& line, std::vector<double>& out) {
    std::string text = line;
    std::replace(text.begin(), text.end(), ',', ' ');
    std::istringstream in(text);
    std::string token;
    while (in >> token) {
        char* end = nullptr;
        const double v = std::strtod(token.c_str(), &end);
        if (end != token.c_str() + token.size() || !std::isfinite(v)) return false;
        out.push_back(v);
    }
    return true;
}

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

std::string beside_scene(const std::string& scene, const std::string& file) {
    const std::filesystem::path p(file);
    if (p.is_absolute()) return file;
    return (std::filesystem::path(scene).parent_path() / p).string();
}

void read_ground_motions(TomlTableReader& top, const SceneContext& c, Model& model) {
    const Tables list = tables_of(top, "ground_motion");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, c.file, indexed("ground_motion", i), scene_table("ground_motion"), c.units);
        GroundMotionSpec g;
        const std::string file = r.string("file");
        g.source = beside_scene(c.file, file);
        AccelerationRecord record;
        try {
            record = parse_acceleration_record(read_bounded_file(g.source, scene_file_limit));
        } catch (const FileReadError& e) {
            r.fail("file", std::string("cannot read the record: ") + e.what());
        } catch (const std::runtime_error& e) {
            r.fail("file", "'" + file + "' is not an acceleration record: " + e.what());
        }
        if (record.values.empty()) r.fail("file", "'" + file + "' holds no accelerations");
        if (r.has("time_step")) {
            g.time_step = r.number("time_step");
            if (record.time_step > 0.0 && std::abs(g.time_step - record.time_step) > 1e-9 * record.time_step)
                r.fail("time_step", "the record's header says DT = " + std::to_string(record.time_step));
        } else if (record.time_step > 0.0) {
            g.time_step = record.time_step;
        } else {
            r.fail("", "missing 'time_step': '" + file + "' has no AT2 header giving DT");
        }
        g.direction = r.choice("direction") == "y" ? 1 : 0;
        double unit = 0.0;
        const toml::node* units = r.node("units");
        if (!units || (units->is_string() && *units->value<std::string>() == "g")) {
            if (!c.units) r.fail("units", "a record in g needs the scene's [units] (or give 'units' as the record's acceleration in the scene's units)");
            unit = c.units->to_scene("9.80665 m/s2", dimension::acceleration);
        } else if (units->is_string()) {
            if (!c.units) r.fail("units", "an acceleration with a unit needs the scene's [units]");
            try {
                unit = c.units->to_scene(*units->value<std::string>(), dimension::acceleration);
            } catch (const UnitError& e) {
                r.fail("units", e.what());
            }
        } else if (const std::optional<double> v = units->value<double>(); v && *v > 0.0 && std::isfinite(*v)) {
            unit = *v;
        } else {
            r.fail("units", "expected \"g\", an acceleration such as \"1 m/s2\", or a positive number");
        }
        const double scale = r.number("scale") * unit;
        for (double& a : record.values) a *= scale;
        g.acceleration = std::move(record.values);
        for (const GroundMotionSpec& other : model.dynamics.ground_motions)
            if (other.direction == g.direction) r.fail("direction", "a record already moves the base in this direction");
        r.finish();
        model.dynamics.ground_motions.push_back(std::move(g));
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

AccelerationRecord parse_acceleration_record(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    AccelerationRecord record;
    std::vector<double> first;
    std::size_t from = 0;
    const bool plain = !lines.empty() && numbers_in(lines[0], first);
    int expected = -1;
    if (!plain) {
        if (lines.size() < 4) throw std::runtime_error("no numbers on line 1, and too short for a PEER AT2 header (four lines)");
        const std::string& header = lines[3];
        static const std::regex npts(R"(NPTS\s*=\s*([0-9]+))", std::regex::icase);
        static const std::regex dt(R"(DT\s*=\s*([0-9.eE+-]+))", std::regex::icase);
        std::smatch m;
        std::vector<double> two;
        if (std::regex_search(header, m, npts)) expected = std::stoi(m[1].str());
        if (std::regex_search(header, m, dt)) record.time_step = std::strtod(m[1].str().c_str(), nullptr);
        if ((expected < 0 || record.time_step <= 0.0) && numbers_in(header.substr(0, header.find_first_of("aAbBcCdDfFgGhHiIjJkKlLmMnNoOpPqQrRsStTuUvVwWxXyYzZ")), two) && two.size() >= 2) {
            expected = static_cast<int>(two[0]);
            record.time_step = two[1];
        }
        if (expected < 0 || !(record.time_step > 0.0) || !std::isfinite(record.time_step))
            throw std::runtime_error("line 4 gives no 'NPTS= n, DT= dt' (a PEER AT2 header)");
        from = 4;
    }
    for (std::size_t k = from; k < lines.size(); ++k)
        if (!numbers_in(lines[k], record.values)) throw std::runtime_error("line " + std::to_string(k + 1) + " holds something other than numbers");
    if (expected >= 0 && static_cast<int>(record.values.size()) != expected)
        throw std::runtime_error("the header announces NPTS = " + std::to_string(expected) + " values, the file holds " +
                                 std::to_string(record.values.size()));
    return record;
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

void check_transient_step(TomlTableReader& r, const TransientSpec& t, const Model& model) {
    // A record sampled every DT is followed at every point only if the step divides DT.
    for (const GroundMotionSpec& g : model.dynamics.ground_motions) {
        const double ratio = g.time_step / t.time_step;
        if (ratio < 1.0 - 1e-9 || std::abs(ratio - std::round(ratio)) > 1e-6 * ratio)
            r.fail("time_step", "the step " + std::to_string(t.time_step) + " does not divide the record's " +
                                    std::to_string(g.time_step) + " ('" + g.source + "'): a step past a sample point would skip its peak");
    }
}

void read_dynamics(TomlTableReader& top, const SceneContext& context, Model& model) {
    read_masses(top, context, model);
    read_damping(top, context, model);
    read_time_series(top, context, model);
    read_ground_motions(top, context, model);
    read_initial_velocities(top, context, model);
}

} // namespace plastica
