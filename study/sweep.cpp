#include "sweep.hpp"

#include "curve_error.hpp"
#include "study_error.hpp"

#include "atomic_file.hpp"
#include "bounded_file.hpp"
#include "safe_names.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <set>
#include <sstream>

namespace plastica {

namespace fs = std::filesystem;

namespace {

std::string run_id(std::size_t index) {
    char b[16];
    std::snprintf(b, sizeof b, "r%04zu", index + 1);
    return b;
}


std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::vector<std::string> split_csv_line(const std::string& line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') fields.back() += '"', ++i;
            else if (c == '"') quoted = false;
            else fields.back() += c;
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields.emplace_back();
        } else {
            fields.back() += c;
        }
    }
    return fields;
}

// A number of a CSV cell, or nothing: a cell from someone else's folder may hold anything.
std::optional<double> cell_number(const std::string& text) {
    if (text.empty()) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size()) return std::nullopt;
    return v;
}

// A run's curve.csv: its load against its control displacement, by the header's names; read only
// inside the sweep folder, rows that are not two numbers passed over.
Curve read_run_curve(const std::string& dir, const std::string& id) {
    Curve c;
    const std::string relative = "runs/" + id + "/curve.csv";
    if (!is_file_inside(dir, relative)) return c;
    std::istringstream in(read_file_inside(dir, relative, result_file_limit));
    std::string line;
    if (!std::getline(in, line)) return c;
    const std::vector<std::string> header = split_csv_line(line);
    const auto column = [&](const char* name) {
        return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
    };
    const std::size_t d = column("control_displacement"), p = column("load");
    if (d >= header.size() || p >= header.size()) return c;
    while (std::getline(in, line)) {
        const std::vector<std::string> fields = split_csv_line(line);
        if (fields.size() != header.size()) continue;
        const std::optional<double> x = cell_number(fields[d]), y = cell_number(fields[p]);
        if (!x || !y) continue;
        c.displacement.push_back(*x);
        c.load.push_back(*y);
    }
    return c;
}

// A run's run.json, or null where there is none or it is not JSON.
nlohmann::json read_run_json(const std::string& dir, const std::string& id) {
    const std::string relative = "runs/" + id + "/run.json";
    if (!is_file_inside(dir, relative)) return nullptr;
    const auto j = nlohmann::json::parse(read_file_inside(dir, relative, result_file_limit), nullptr, false);
    return j.is_discarded() ? nlohmann::json() : j;
}

// What sweep.csv takes of a run.json, each value checked for its type: a folder from elsewhere
// may hold anything, and a wrong type is a failed run, not a crash.
struct RunRecord {
    std::string status = "running", reason, scene_file;
    double peak_load = NAN, peak_displacement = NAN, seconds = 0.0;
    long long iterations = 0, steps = 0;
    bool has_peak = false;
};

std::optional<RunRecord> run_record(const nlohmann::json& j, std::string& problem) {
    RunRecord r;
    const auto text = [&](const char* key, std::string& into) {
        if (!j.contains(key)) return true;
        if (!j[key].is_string()) return problem = std::string("'") + key + "' is not a text", false;
        into = j[key].get<std::string>();
        return true;
    };
    const auto whole = [&](const char* key, long long& into) {
        if (!j.contains(key)) return true;
        if (!j[key].is_number_integer()) return problem = std::string("'") + key + "' is not a whole number", false;
        into = j[key].get<long long>();
        return true;
    };
    if (!text("status", r.status) || !text("reason", r.reason) || !text("scene_file", r.scene_file) ||
        !whole("iterations", r.iterations) || !whole("steps", r.steps))
        return std::nullopt;
    if (j.contains("peak")) {
        const nlohmann::json& peak = j["peak"];
        if (!peak.is_object() || !peak.value("load", nlohmann::json(NAN)).is_number() ||
            !peak.value("control_displacement", nlohmann::json(NAN)).is_number())
            return problem = "'peak' is not an object of numbers", std::nullopt;
        r.has_peak = true;
        // A double default: NAN alone is a float, and value() returns its default's type.
        r.peak_load = peak.value("load", static_cast<double>(NAN));
        r.peak_displacement = peak.value("control_displacement", static_cast<double>(NAN));
    }
    if (j.contains("seconds")) {
        if (!j["seconds"].is_object()) return problem = "'seconds' is not an object", std::nullopt;
        for (const auto& [stage, seconds] : j["seconds"].items()) {
            if (!seconds.is_number()) return problem = "'seconds." + stage + "' is not a number", std::nullopt;
            r.seconds += seconds.get<double>();
        }
    }
    return r;
}

// The shortest text that reads back as the same double: the precision the value carries (run.json
// writes its numbers so), no more and no less.
std::string shortest(double v) {
    if (std::isnan(v)) return "nan";
    char text[32];
    return std::string(text, std::to_chars(text, text + sizeof text, v).ptr);
}

std::string number(double v) {
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}

// A key or value goes into a command line of jobs.txt and a Slurm script: one line, one argument.
void check_plan_text(const std::string& where, const std::string& text) {
    if (has_control_character(text))
        throw StudyError(where + ": a value may not hold a newline or another control character (each run is one line of jobs.txt)");
}

} // namespace

std::vector<std::string> values_to_check(const SweepPlan& plan, std::size_t k, bool sampled) {
    std::vector<std::string> values;
    std::set<std::string> seen;
    for (const std::vector<std::string>& run : plan.values)
        if (seen.insert(run[k]).second) values.push_back(run[k]);
    if (!sampled || values.size() <= 2) return values;
    const auto number = [](const std::string& v) { return std::strtod(v.c_str(), nullptr); };
    const auto [low, high] = std::minmax_element(values.begin(), values.end(),
                                                 [&](const std::string& a, const std::string& b) { return number(a) < number(b); });
    return {*low, *high};
}

std::string quoted_for_shell(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

SweepPlan grid_plan(const std::vector<std::pair<std::string, std::vector<std::string>>>& lists, bool zip) {
    SweepPlan plan;
    if (lists.empty()) throw StudyError("a sweep needs --vary KEY=v1,v2,… or --sample");
    if (lists.size() > max_sweep_keys)
        throw StudyError("a sweep varies at most " + std::to_string(max_sweep_keys) + " keys, not " + std::to_string(lists.size()));
    std::size_t count = zip ? lists.front().second.size() : 1;
    for (const auto& [key, values] : lists) {
        if (values.empty()) throw StudyError("--vary " + key + ": no values");
        check_plan_text("--vary " + key, key);
        for (const std::string& v : values) check_plan_text("--vary " + key, v);
        if (zip && values.size() != count)
            throw StudyError("--zip needs lists of the same length (" + key + " has " + std::to_string(values.size()) + ")");
        // Checked before multiplying: a product of lists must not wrap round to a small count.
        if (!zip && count > max_sweep_runs / values.size())
            throw StudyError("the grid has more than " + std::to_string(max_sweep_runs) + " runs (the lists' lengths multiply)");
        if (!zip) count *= values.size();
        plan.keys.push_back(key);
    }
    if (count > max_sweep_runs) throw StudyError("the grid has " + std::to_string(count) + " runs, more than a million");
    for (std::size_t r = 0; r < count; ++r) {
        std::vector<std::string> row;
        std::size_t rest = r;
        // The first key varies slowest: the index in mixed radix, most significant first.
        std::size_t stride = count;
        for (const auto& [key, values] : lists) {
            if (zip) {
                row.push_back(values[r]);
                continue;
            }
            stride /= values.size();
            row.push_back(values[rest / stride]);
            rest %= stride;
        }
        plan.ids.push_back(run_id(r));
        plan.values.push_back(row);
    }
    return plan;
}

SampledKey parse_sample(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0) throw StudyError("--sample takes KEY=normal:μ:σ, lognormal:μ:σ or uniform:a:b (got '" + text + "')");
    SampledKey s;
    s.key = text.substr(0, eq);
    std::stringstream in(text.substr(eq + 1));
    std::vector<std::string> parts;
    for (std::string p; std::getline(in, p, ':');) parts.push_back(p);
    if (parts.size() != 3 || (parts[0] != "normal" && parts[0] != "lognormal" && parts[0] != "uniform"))
        throw StudyError("--sample " + s.key + ": expected normal:μ:σ, lognormal:μ:σ or uniform:a:b");
    s.law = parts[0];
    try {
        s.a = std::stod(parts[1]);
        s.b = std::stod(parts[2]);
    } catch (const std::exception&) {
        throw StudyError("--sample " + s.key + ": '" + parts[1] + "' and '" + parts[2] + "' must be numbers");
    }
    if (s.law != "uniform" && !(s.b > 0.0)) throw StudyError("--sample " + s.key + ": σ must be positive");
    if (s.law == "uniform" && !(s.b > s.a)) throw StudyError("--sample " + s.key + ": expected a < b");
    return s;
}

SweepPlan sample_plan(const std::vector<SampledKey>& keys, int runs, std::uint64_t seed) {
    if (runs < 1 || runs > 1'000'000) throw StudyError("--samples takes 1 to 1 000 000 runs");
    if (keys.size() > max_sweep_keys) throw StudyError("a sweep samples at most " + std::to_string(max_sweep_keys) + " keys");
    SweepPlan plan;
    for (const SampledKey& k : keys) check_plan_text("--sample " + k.key, k.key), plan.keys.push_back(k.key);
    // One generator per key, seeded from the sweep's seed and the key's position, so adding a
    // key leaves the values of the others unchanged.
    std::vector<std::mt19937_64> generators;
    for (std::size_t k = 0; k < keys.size(); ++k) generators.emplace_back(seed * 1000003u + k);
    for (int r = 0; r < runs; ++r) {
        std::vector<std::string> row;
        for (std::size_t k = 0; k < keys.size(); ++k) {
            // Inverse transform of one uniform draw (the standard distributions' algorithms
            // are not fixed by the C++ standard; this is, so a seed means the same values anywhere).
            const double u = (static_cast<double>(generators[k]() >> 11) + 0.5) * 0x1.0p-53;
            const SampledKey& s = keys[k];
            double v;
            if (s.law == "uniform") {
                v = s.a + u * (s.b - s.a);
            } else {
                // Φ⁻¹(u) by the erfc relation and Newton on erfc (Acklam-free, exact to 1e-15).
                double z = 0.0;
                for (int it = 0; it < 60; ++it) {
                    const double f = 0.5 * std::erfc(-z / std::sqrt(2.0)) - u;
                    const double density = std::exp(-0.5 * z * z) / std::sqrt(2.0 * M_PI);
                    const double step = f / density;
                    z -= std::clamp(step, -2.0, 2.0);
                    if (std::abs(step) < 1e-14) break;
                }
                v = s.a + s.b * z;
                if (s.law == "lognormal") v = std::exp(v);
            }
            row.push_back(number(v));
        }
        plan.ids.push_back(run_id(static_cast<std::size_t>(r)));
        plan.values.push_back(row);
    }
    return plan;
}

void write_plan(const std::string& dir, const SweepPlan& plan) {
    fs::create_directories(dir);
    std::ostringstream out;
    out << "id";
    for (const std::string& k : plan.keys) out << ',' << csv_field(k);
    out << '\n';
    for (std::size_t r = 0; r < plan.ids.size(); ++r) {
        out << plan.ids[r];
        for (const std::string& v : plan.values[r]) out << ',' << csv_field(v);
        out << '\n';
    }
    write_file_atomically((fs::path(dir) / "plan.csv").string(), out.str());
}

SweepPlan read_plan(const std::string& dir) {
    if (!is_file_inside(dir, "plan.csv")) throw StudyError(dir + ": no plan.csv (not a sweep folder)");
    std::istringstream in;
    try {
        in.str(read_file_inside(dir, "plan.csv", result_file_limit));
    } catch (const FileReadError& e) {
        throw StudyError(e.what());
    }
    SweepPlan plan;
    std::string line;
    if (!std::getline(in, line)) throw StudyError(dir + "/plan.csv: empty");
    std::vector<std::string> header = split_csv_line(line);
    // A plan from elsewhere is held to what a sweep writes: its ids name run folders, and each
    // key is a chart.
    if (header.size() < 2 || header.size() > max_sweep_keys + 1)
        throw StudyError(dir + "/plan.csv:1: expected an id and 1 to " + std::to_string(max_sweep_keys) + " keys, found " +
                         std::to_string(header.size()) + " columns");
    plan.keys.assign(header.begin() + 1, header.end());
    for (const std::string& key : plan.keys) check_plan_text(dir + "/plan.csv:1", key);
    for (int number = 2; std::getline(in, line); ++number) {
        if (line.empty()) continue;
        std::vector<std::string> fields = split_csv_line(line);
        const std::string where = dir + "/plan.csv:" + std::to_string(number);
        if (fields.size() != header.size())
            throw StudyError(where + ": expected " + std::to_string(header.size()) + " fields");
        if (!is_plain_name(fields.front()))
            throw StudyError(where + ": the id '" + fields.front() + "' is not a plain name (it names the run's folder)");
        for (const std::string& v : fields) check_plan_text(where, v);
        if (plan.ids.size() == max_sweep_runs) throw StudyError(where + ": more than a million runs");
        plan.ids.push_back(fields.front());
        plan.values.emplace_back(fields.begin() + 1, fields.end());
    }
    return plan;
}

RunOutput parse_run_output(const std::string& text) {
    if (text == "curves") return RunOutput::curves;
    if (text == "series") return RunOutput::series;
    if (text == "pictures") return RunOutput::pictures;
    throw StudyError("--run-output takes curves, series or pictures, got '" + text + "'");
}

std::vector<std::string> run_arguments(const std::string& scene, const std::string& dir, const SweepPlan& plan, std::size_t run,
                                       RunOutput output) {
    std::vector<std::string> args{"run", scene};
    for (std::size_t k = 0; k < plan.keys.size(); ++k) {
        args.push_back("--set");
        args.push_back(plan.keys[k] + "=" + plan.values[run][k]);
    }
    if (output == RunOutput::curves) args.push_back("--curves-only");
    if (output == RunOutput::series) args.push_back("--no-render");
    for (const char* a : {"-q", "--force", "-o"}) args.push_back(a);
    args.push_back((fs::path(dir) / "runs" / plan.ids[run]).string());
    return args;
}

bool run_finished(const std::string& dir, const std::string& id) {
    const nlohmann::json j = read_run_json(dir, id);
    std::string problem;
    const std::optional<RunRecord> r = j.is_object() ? run_record(j, problem) : std::nullopt;
    return r && r->status != "running";
}

void write_jobs(const std::string& dir, const std::string& program, const std::string& scene, const SweepPlan& plan,
                RunOutput output) {
    // Each path is quoted; one with a newline would still break a line of either file apart.
    for (const auto& [what, path] : {std::pair{"the output folder", fs::absolute(dir).string()}, std::pair{"the program", program},
                                     std::pair{"the scene", scene}})
        if (has_control_character(path) || path.find('"') != std::string::npos)
            throw StudyError(std::string(what) + " '" + path + "' holds a control character or '\"': it cannot go into jobs.txt and sweep.sbatch");
    for (std::size_t r = 0; r < plan.ids.size(); ++r) {
        for (const std::string& v : plan.values[r]) check_plan_text("run " + plan.ids[r], v);
        if (!is_plain_name(plan.ids[r])) throw StudyError("run id '" + plan.ids[r] + "' is not a plain name");
    }
    fs::create_directories(fs::path(dir) / "logs");
    std::ostringstream jobs;
    for (std::size_t r = 0; r < plan.ids.size(); ++r) {
        jobs << quoted_for_shell(program);
        for (const std::string& a : run_arguments(scene, dir, plan, r, output)) jobs << ' ' << quoted_for_shell(a);
        // Its messages where the in-process pool puts them, so merge can say why a run failed.
        jobs << " > " << quoted_for_shell((fs::absolute(dir) / "logs" / (plan.ids[r] + ".txt")).string()) << " 2>&1\n";
    }
    std::ostringstream sbatch;
    const std::string logs = (fs::absolute(dir) / "logs").string();
    sbatch << "#!/bin/bash\n"
           << "# A Slurm job array over jobs.txt: task N runs line N. Submit with: sbatch "
           << quoted_for_shell((fs::path(dir) / "sweep.sbatch").string()) << "\n"
           << "#SBATCH --job-name=plastica-sweep\n"
           << "#SBATCH --array=1-" << plan.ids.size() << "\n"
           << "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n"
           << "#SBATCH --output=\"" << logs << "/slurm-%a.txt\"\n"
           << "line=$(sed -n \"${SLURM_ARRAY_TASK_ID}p\" " << quoted_for_shell(fs::absolute(fs::path(dir) / "jobs.txt").string()) << ")\n"
           << "eval \"$line\"\n";
    write_file_atomically((fs::path(dir) / "jobs.txt").string(), jobs.str());
    write_file_atomically((fs::path(dir) / "sweep.sbatch").string(), sbatch.str());
}

SweepSummary write_sweep_csv(const std::string& dir, const std::vector<double>& at) {
    const SweepPlan plan = read_plan(dir);
    SweepSummary summary;
    std::ostringstream out;
    out << "id";
    for (const std::string& k : plan.keys) out << ',' << csv_field(k);
    out << ",status,reason,peak_load,peak_displacement";
    for (double d : at) out << ",load_at_" << number(d);
    out << ",iterations,steps,seconds\n";
    for (std::size_t r = 0; r < plan.ids.size(); ++r) {
        ++summary.runs;
        const std::string& id = plan.ids[r];
        out << id;
        for (const std::string& v : plan.values[r]) out << ',' << csv_field(v);
        const nlohmann::json j = read_run_json(dir, id);
        std::string problem;
        const std::optional<RunRecord> record = j.is_object() ? run_record(j, problem) : std::nullopt;
        const std::string status = !j.is_object() ? "missing" : record ? record->status : "malformed";
        if (status == "malformed") {
            ++summary.failed;
            summary.failed_ids.push_back(id);
            out << ",failed," << csv_field("run.json: " + problem) << ",,";
            for (std::size_t k = 0; k < at.size(); ++k) out << ',';
            out << ",,,\n";
            continue;
        }
        if (!j.is_object() || status == "running") {
            // Never silently dropped: a run that did not finish is a row that says so. A run
            // refused before it started (bad input: exit 2) left only its log.
            const std::string log_name = "logs/" + id + ".txt";
            std::istringstream log(is_file_inside(dir, log_name) ? read_file_inside(dir, log_name, result_file_limit) : "");
            std::string first;
            if (std::getline(log, first) && !first.empty() && status != "running") {
                ++summary.failed;
                summary.failed_ids.push_back(id);
                out << ",failed," << csv_field(first.substr(0, 1000)) << ",,";
                for (std::size_t k = 0; k < at.size(); ++k) out << ',';
                out << ",,,\n";
                continue;
            }
            ++summary.missing;
            summary.missing_ids.push_back(id);
            out << ",missing," << csv_field(status == "running" ? "started, did not finish" : "not run") << ",,";
            for (std::size_t k = 0; k < at.size(); ++k) out << ',';
            out << ",,,\n";
            continue;
        }
        if (status == "completed") ++summary.completed;
        else if (status == "interrupted") ++summary.failed, summary.failed_ids.push_back(id);
        else ++summary.stopped;
        out << ',' << csv_field(status) << ',' << csv_field(record->reason);
        out << ',' << shortest(record->peak_load) << ',' << shortest(record->peak_displacement);
        const Curve curve = read_run_curve(dir, id);
        for (double d : at) {
            const double p = curve.displacement.size() > 1 ? load_at(curve, d) : NAN;
            out << ',';
            if (std::isfinite(p)) out << shortest(p);
        }
        out << ',' << record->iterations << ',' << record->steps << ',' << shortest(record->seconds) << '\n';
    }
    write_file_atomically((fs::path(dir) / "sweep.csv").string(), out.str());
    return summary;
}

std::vector<SweepRunResult> read_sweep_results(const std::string& dir, const SweepPlan& plan) {
    std::vector<SweepRunResult> results;
    for (std::size_t r = 0; r < plan.ids.size(); ++r) {
        SweepRunResult x;
        x.id = plan.ids[r];
        x.values = plan.values[r];
        const nlohmann::json j = read_run_json(dir, x.id);
        std::string problem;
        const std::optional<RunRecord> record = j.is_object() ? run_record(j, problem) : std::nullopt;
        x.finished = record && record->status != "running" && record->has_peak;
        if (x.finished) {
            x.scene_file = record->scene_file;
            x.peak_load = record->peak_load;
            const Curve c = read_run_curve(dir, x.id);
            x.displacement = c.displacement;
            x.load = c.load;
        }
        results.push_back(std::move(x));
    }
    return results;
}

} // namespace plastica
