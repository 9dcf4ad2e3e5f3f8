#include "run_report.hpp"

#include "atomic_file.hpp"

#include <sstream>

namespace plastica {

namespace {
std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n') { out += "\\n"; continue; }
        out += c;
    }
    return out + "\"";
}
} // namespace

std::string to_json(const RunReport& r) {
    std::ostringstream j;
    j.precision(10);
    j << "{\n  \"program\": \"plastica\",\n  \"version\": \"" << PLASTICA_VERSION << "\",\n";
    j << "  \"scene\": " << quoted(r.model->name) << ",\n  \"scene_file\": " << quoted(r.scene_file) << ",\n";
    j << "  \"nodes\": " << r.model->nodes.size() << ",\n  \"elements\": " << r.model->elements.size()
      << ",\n  \"springs\": " << r.model->springs.size() << ",\n";
    j << "  \"inelastic\": " << (r.model->inelastic() ? "true" : "false") << ",\n";
    j << "  \"status\": " << quoted(to_string(r.summary.status)) << ",\n  \"reason\": " << quoted(r.summary.reason) << ",\n";
    j << "  \"steps\": " << r.summary.steps << ",\n  \"iterations\": " << r.summary.iterations
      << ",\n  \"cut_steps\": " << r.summary.cut_steps << ",\n";
    // Which rule accepted the steps: the residual within its tolerance, or round-off
    // stagnation within ten times it (never more).
    j << "  \"accepted_by\": {\"residual\": " << r.summary.accepted_by_residual
      << ", \"stagnation\": " << r.summary.accepted_by_stagnation << "},\n";
    // Section solves (SCM) that did not converge: the end kept its previous stiffness for that
    // step. Counted over the run, so a user sees it rather than a silent plastic hinge.
    int section_failures = 0;
    for (const ElementResult& e : r.last.elements)
        for (const HingeReport& h : e.hinge) section_failures += h.section_failures;
    if (r.model->inelastic()) j << "  \"section_solve_failures\": " << section_failures << ",\n";
    j << "  \"final\": {\"load_factor\": " << r.last.load_factor << ", \"load\": " << r.last.load
      << ", \"control_displacement\": " << r.last.control_displacement << ", \"contact_count\": "
      << r.last.contact_count << ", \"hinge_count\": " << r.last.hinge_count << "},\n";
    j << "  \"peak\": {\"load\": " << r.peak_load << ", \"control_displacement\": " << r.peak_load_displacement << "},\n";
    j << "  \"seconds\": {";
    for (std::size_t i = 0; i < r.stage_seconds.size(); ++i)
        j << (i ? ", " : "") << quoted(r.stage_seconds[i].first) << ": " << r.stage_seconds[i].second;
    j << "}\n}\n";
    return j.str();
}

void write_run_report(const std::string& path, const RunReport& report) {
    write_file_atomically(path, to_json(report));
}

} // namespace plastica
