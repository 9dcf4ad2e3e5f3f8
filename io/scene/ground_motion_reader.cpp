// [[ground_motion]]: acceleration records (PEER AT2 or plain), their units and their time step
// against the analysis' (io/scene/dynamics_reader.hpp).
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

std::string beside_scene(const std::string& scene, const std::string& file) {
    const std::filesystem::path p(file);
    if (p.is_absolute()) return file;
    return (std::filesystem::path(scene).parent_path() / p).string();
}

} // namespace

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
        // The count as a double, checked before it becomes an int: a header may claim any number
        // of digits, and a record file of at most scene_file_limit bytes holds fewer values.
        double count = -1.0;
        if (std::regex_search(header, m, npts)) count = std::strtod(m[1].str().c_str(), nullptr);
        if (std::regex_search(header, m, dt)) record.time_step = std::strtod(m[1].str().c_str(), nullptr);
        if ((count < 0.0 || record.time_step <= 0.0) && numbers_in(header.substr(0, header.find_first_of("aAbBcCdDfFgGhHiIjJkKlLmMnNoOpPqQrRsStTuUvVwWxXyYzZ")), two) && two.size() >= 2) {
            count = two[0];
            record.time_step = two[1];
        }
        if (count > static_cast<double>(scene_file_limit) || (count >= 0.0 && count != std::floor(count)))
            throw std::runtime_error("line 4 announces NPTS = " + (std::ostringstream() << count).str() +
                                     ", not a count of values a record file can hold (at most " + std::to_string(scene_file_limit / 2) + ")");
        if (count >= 0.0) expected = static_cast<int>(count);
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

void check_transient_step(TomlTableReader& r, const TransientSpec& t, const Model& model) {
    // Without mass, M a = F − f has no answer: a run would stand still or never converge.
    bool massive = false;
    for (const ElementSpec& e : model.elements)
        massive = massive || model.sections[static_cast<std::size_t>(e.section)].mass_per_length > 0.0;
    for (const NodalMass& m : model.dynamics.masses) massive = massive || m.mass > 0.0 || m.rotational > 0.0;
    if (!massive)
        r.fail("scheme", "a transient stage needs mass, and the structure has none: give its [[material]] a 'density' "
                         "(7850 kg/m3 for steel) or put a [[mass]] with 'm' at the nodes that move");
    // A record sampled every DT is followed at every point only if the step divides DT.
    for (const GroundMotionSpec& g : model.dynamics.ground_motions) {
        const double ratio = g.time_step / t.time_step;
        if (ratio < 1.0 - 1e-9 || std::abs(ratio - std::round(ratio)) > 1e-6 * ratio)
            r.fail("time_step", "the step " + std::to_string(t.time_step) + " does not divide the record's " +
                                    std::to_string(g.time_step) + " ('" + g.source + "'): a step past a sample point would skip its peak");
    }
}

} // namespace plastica
