#include "sweep.hpp"

#include "curve_error.hpp"
#include "study_error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace plastica {

namespace fs = std::filesystem;

namespace {

std::string run_id(std::size_t index) {
    char b[16];
    std::snprintf(b, sizeof b, "r%04zu", index + 1);
    return b;
}

std::string quoted_for_shell(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
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

// A run's curve.csv: its load against its control displacement, by the header's names.
Curve read_run_curve(const std::string& file) {
    std::ifstream in(file);
    Curve c;
    std::string line;
    if (!in || !std::getline(in, line)) return c;
    const std::vector<std::string> header = split_csv_line(line);
    const auto column = [&](const char* name) {
        return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
    };
    const std::size_t d = column("control_displacement"), p = column("load");
    if (d >= header.size() || p >= header.size()) return c;
    while (std::getline(in, line)) {
        const std::vector<std::string> fields = split_csv_line(line);
        if (fields.size() != header.size()) continue;
        c.displacement.push_back(std::stod(fields[d]));
        c.load.push_back(std::stod(fields[p]));
    }
    return c;
}

std::string number(double v) {
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}

} // namespace

SweepPlan grid_plan(const std::vector<std::pair<std::string, std::vector<std::string>>>& lists, bool zip) {
    SweepPlan plan;
    if (lists.empty()) throw StudyError("a sweep needs --vary KEY=v1,v2,… or --sample");
    std::size_t count = zip ? lists.front().second.size() : 1;
    for (const auto& [key, values] : lists) {
        if (values.empty()) throw StudyError("--vary " + key + ": no values");
        if (zip && values.size() != count)
            throw StudyError("--zip needs lists of the same length (" + key + " has " + std::to_string(values.size()) + ")");
        if (!zip) count *= values.size();
        plan.keys.push_back(key);
    }
    if (count > 1'000'000) throw StudyError("the grid has " + std::to_string(count) + " runs, more than a million");
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
    SweepPlan plan;
    for (const SampledKey& k : keys) plan.keys.push_back(k.key);
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
    std::ofstream out(fs::path(dir) / "plan.csv");
    out << "id";
    for (const std::string& k : plan.keys) out << ',' << csv_field(k);
    out << '\n';
    for (std::size_t r = 0; r < plan.ids.size(); ++r) {
        out << plan.ids[r];
        for (const std::string& v : plan.values[r]) out << ',' << csv_field(v);
        out << '\n';
    }
    if (!out) throw StudyError(dir + "/plan.csv: cannot write");
}

SweepPlan read_plan(const std::string& dir) {
    std::ifstream in(fs::path(dir) / "plan.csv");
    if (!in) throw StudyError(dir + ": no plan.csv (not a sweep folder)");
    SweepPlan plan;
    std::string line;
    if (!std::getline(in, line)) throw StudyError(dir + "/plan.csv: empty");
    std::vector<std::string> header = split_csv_line(line);
    plan.keys.assign(header.begin() + 1, header.end());
    for (int number = 2; std::getline(in, line); ++number) {
        if (line.empty()) continue;
        std::vector<std::string> fields = split_csv_line(line);
        if (fields.size() != header.size())
            throw StudyError(dir + "/plan.csv:" + std::to_string(number) + ": expected " + std::to_string(header.size()) + " fields");
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
    std::ifstream in(fs::path(dir) / "runs" / id / "run.json");
    if (!in) return false;
    const auto j = nlohmann::json::parse(in, nullptr, false);
    return !j.is_discarded() && j.is_object() && j.value("status", "running") != "running";
}

void write_jobs(const std::string& dir, const std::string& program, const std::string& scene, const SweepPlan& plan,
                RunOutput output) {
    fs::create_directories(fs::path(dir) / "logs");
    std::ofstream jobs(fs::path(dir) / "jobs.txt");
    for (std::size_t r = 0; r < plan.ids.size(); ++r) {
        jobs << quoted_for_shell(program);
        for (const std::string& a : run_arguments(scene, dir, plan, r, output)) jobs << ' ' << quoted_for_shell(a);
        // Its messages where the in-process pool puts them, so merge can say why a run failed.
        jobs << " > " << quoted_for_shell((fs::absolute(dir) / "logs" / (plan.ids[r] + ".txt")).string()) << " 2>&1\n";
    }
    std::ofstream sbatch(fs::path(dir) / "sweep.sbatch");
    const std::string logs = (fs::absolute(dir) / "logs").string();
    sbatch << "#!/bin/bash\n"
           << "# A Slurm job array over jobs.txt: task N runs line N. Submit with: sbatch " << (fs::path(dir) / "sweep.sbatch").string() << "\n"
           << "#SBATCH --job-name=plastica-sweep\n"
           << "#SBATCH --array=1-" << plan.ids.size() << "\n"
           << "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n"
           << "#SBATCH --output=" << logs << "/slurm-%a.txt\n"
           << "line=$(sed -n \"${SLURM_ARRAY_TASK_ID}p\" " << quoted_for_shell(fs::absolute(fs::path(dir) / "jobs.txt").string()) << ")\n"
           << "eval \"$line\"\n";
    if (!jobs || !sbatch) throw StudyError(dir + ": cannot write jobs.txt or sweep.sbatch");
}

SweepSummary write_sweep_csv(const std::string& dir, const std::vector<double>& at) {
    const SweepPlan plan = read_plan(dir);
    SweepSummary summary;
    std::ofstream out(fs::path(dir) / "sweep.csv");
    out.precision(10);
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
        const fs::path folder = fs::path(dir) / "runs" / id;
        std::ifstream in(folder / "run.json");
        const auto j = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
        const std::string status = j.is_object() ? j.value("status", "running") : "missing";
        if (!j.is_object() || status == "running") {
            // Never silently dropped: a run that did not finish is a row that says so. A run
            // refused before it started (bad input: exit 2) left only its log.
            std::ifstream log(fs::path(dir) / "logs" / (id + ".txt"));
            std::string first;
            if (log && std::getline(log, first) && !first.empty() && status != "running") {
                ++summary.failed;
                summary.failed_ids.push_back(id);
                out << ",failed," << csv_field(first) << ",,";
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
        else if (status == "interrupted" || status == "missing") ++summary.failed, summary.failed_ids.push_back(id);
        else ++summary.stopped;
        out << ',' << status << ',' << csv_field(j.value("reason", ""));
        out << ',' << j["peak"].value("load", NAN) << ',' << j["peak"].value("control_displacement", NAN);
        const Curve curve = read_run_curve((folder / "curve.csv").string());
        for (double d : at) {
            const double p = curve.displacement.size() > 1 ? load_at(curve, d) : NAN;
            out << ',';
            if (std::isfinite(p)) out << p;
        }
        double seconds = 0.0;
        if (j.contains("seconds"))
            for (const auto& [stage, s] : j["seconds"].items()) seconds += s.get<double>();
        out << ',' << j.value("iterations", 0) << ',' << j.value("steps", 0) << ',' << seconds << '\n';
    }
    if (!out) throw StudyError(dir + "/sweep.csv: cannot write");
    return summary;
}

std::vector<SweepRunResult> read_sweep_results(const std::string& dir, const SweepPlan& plan) {
    std::vector<SweepRunResult> results;
    for (std::size_t r = 0; r < plan.ids.size(); ++r) {
        SweepRunResult x;
        x.id = plan.ids[r];
        x.values = plan.values[r];
        const fs::path folder = fs::path(dir) / "runs" / x.id;
        std::ifstream in(folder / "run.json");
        const auto j = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
        x.finished = j.is_object() && j.value("status", "running") != "running" && j.contains("peak");
        if (x.finished) {
            x.scene_file = j.value("scene_file", "");
            x.peak_load = j["peak"].value("load", NAN);
            const Curve c = read_run_curve((folder / "curve.csv").string());
            x.displacement = c.displacement;
            x.load = c.load;
        }
        results.push_back(std::move(x));
    }
    return results;
}

} // namespace plastica
