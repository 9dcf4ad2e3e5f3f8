#include "material/concrete.hpp"

#include "material/material_registry.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

namespace {
double parameter(const SteelSpec& spec, const char* name, double fallback) {
    const auto it = spec.parameters.find(name);
    return it == spec.parameters.end() ? fallback : it->second;
}
} // namespace

Concrete::Concrete(const SteelSpec& spec, double)
    : fc_(spec.fy), eps_c2_(parameter(spec, "eps_c2", 0.002)), eps_cu2_(parameter(spec, "eps_cu2", 0.0035)),
      n_(parameter(spec, "n", 2.0)), ft_(parameter(spec, "ft", 0.0)), eps_tu_(parameter(spec, "eps_tu", 0.001)) {
    if (!(fc_ > 0.0)) throw MaterialParameterError("fc", "expected a positive compressive strength fc");
    if (!(eps_cu2_ >= eps_c2_)) throw MaterialParameterError("eps_cu2", "expected eps_cu2 ≥ eps_c2");
    E_ = n_ * fc_ / eps_c2_;
    if (ft_ > 0.0 && !(eps_tu_ > ft_ / E_))
        throw MaterialParameterError("eps_tu", "expected a strain beyond ft/E, where tension has softened to zero");
    trial_.unload_slope = committed_.unload_slope = E_;
}

StressTangent Concrete::envelope(double strain) const {
    if (strain <= -eps_c2_) return {-fc_, 0.0};
    const double u = 1.0 + strain / eps_c2_; // 1 unstrained, 0 at εc2
    return {-fc_ * (1.0 - std::pow(u, n_)), fc_ * n_ * std::pow(u, n_ - 1.0) / eps_c2_};
}

void Concrete::unload_from(State& s) const {
    // Karsan–Jirsa's plastic strain, taken at εcu2 at most (Concrete01's rule).
    const double eta = std::min(-s.min_strain, eps_cu2_) / eps_c2_;
    const double ratio = eta < 2.0 ? 0.145 * eta * eta + 0.13 * eta : 0.707 * (eta - 2.0) + 0.834;
    const double span = s.min_strain + ratio * eps_c2_; // from εp to εmin, ≤ 0
    const double elastic_span = s.stress / E_;
    if (span > -1e-300) {
        s.end_strain = s.min_strain - elastic_span;
        s.unload_slope = E_;
    } else if (span <= elastic_span) {
        s.end_strain = s.min_strain - span;
        s.unload_slope = s.stress / span;
    } else {
        s.end_strain = s.min_strain - elastic_span;
        s.unload_slope = E_;
    }
}

StressTangent Concrete::tension(const State& s, double opening) const {
    if (ft_ <= 0.0) return {0.0, 0.0};
    const double cracking = ft_ / E_;
    const auto on_envelope = [&](double e) -> StressTangent {
        if (e <= cracking) return {E_ * e, E_};
        if (e < eps_tu_) return {ft_ * (eps_tu_ - e) / (eps_tu_ - cracking), -ft_ / (eps_tu_ - cracking)};
        return {0.0, 0.0};
    };
    if (opening >= s.max_opening || s.max_opening <= cracking) return on_envelope(opening);
    const double secant = on_envelope(s.max_opening).stress / s.max_opening; // back towards εp
    return {secant * opening, secant};
}

StressTangent Concrete::set_trial_strain(double strain) {
    State& s = trial_;
    s = committed_;
    s.strain = strain;
    if (strain <= s.min_strain) {
        const StressTangent e = envelope(strain);
        s.min_strain = strain;
        s.stress = e.stress;
        s.tangent = e.tangent;
        unload_from(s);
    } else if (strain <= s.end_strain) {
        s.stress = s.unload_slope * (strain - s.end_strain);
        s.tangent = s.unload_slope;
    } else {
        const double opening = strain - s.end_strain;
        const StressTangent t = tension(s, opening);
        s.max_opening = std::max(s.max_opening, opening);
        s.stress = t.stress;
        s.tangent = t.tangent;
    }
    return {s.stress, s.tangent};
}

} // namespace plastica
