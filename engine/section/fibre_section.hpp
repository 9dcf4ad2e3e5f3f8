// Fibre section solved by the Strain Compatibility Method (Silva et al., CS-ASA, eqs. 7–11).
// Plane sections: ε(y) = ε0 − y·Φ; resultants N = Σ σ A, M = −Σ σ y A (M = EI·Φ when elastic).
// Given a target (N, M), Newton on X = [ε0, Φ] solves F(X) = f_ext − f_int(X) = 0 with the
// Jacobian [∂N/∂ε0 ∂N/∂Φ; ∂M/∂ε0 ∂M/∂Φ]; the tangents are EA_T = f11 − f12 f21 / f22 and
// EI_T = f22 − f12 f21 / f11. The capacity M_p(N) is the fully plastic limit of the fibres.
#pragma once

#include "material/uniaxial_material.hpp"
#include "section/capacity_curve.hpp"
#include "section/section_capacity.hpp"
#include "model/model.hpp"

#include <Eigen/Dense>
#include <array>
#include <vector>

namespace plastica {

struct SectionResponse {
    double N = 0.0;
    double M = 0.0;
    Eigen::Matrix2d tangent = Eigen::Matrix2d::Zero(); // ∂(N, M)/∂(ε0, Φ)
};

enum class ScmOutcome { converged, beyond_capacity, no_convergence };

struct ScmResult {
    ScmOutcome outcome = ScmOutcome::no_convergence;
    int iterations = 0;
    double eps0 = 0.0;
    double curvature = 0.0;
    double ea_tangent = 0.0;
    double ei_tangent = 0.0;
    SectionResponse response;
};

struct MomentCurvaturePoint {
    double curvature = 0.0;
    double moment = 0.0;
    double eps0 = 0.0;
    // What has happened by this point: a fibre without tensile strength opened (concrete
    // cracked), a fibre with tensile strength yielded (steel), a fibre passed its design
    // compressive limit (concrete crushed at εcu2).
    bool cracked = false, yielded = false, crushed = false;
};

class FibreSection {
public:
    explicit FibreSection(const SectionSpec& spec);

    // Trial state of every fibre from the section deformation; returns resultants and tangent.
    SectionResponse set_trial_deformation(double eps0, double curvature);
    // The same with every fibre kept on its previous branch (UniaxialMaterial), and whether the
    // fibres are consistent with the branches they were kept to.
    SectionResponse set_trial_deformation_on_branches(double eps0, double curvature);
    bool branches_consistent() const;
    // SCM: the deformation that carries (N, M), starting from the committed deformation.
    ScmResult solve_for_forces(double N, double M, int max_iterations = 100);

    void commit();
    void revert();

    // Fully plastic moment for axial force N, for positive (sign > 0) or negative bending.
    // At least zero: a section whose plastic centroid lies off its elastic one (a composite beam)
    // carries, near a squash load, only moments of one sign (moment_bound is below zero there).
    double moment_capacity(double N, double sign) const;
    // The edge of the fully plastic domain on that side, signed: the largest M (sign > 0) or the
    // smallest (sign < 0) the fibres carry with N, at the squash points too.
    double moment_bound(double N, double sign) const;
    // Every (N, M) the fibres can carry at their limit stresses is a convex polygon (a sum of
    // one segment per fibre). The plastic hinge's capacity: the smooth curve through its
    // breakpoints, for positive (sign > 0) and negative bending.
    // A section with a design strain limit (concrete) takes its capacity by strain limits
    // instead (section/strain_limit_capacity.hpp).
    const CapacityCurve& hinge_capacity(double sign) const;
    double hinge_moment_capacity(double N, double sign) const { return hinge_capacity(sign).at(N).moment; }
    double hinge_moment_bound(double N, double sign) const { return (sign > 0.0 ? 1.0 : -1.0) * hinge_capacity(sign).bound(N); }
    double axial_capacity_tension() const { return ny_tension_; }
    double axial_capacity_compression() const { return ny_compression_; }
    double elastic_ea() const { return ea0_; }
    double elastic_ei() const { return ei0_; }
    // Whether a fibre's law sets a design strain limit (concrete's εcu2).
    bool has_strain_limits() const;
    // The fibres as they are, for capacity by strain limits and for pictures.
    const std::vector<SectionFibre>& fibres() const { return fibres_; }
    // The capacity by strain limits, or null for a section without them.
    const SectionCapacity* strain_limit_capacity_curves() const { return strain_limit_hinge_.get(); }
    // Moment at which the section first yields under axial force N (positive bending), at the
    // outer edge of its outermost fibres (a tube's outer face, not its mid-wall).
    double first_yield_moment(double N, double sign = 1.0) const;
    // The same at the fibres' centres: where the fibres themselves start to yield in the SCM
    // (the hinge measures how far a step advances its ends from it).
    double first_fibre_yield_moment(double N, double sign = 1.0) const;

    // Monotonic M–κ curve at constant N from the virgin state, up to the given curvature.
    std::vector<MomentCurvaturePoint> moment_curvature(double N, double max_curvature,
                                                       int points) const;

    int failed_fibres() const;
    int yielded_fibres() const;
    double yielded_area_share() const; // area at the yield stress (or failed) over the whole
    std::size_t fibre_count() const { return fibres_.size(); }
    double committed_eps0() const { return eps0_c_; }
    double committed_curvature() const { return phi_c_; }

private:
    template <bool on_branches>
    SectionResponse set_trial(double eps0, double curvature);
    double yield_moment(double N, bool at_edges, double sign) const;
    // The moment at which the first steel fibre yields in the cracked section (monotonic, from
    // the unstressed state), for sections with concrete.
    double cracked_yield_moment(double N, double sign) const;
    // ε0 that carries N at curvature κ from the unstressed state (N(ε0) is monotone).
    double axial_strain_for(double N, double curvature, double start);
    void mark_events(MomentCurvaturePoint& point) const;
    SectionSpec spec_; // kept to rebuild an unstressed copy
    std::vector<SectionFibre> fibres_; // grouped by law: group k is [groups_[k], groups_[k + 1])
    std::vector<std::size_t> groups_;
    // M_p(N) and the hinge's curves, shared by every section of the same fibres.
    std::shared_ptr<const SectionCapacity> capacity_;
    std::shared_ptr<const SectionCapacity> strain_limit_hinge_; // sections with strain limits
    double ea0_ = 0.0, ei0_ = 0.0;
    double ny_tension_ = 0.0, ny_compression_ = 0.0;
    double force_scale_ = 1.0, moment_scale_ = 1.0; // for convergence tests
    double eps0_t_ = 0.0, phi_t_ = 0.0, eps0_c_ = 0.0, phi_c_ = 0.0;
};

} // namespace plastica
