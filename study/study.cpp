#include "study.hpp"
#include "scene_variant.hpp"

#include "analysis/path_following.hpp"
#include "study_error.hpp"
#include "scene_reader.hpp"
#include "verification/cantilever_elastica.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace plastica {

namespace {

struct Solved {
    Curve curve;
    RunSummary summary;
    double seconds = 0.0;
    int repeats = 0;
};

Solved solve(const Model& model, double min_seconds) {
    Solved s;
    std::vector<double> times;
    double total = 0.0;
    while (times.empty() || (total < min_seconds && times.size() < 7)) {
        Curve curve;
        PathFollowing analysis(model);
        const auto t0 = std::chrono::steady_clock::now();
        RunControl curve_alone;
        curve_alone.report_sections = false;
        s.summary = analysis.run({[&](const StepResult& r) {
            curve.displacement.push_back(r.control_displacement);
            curve.load.push_back(r.load);
        }}, curve_alone);
        times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        total += times.back();
        s.curve = std::move(curve);
    }
    std::sort(times.begin(), times.end());
    s.seconds = times[times.size() / 2];
    s.repeats = static_cast<int>(times.size());
    return s;
}

// The exact load–deflection curve of the scene's closed form, sampled densely.
Curve exact_curve(const Model& model) {
    if (model.report.exact != "cantilever_tip_load")
        throw StudyError(model.source + ": no closed form; set [report] exact, or use --reference finest or a CSV file");
    double x0 = 1e300, x1 = -1e300;
    for (const Node& n : model.nodes) x0 = std::min(x0, n.x), x1 = std::max(x1, n.x);
    const double L = x1 - x0;
    const double EI = model.sections.front().E * model.sections.front().inertia;
    Curve c;
    c.displacement.push_back(0.0);
    c.load.push_back(0.0);
    for (int i = 1; i <= 400; ++i) {
        const double alpha = 12.0 * i / 400.0; // beyond PL²/EI = 10, the scene's end
        c.displacement.push_back(cantilever_tip_load(alpha).deflection * L);
        c.load.push_back(alpha * EI / (L * L) * model.report.load_scale);
    }
    return c;
}

double step_size(const std::string& parameter, double level) {
    return parameter == "increment" ? level : 1.0 / level;
}

// Least-squares slope of log(error) against log(h).
double slope(const std::vector<double>& h, const std::vector<double>& error) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (std::size_t i = 0; i < h.size(); ++i) {
        if (!(error[i] > 0) || !std::isfinite(error[i])) continue;
        const double x = std::log(h[i]), y = std::log(error[i]);
        sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
    }
    if (n < 2) return std::nan("");
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace

namespace {

// "displacements a … b" of a curve.
std::string span_text(const Curve& c) {
    std::ostringstream s;
    if (c.displacement.empty()) return "no points";
    const auto [lo, hi] = std::minmax_element(c.displacement.begin(), c.displacement.end());
    s << "displacements " << *lo + 0.0 << " … " << *hi + 0.0; // + 0.0: no "-0"
    return s.str();
}

} // namespace

StudyReport run_study(const StudyOptions& options) {
    StudyReport report;
    const Model base = read_scene(options.scene);
    const bool compared = !options.methods.empty();
    const bool extrapolated = options.reference == "extrapolated", finest_run = options.reference == "finest";
    std::optional<Curve> fixed_reference;
    if (options.reference == "exact") {
        fixed_reference = exact_curve(base);
        report.reference = "exact: " + base.report.exact;
    } else if (extrapolated) {
        report.reference = compared ? "each method's own limit, extrapolated from its three finest levels"
                                    : "the limit extrapolated from the three finest levels";
    } else if (finest_run) {
        report.reference = compared ? "each method's own finest level" : "finest level of each parameter";
    } else {
        fixed_reference = read_curve_csv(options.reference);
        report.reference = "curve " + options.reference;
    }
    // Without a method comparison, one pass with the scene's own plasticity.
    const std::vector<std::string> methods = compared ? options.methods : std::vector<std::string>{""};
    for (const Ladder& ladder : options.ladders) {
        if (ladder.levels.size() < 2) throw StudyError("--vary " + ladder.parameter + " needs at least two levels");
        std::vector<double> hs;
        for (double level : ladder.levels) hs.push_back(step_size(ladder.parameter, level));
        const std::size_t finest = static_cast<std::size_t>(std::min_element(hs.begin(), hs.end()) - hs.begin());

        std::vector<std::vector<Solved>> runs; // [method][level]
        std::vector<Curve> references;         // [method]
        for (const std::string& method : methods) {
            runs.emplace_back();
            for (double level : ladder.levels)
                runs.back().push_back(solve(scene_variant(options.scene, ladder.parameter, level, method), options.min_seconds));
            if (extrapolated && ladder.levels.size() < 3)
                throw StudyError("--vary " + ladder.parameter + ": a limit is extrapolated from three levels or more; give a third level, "
                                 "or --reference finest|exact|FILE");
            if (ladder.levels.size() >= 3) {
                std::vector<Curve> curves;
                for (const Solved& run : runs.back()) curves.push_back(run.curve);
                StudyReport::Limit limit{method, ladder.parameter, extrapolated_limit(curves, hs), {}};
                for (std::size_t k : limit.limit.used) limit.levels.push_back(ladder.levels[k]);
                report.limits.push_back(limit);
            }
            references.push_back(fixed_reference ? *fixed_reference
                                 : extrapolated   ? report.limits.back().limit.curve
                                                  : runs.back()[finest].curve);
        }
        if (report.at.empty()) {
            report.at = options.at;
            if (report.at.empty()) {
                // Quarters of the range every method's finest level shares with its reference.
                double from = -1e300, to = 1e300;
                for (std::size_t m = 0; m < methods.size(); ++m) {
                    const CurveError span = curve_error(runs[m][finest].curve, references[m], {});
                    from = std::max(from, span.from), to = std::min(to, span.to);
                }
                for (double f : {0.25, 0.5, 0.75, 1.0}) report.at.push_back(from + f * (to - from));
            }
        }
        for (std::size_t m = 0; m < methods.size(); ++m) {
            std::vector<double> level_h, errors;
            for (std::size_t i = 0; i < runs[m].size(); ++i) {
                const Solved& run = runs[m][i];
                StudyLevel l;
                l.method = methods[m];
                l.parameter = ladder.parameter;
                l.level = ladder.levels[i];
                l.seconds = run.seconds;
                l.repeats = run.repeats;
                l.steps = run.summary.steps;
                l.iterations = run.summary.iterations;
                l.status = run.summary.reason;
                l.is_reference = finest_run && i == finest;
                l.error = curve_error(run.curve, references[m], report.at);
                if (std::isnan(l.error.max)) {
                    std::ostringstream why;
                    why << ladder.parameter << " = " << l.level << ": its curve has no displacement in common with "
                        << (fixed_reference ? "the reference" : extrapolated ? "the extrapolated limit" : "the finest level") << " ("
                        << span_text(run.curve) << " against " << span_text(references[m]) << "): there is no error to measure";
                    throw StudyError(why.str());
                }
                if (!l.is_reference) {
                    level_h.push_back(hs[i]);
                    errors.push_back(l.error.max);
                }
                report.levels.push_back(l);
            }
            report.observed_order.push_back({methods[m], ladder.parameter, slope(level_h, errors)});
        }
        // How far apart the methods' limits are: the model difference no refinement removes.
        if (compared && ladder.levels.size() >= 3) {
            const auto first = report.limits.end() - static_cast<std::ptrdiff_t>(methods.size());
            for (auto limit = first; limit + 1 != report.limits.end(); ++limit)
                report.limit_gaps.push_back({ladder.parameter, limit->method, methods.back(),
                                             curve_error(limit->limit.curve, report.limits.back().limit.curve, report.at)});
        }
    }
    return report;
}

} // namespace plastica
