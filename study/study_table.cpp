#include "study_table.hpp"

#include "study_error.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <sstream>

namespace plastica {

namespace {

std::string percent(double relative) {
    char b[32];
    if (std::isnan(relative)) return "-";
    std::snprintf(b, sizeof b, "%.3g %%", 100.0 * relative);
    return b;
}

std::string formatted(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string formatted(const char* format, ...) {
    char b[256];
    va_list args;
    va_start(args, format);
    std::vsnprintf(b, sizeof b, format, args);
    va_end(args);
    return b;
}

} // namespace

void write_study_csv(std::ostream& out, const StudyReport& report) {
    out.precision(10);
    out << "method,parameter,level,seconds,repeats,steps,iterations,status,is_reference,max_error,rms_error";
    for (double d : report.at) out << ",error_at_" << d;
    out << "\n";
    for (const StudyLevel& l : report.levels) {
        out << l.method << ',' << l.parameter << ',' << l.level << ',' << l.seconds << ',' << l.repeats << ',' << l.steps << ','
            << l.iterations << ",\"" << l.status << "\"," << l.is_reference << ',' << l.error.max << ',' << l.error.rms;
        for (double e : l.error.at) out << ',' << e;
        out << "\n";
    }
}

void print_study_table(std::ostream& out, const std::string& scene, const StudyReport& report, bool methods_compared) {
    out << scene << ": errors against " << report.reference << " (relative to the peak load)\n";
    if (methods_compared) out << formatted("%-12s ", "plasticity");
    out << formatted("%-10s %8s %10s %6s %7s %10s %10s", "parameter", "level", "seconds", "steps", "iters", "max", "rms");
    for (double d : report.at) out << formatted("   at %-6g", d);
    out << "\n";
    for (const StudyLevel& l : report.levels) {
        if (methods_compared) out << formatted("%-12s ", l.method.c_str());
        out << formatted("%-10s %8g %10.4g %6d %7d %10s %10s", l.parameter.c_str(), l.level, l.seconds, l.steps, l.iterations,
                         l.is_reference ? "reference" : percent(l.error.max).c_str(),
                         l.is_reference ? "" : percent(l.error.rms).c_str());
        for (double e : l.error.at) out << formatted("   %-9s", l.is_reference ? "" : percent(e).c_str());
        out << "\n";
    }
    for (const StudyReport::Order& o : report.observed_order)
        out << formatted("observed order of convergence in %s%s: %.2f\n", o.parameter.c_str(),
                         o.method.empty() ? "" : (" with " + o.method).c_str(), o.order);
    for (const StudyReport::Limit& l : report.limits) out << limit_text(l) << "\n";
    for (const StudyReport::LimitGap& g : report.limit_gaps) {
        out << formatted("limits apart in %s: %s against %s: max %s", g.parameter.c_str(), g.method.c_str(), g.against.c_str(),
                         percent(g.gap.max).c_str());
        for (std::size_t i = 0; i < report.at.size() && i < g.gap.at.size(); ++i)
            out << formatted(", %s at %g", percent(g.gap.at[i]).c_str(), report.at[i]);
        out << "\n";
    }
}

std::string limit_text(const StudyReport::Limit& l) {
    std::ostringstream s;
    s << "limit" << (l.method.empty() ? "" : " of " + l.method) << " in " << l.parameter << ": ";
    const auto& levels = l.levels;
    if (l.limit.extrapolated)
        s << formatted("extrapolated from %s = %g, %g, %g at observed order %.2f", l.parameter.c_str(), levels[0], levels[1], levels[2],
                       l.limit.order);
    else
        s << formatted("the finest level, %s = %g, not extrapolated: its curves change by %s (RMS, of the peak) from %g to %g and "
                       "by %s from %g to %g, %s",
                       l.parameter.c_str(), levels[2], percent(l.limit.change[0]).c_str(), levels[0], levels[1],
                       percent(l.limit.change[1]).c_str(), levels[1], levels[2],
                       std::isnan(l.limit.order) ? "which does not shrink"
                                                 : formatted("an observed order of %.2f, below %.1f", l.limit.order, minimum_order).c_str());
    return s.str();
}

void write_limits_csv(std::ostream& out, const StudyReport& report) {
    out.precision(12);
    out << "method,parameter,extrapolated,order,displacement,load\n";
    for (const StudyReport::Limit& l : report.limits)
        for (std::size_t i = 0; i < l.limit.curve.displacement.size(); ++i)
            out << l.method << ',' << l.parameter << ',' << l.limit.extrapolated << ',' << l.limit.order << ','
                << l.limit.curve.displacement[i] << ',' << l.limit.curve.load[i] << "\n";
}

std::vector<double> parse_numbers(const std::string& text, const std::string& what) {
    std::vector<double> values;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        std::size_t used = 0;
        try {
            values.push_back(std::stod(item, &used));
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != item.size() || !(values.empty() || std::isfinite(values.back())))
            throw StudyError(what + ": '" + item + "' is not a number");
    }
    return values;
}

void add_variation(StudyOptions& options, const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos) throw StudyError("--vary takes NAME=v1,v2,… (got '" + text + "')");
    const std::string name = text.substr(0, eq), values = text.substr(eq + 1);
    if (name == "plasticity") {
        std::stringstream in(values);
        for (std::string method; std::getline(in, method, ',');) {
            if (method != "hinges" && method != "distributed" && method != "force_based")
                throw StudyError("--vary plasticity: expected hinges, distributed or force_based, got '" + method + "'");
            options.methods.push_back(method);
        }
        if (options.methods.size() < 2) throw StudyError("--vary plasticity needs two methods, e.g. plasticity=hinges,distributed");
        return;
    }
    Ladder l{name, parse_numbers(values, "--vary " + name)};
    for (double v : l.levels)
        if (!(v > 0)) throw StudyError("--vary " + l.parameter + ": levels must be positive");
    options.ladders.push_back(l);
}

} // namespace plastica
