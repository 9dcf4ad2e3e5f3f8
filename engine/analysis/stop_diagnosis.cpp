#include "analysis/stop_diagnosis.hpp"

#include <cmath>
#include <sstream>

namespace plastica {

StopReason diagnose_failed_step(const FailedStep& f) {
    StopReason out;
    std::ostringstream why;
    if (f.failure == NewtonFailure::non_finite) {
        out.status = RunStatus::non_finite;
        why << "non-finite state in step " << f.step;
        if (!f.non_finite_where.empty()) why << " at " << f.non_finite_where;
    } else if (!f.mechanism.empty()) {
        why << "the structure became a mechanism in step " << f.step << " at load factor " << f.load_factor << ": "
            << f.mechanism;
    } else if (f.limit) {
        out.status = RunStatus::limit_load;
        why << "limit load reached at load factor " << f.load_factor << " (" << f.limit_evidence << ")";
        if (!f.plastic_sites.empty()) why << ": a plastic mechanism, hinges at capacity at " << f.plastic_sites;
    } else {
        why << "no convergence in step " << f.step << " at load factor " << f.load_factor << " (" << to_string(f.failure);
        if (f.hopeless) why << ", no smaller increment can help";
        else why << " with the increment cut to " << std::abs(f.increment);
        // The verdict names the criterion that failed: a residual within its tolerance did not.
        const bool residual_met = f.residual <= f.tolerance;
        why << "; the residual ended at " << f.residual << " of the load";
        if (!residual_met) why << ", residual_tolerance " << f.tolerance << ")";
        else if (!f.settled)
            why << ", within residual_tolerance " << f.tolerance
                << ", but contact, hinges or fibres kept changing state between iterations)";
        else
            why << ", within residual_tolerance " << f.tolerance << ", but the corrections stayed at " << f.correction_ratio
                << " of the increment, above displacement_tolerance " << f.displacement_tolerance << ")";
        if (!residual_met && !f.tolerance_follows_floor && f.floor.total >= 0.1 * f.tolerance) {
            why << ": round-off alone leaves about " << f.floor.total
                << " of the load out of balance in this model (its stiffest terms times the rounding "
                   "of its displacements), so the tolerance cannot be met; ";
            if (f.floor.from_springs >= 0.5 * f.floor.total)
                why << "most of it comes from the foundation's penalty stiffness: lower it (the "
                       "penetration falls as 1/k, so 1e4 to 1e6 times EI/L³ is plenty), or set a "
                       "residual_tolerance above that";
            else
                why << "use fewer or longer elements, or a residual_tolerance above that";
        }
        if (f.controlled_through_contact)
            why << "; the members' surfaces press on each other ([[self_contact]]), so the controlled point can "
                   "hardly move further: control the plate's travel (load control or arc length) to press on";
    }
    out.reason = why.str();
    return out;
}

} // namespace plastica
