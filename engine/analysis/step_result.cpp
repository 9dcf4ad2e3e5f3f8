#include "analysis/step_result.hpp"

namespace plastica {

const char* to_string(RunStatus status) {
    switch (status) {
    case RunStatus::completed: return "completed";
    case RunStatus::no_convergence: return "no_convergence";
    case RunStatus::limit_load: return "limit_load";
    case RunStatus::non_finite: return "non_finite";
    case RunStatus::interrupted: return "interrupted";
    case RunStatus::step_limit: return "step_limit";
    case RunStatus::penetration: return "penetration";
    case RunStatus::output_failed: return "output_failed";
    case RunStatus::out_of_memory: return "out_of_memory";
    }
    return "unknown";
}

} // namespace plastica

namespace plastica {

const char* to_string(CriticalKind kind) {
    return kind == CriticalKind::bifurcation ? "bifurcation" : "limit_point";
}

} // namespace plastica
