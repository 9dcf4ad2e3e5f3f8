#include "section/fibre_section.hpp"

#include "material/material_registry.hpp"
#include "section/strain_limit_capacity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace plastica {


FibreSection::FibreSection(const SectionSpec& spec) : spec_(spec) {
    // Fibres of one law side by side (in their order otherwise), so that each law's loop runs
    // over a contiguous run of them.
    std::vector<std::size_t> order(spec.fibres.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return spec.fibres[a].material < spec.fibres[b].material; });
    fibres_.reserve(spec.fibres.size());
    int group_material = -1;
    for (std::size_t index : order) {
        const Fibre& f = spec.fibres[index];
        const SteelSpec& law = f.material == 0 ? *spec.steel : spec.other_materials.at(static_cast<std::size_t>(f.material - 1));
        MaterialHolder material(make_material(law, f.residual_stress));
        const double E = material->elastic_modulus();
        if (f.material != group_material) {
            groups_.push_back(fibres_.size());
            group_material = f.material;
        }
        fibres_.push_back({f.area, f.y, material->limit_stress(1.0), material->limit_stress(-1.0), f.residual_stress, std::move(material), f.extent});
        ea0_ += E * f.area;
        ei0_ += E * f.area * f.y * f.y;
        ny_tension_ += fibres_.back().limit_tension * f.area;
        ny_compression_ += fibres_.back().limit_compression * f.area;
    }
    groups_.push_back(fibres_.size());
    std::vector<CapacityFibre> limits;
    limits.reserve(fibres_.size());
    for (const SectionFibre& f : fibres_) limits.push_back({f.area, f.y, f.limit_tension, f.limit_compression});
    capacity_ = section_capacity(limits);
    // Sections with a design strain limit (concrete) yield as hinges at their capacity by strain limits.
    if (has_strain_limits()) strain_limit_hinge_ = strain_limit_capacity(*this);
    force_scale_ = std::max(ny_tension_, ny_compression_);
    moment_scale_ = std::max(moment_capacity(0.0, 1.0), moment_capacity(0.0, -1.0));
}

bool FibreSection::has_strain_limits() const {
    return std::any_of(fibres_.begin(), fibres_.end(),
                       [](const SectionFibre& f) { return std::isfinite(f.material->strain_limits().bending_compression); });
}

const CapacityCurve& FibreSection::hinge_capacity(double sign) const {
    const int side = sign > 0.0 ? 0 : 1;
    return strain_limit_hinge_ ? strain_limit_hinge_->hinge[side] : capacity_->hinge[side];
}

SectionResponse FibreSection::set_trial_deformation(double eps0, double curvature) {
    return set_trial<false>(eps0, curvature);
}

SectionResponse FibreSection::set_trial_deformation_on_branches(double eps0, double curvature) {
    return set_trial<true>(eps0, curvature);
}

bool FibreSection::branches_consistent() const {
    return std::all_of(fibres_.begin(), fibres_.end(),
                       [](const SectionFibre& f) { return f.material->branch_consistent(); });
}

template <bool on_branches>
SectionResponse FibreSection::set_trial(double eps0, double curvature) {
    eps0_t_ = eps0;
    phi_t_ = curvature;
    if (fibres_.empty()) return {};
    FibreSums sums;
    for (std::size_t g = 0; g + 1 < groups_.size(); ++g) {
        SectionFibre* first = fibres_.data() + groups_[g];
        const FibreSums part = first->material->set_trial_fibres(first, groups_[g + 1] - groups_[g], eps0, curvature, on_branches);
        sums.N += part.N;
        sums.M += part.M;
        sums.k11 += part.k11;
        sums.k12 += part.k12;
        sums.k22 += part.k22;
    }
    SectionResponse r;
    r.N = sums.N;
    r.M = sums.M;
    r.tangent << sums.k11, sums.k12, sums.k12, sums.k22;
    return r;
}

ScmResult FibreSection::solve_for_forces(double N, double M, int max_iterations) {
    ScmResult result;
    const double sign = M >= 0.0 ? 1.0 : -1.0;
    if (N >= ny_tension_ || N <= -ny_compression_ ||
        std::abs(M) >= moment_capacity(N, sign) * (1.0 - 1e-12)) {
        result.outcome = ScmOutcome::beyond_capacity;
        return result;
    }
    Eigen::Vector2d x(eps0_c_, phi_c_);
    const Eigen::Vector2d target(N, M);
    const Eigen::Vector2d scale(force_scale_, moment_scale_);
    SectionResponse r = set_trial_deformation(x[0], x[1]);
    auto misfit = [&](const SectionResponse& s) {
        return Eigen::Vector2d((target[0] - s.N) / scale[0], (target[1] - s.M) / scale[1]);
    };
    Eigen::Vector2d f = misfit(r);
    for (int it = 0; it < max_iterations; ++it) {
        result.iterations = it;
        if (f.lpNorm<Eigen::Infinity>() < 1e-11) {
            result.outcome = ScmOutcome::converged;
            break;
        }
        const double det = r.tangent.determinant();
        if (!(std::abs(det) > 1e-300)) break; // every fibre yielded: no unique deformation
        const Eigen::Vector2d step = r.tangent.partialPivLu().solve(target - Eigen::Vector2d(r.N, r.M));
        // Backtracking line search on the scaled misfit: the fibre law is piecewise linear,
        // and a full step can jump across several yield kinks near the capacity curve.
        double alpha = 1.0;
        SectionResponse trial;
        Eigen::Vector2d f_trial;
        for (int ls = 0; ls < 30; ++ls) {
            trial = set_trial_deformation(x[0] + alpha * step[0], x[1] + alpha * step[1]);
            f_trial = misfit(trial);
            if (f_trial.norm() < (1.0 - 1e-4 * alpha) * f.norm()) break;
            alpha *= 0.5;
        }
        x += alpha * step;
        r = trial;
        f = f_trial;
    }
    if (result.outcome != ScmOutcome::converged && f.lpNorm<Eigen::Infinity>() < 1e-11)
        result.outcome = ScmOutcome::converged;
    // The fibres nearly always hold the trial at x already (the last deformation set was the
    // accepted one); not after a line search that found no descent.
    if (eps0_t_ != x[0] || phi_t_ != x[1]) set_trial_deformation(x[0], x[1]);
    result.eps0 = x[0];
    result.curvature = x[1];
    result.response = r;
    const double f11 = r.tangent(0, 0), f12 = r.tangent(0, 1), f22 = r.tangent(1, 1);
    result.ea_tangent = f22 > 0.0 ? f11 - f12 * f12 / f22 : f11;
    result.ei_tangent = f11 > 0.0 ? f22 - f12 * f12 / f11 : 0.0;
    return result;
}

void FibreSection::commit() {
    for (SectionFibre& f : fibres_) f.material->commit();
    eps0_c_ = eps0_t_;
    phi_c_ = phi_t_;
}

void FibreSection::revert() {
    for (SectionFibre& f : fibres_) f.material->revert();
    eps0_t_ = eps0_c_;
    phi_t_ = phi_c_;
}

double FibreSection::moment_capacity(double N, double sign) const {
    if (N >= ny_tension_ || N <= -ny_compression_) return 0.0;
    return std::max((sign > 0.0 ? 1.0 : -1.0) * moment_bound(N, sign), 0.0);
}

double FibreSection::moment_bound(double N, double sign) const {
    const std::vector<CapacityPoint>& curve = capacity_->polyline[sign > 0.0 ? 0 : 1];
    if (curve.size() < 2 || N < curve.front().N || N > curve.back().N) return 0.0;
    const auto upper = std::upper_bound(curve.begin() + 1, curve.end() - 1, N,
                                        [](double n, const CapacityPoint& p) { return n < p.N; });
    const CapacityPoint& a = *(upper - 1);
    const CapacityPoint& b = *upper;
    const double t = b.N > a.N ? (N - a.N) / (b.N - a.N) : 0.0;
    return a.M + t * (b.M - a.M);
}

double FibreSection::first_yield_moment(double N, double sign) const {
    // Concrete cracks long before steel yields: its first yield is the cracked section's.
    return has_strain_limits() ? cracked_yield_moment(N, sign) : yield_moment(N, true, sign);
}

double FibreSection::axial_strain_for(double N, double curvature, double start) {
    double eps0 = start, lo = -1.0, hi = 1.0;
    for (int it = 0; it < 200; ++it) {
        const SectionResponse r = set_trial_deformation(eps0, curvature);
        const double g = r.N - N;
        if (std::abs(g) < 1e-12 * force_scale_) break;
        if (g > 0.0) hi = std::min(hi, eps0); else lo = std::max(lo, eps0);
        double next = r.tangent(0, 0) > 0.0 ? eps0 - g / r.tangent(0, 0) : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        eps0 = next;
    }
    return eps0;
}

double FibreSection::cracked_yield_moment(double N, double sign) const {
    if (N >= ny_tension_ || N <= -ny_compression_) return 0.0;
    FibreSection virgin(spec_);
    const double s = sign > 0.0 ? 1.0 : -1.0;
    const auto steel_yields = [&](double curvature) {
        virgin.axial_strain_for(N, s * curvature, 0.0);
        return std::any_of(virgin.fibres_.begin(), virgin.fibres_.end(),
                           [](const SectionFibre& f) { return f.limit_tension > 0.0 && f.material->yielding(); });
    };
    // Bracket the first yield in curvature, then bisect.
    double lo = 0.0, hi = first_fibre_yield_moment(0.0, s) / ei0_;
    if (!(hi > 0.0) || !std::isfinite(hi)) hi = 1e-9;
    for (int k = 0; k < 60 && !steel_yields(hi); ++k) lo = hi, hi *= 2.0;
    for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (steel_yields(mid) ? hi : lo) = mid;
    }
    virgin.axial_strain_for(N, s * lo, 0.0);
    return s * virgin.set_trial_deformation(virgin.eps0_t_, s * lo).M;
}

void FibreSection::mark_events(MomentCurvaturePoint& p) const {
    for (const SectionFibre& f : fibres_) {
        const double strain = f.material->strain();
        const double limit = f.material->strain_limits().bending_compression;
        if (f.limit_tension == 0.0 && strain > 0.0) p.cracked = true;
        if (f.limit_tension > 0.0 && f.material->yielding()) p.yielded = true;
        if (std::isfinite(limit) && strain < -limit) p.crushed = true;
    }
}

double FibreSection::first_fibre_yield_moment(double N, double sign) const { return yield_moment(N, false, sign); }

double FibreSection::yield_moment(double N, bool at_edges, double sign) const {
    // Elastic stresses σ = N·E/EA + M·E·y/EI (with M positive compressing +y) reach the limit
    // first at the fibre edge with the smallest margin (a wall's outer face, not its middle);
    // residual stresses are part of the initial stress. A fibre without tensile strength
    // (concrete) cracks rather than yields: only its compression counts.
    double best = std::numeric_limits<double>::infinity();
    for (const SectionFibre& f : fibres_) {
        const double E = f.material->elastic_modulus();
        const double axial = N * E / ea0_ + f.residual_stress;
        const double extent = at_edges ? f.extent : 0.0;
        for (double edge : {f.y - extent, f.y + extent}) {
            const double per_moment = -(sign > 0.0 ? 1.0 : -1.0) * E * edge / ei0_;
            if (per_moment == 0.0) continue;
            if (per_moment > 0.0 && f.limit_tension == 0.0) continue;
            const double limit = per_moment > 0.0 ? (f.limit_tension - axial) / per_moment : (-f.limit_compression - axial) / per_moment;
            best = std::min(best, limit);
        }
    }
    return best;
}

std::vector<MomentCurvaturePoint> FibreSection::moment_curvature(double N, double max_curvature,
                                                                 int points) const {
    FibreSection virgin(spec_);
    std::vector<MomentCurvaturePoint> curve;
    double eps0 = 0.0;
    bool cracked = false, yielded = false, crushed = false;
    for (int p = 0; p <= points; ++p) {
        const double phi = max_curvature * p / points;
        eps0 = virgin.axial_strain_for(N, phi, eps0);
        SectionResponse r = virgin.set_trial_deformation(eps0, phi);
        MomentCurvaturePoint point{phi, r.M, eps0};
        virgin.mark_events(point);
        // Once happened, it stays so (a fibre that closes again was still cracked).
        point.cracked = cracked = cracked || point.cracked;
        point.yielded = yielded = yielded || point.yielded;
        point.crushed = crushed = crushed || point.crushed;
        virgin.commit();
        curve.push_back(point);
    }
    return curve;
}

int FibreSection::failed_fibres() const {
    return static_cast<int>(std::count_if(fibres_.begin(), fibres_.end(),
                                          [](const SectionFibre& f) { return f.material->failed(); }));
}

int FibreSection::yielded_fibres() const {
    return static_cast<int>(std::count_if(fibres_.begin(), fibres_.end(),
                                          [](const SectionFibre& f) { return f.material->yielding(); }));
}

double FibreSection::yielded_area_share() const {
    double yielded = 0.0, total = 0.0;
    for (const SectionFibre& f : fibres_) {
        total += f.area;
        if (f.material->yielding() || f.material->failed()) yielded += f.area;
    }
    return total > 0.0 ? yielded / total : 0.0;
}

} // namespace plastica
