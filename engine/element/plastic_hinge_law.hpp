// Refined plastic hinges at both ends of an elastic beam (concentrated plasticity, CS-ASA
// style), written as stress-resultant plasticity of the basic forces q = [N, M_i, M_j].
//
// Each end has two kinds of yield rows, solved together by one return map from the committed
// state (backward Euler, element/return_map.hpp):
// - the CS-ASA paper's pseudo-spring (Silva, Silveira, Lemes, Nogueira, Gonçalves) while the end section is partly yielded: a loading surface
//   through the committed moment with hardening S = (6EI/L)·η/(1 − η), η = EI_T/EI of the
//   section by the Strain Compatibility Method at the committed state (Chan & Chui 2000). Its
//   multiplier decides loading or unloading, so the response stays continuous where an end
//   turns round (an elastic-trial sign test makes it jump there, and Newton then cycles);
// - the section's N–M capacity M_p(N) (section/capacity_curve.hpp, smooth through the fibres'
//   fully plastic states) and the squash loads: the force state stays inside and flows along
//   the normal, plastic rotation and plastic axial strain alike, so N never exceeds the squash
//   load and catenary action comes out right. The curved surface is met by linearising it at
//   the current N and repeating the linear return map until N stops moving (Newton on the
//   surface); the consistent tangent includes its curvature.
// Every row carries some hardening: the capacity rows 1e-6 of the elastic stiffness along
// their normal, remembered from step to step (the moment at capacity grows by 1e-6·4EI/L per
// radian of plastic rotation). It keeps the tangent regular where a whole member flows at the
// squash load.
#pragma once

#include "element/basic_law.hpp"
#include "element/hinge_ends.hpp"
#include "element/return_map.hpp"
#include "section/fibre_section.hpp"

#include <array>
#include <vector>

namespace plastica {

class PlasticHingeLaw final : public TrialTangentLaw {
public:
    static constexpr double regularising_hardening = 1e-6;
    // Stiffened (stiffen_capacity), the rows harden by at least this many times their own too: a
    // hardening law's mechanism (1e-4 hinges flattening a pipe under load control of the plate)
    // stops where its own hardening holds it no better.
    static constexpr double stiffened_own_factor = 10.0;

    // ends_served: for each end, how many element ends its capacity rows and its pseudo-spring
    // stand for (analysis/hinge_allocation.hpp): 0, none; 1, its own; 2, its own and the other
    // element's at the node, where nothing else takes moment. A row serving two ends has half
    // the hardening (regularising, or the spring's): the node's hinge then hardens like the
    // two ends' hinges in series, as it does where each end has its own.
    PlasticHingeLaw(const SectionSpec& section, double L0, HingeEnds ends_served = {});

    void commit() override;
    void revert() override;
    bool has_hinges() const override { return true; }
    // Called at a committed state: an end that stops serving drops its capacity rows (its
    // plastic deformation stays), an end that starts takes its section's committed stiffness.
    void serve_hinge_ends(const HingeEnds& ends) override;
    HingeReport hinge(int end) const override { return committed_end_[end]; }
    Eigen::Vector3d plastic_deformation() const override;
    void freeze_states(bool frozen) override { frozen_ = frozen; }
    void predict_unloading() override { unloading_predictor_ = true; }
    void stiffen_capacity(double ratio) override {
        stiffened_ = ratio;
        linearise_capacity(q_c_[0]); // the predictor's rows too
    }
    bool states_consistent() const override { return consistent_; }
    double trial_yield_advance() const override;
    std::unique_ptr<BasicLaw> clone() const override {
        return std::make_unique<PlasticHingeLaw>(*this);
    }

private:
    void trial_response(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) override;
    // Section moment at an end from the basic end moments: the sagging moment EI·dθ/ds is
    // −M_i at the first end and +M_j at the second.
    static double section_moment(const Eigen::Vector3d& q, int end) {
        return end == 0 ? -q[1] : q[2];
    }
    void set_loading_surfaces();
    // Linearises the capacity rows at axial force N (disabled at an end without capacity).
    void linearise_capacity(double N);
    bool outside_capacity(const Eigen::Vector3d& q) const;
    double capacity_margin(const Eigen::Vector3d& q, int end) const; // M_p(N)+offset − |m|, ≥ 0 inside
    Eigen::Matrix3d curved_tangent(const ReturnMap& r) const;
    // A trial state without plastic flow: q_now with tangent k_now.
    void set_without_flow(const Eigen::Vector3d& e, const Eigen::Vector3d& q_now, const Eigen::Matrix3d& k_now,
                          Eigen::Vector3d& q, Eigen::Matrix3d& k);

    double EA_, EI_, L0_;
    std::array<FibreSection, 2> sections_;
    Eigen::Matrix3d k_elastic_;
    Eigen::Matrix3d f_elastic_; // its inverse, the elastic flexibility
    double moment_scale_;          // plastic moment at N = 0
    // Rows: 0, 1 pseudo-springs of ends i, j; 2, 3 their capacity in positive bending, 4, 5
    // in negative bending; 6, 7 tension and compression squash loads (in an element without
    // capacity rows only).
    enum Row { spring_i = 0, spring_j = 1, capacity_i = 2, capacity_j = 3, negative_i = 4, negative_j = 5,
               tension = 6, compression = 7, row_count = 8 };
    static_assert(row_count <= max_yield_rows, "the return map holds its row sets in place");
    static bool capacity_row(int r) { return r >= capacity_i && r <= negative_j; }
    static int row_end(int r) { return (r - capacity_i) % 2; }
    static double row_sign(int r) { return r < negative_i ? 1.0 : -1.0; }
    std::vector<YieldRow> rows_;
    std::array<bool, 2> capacity_at_;   // ends with capacity rows
    HingeEnds ends_served_;
    std::array<double, row_count> hardened_{};     // remembered hardening of each row's limit

    // Committed state.
    Eigen::Vector3d e_c_ = Eigen::Vector3d::Zero();
    Eigen::Vector3d q_c_ = Eigen::Vector3d::Zero();
    std::array<double, 2> eta_c_{1.0, 1.0};              // pseudo-spring η for the next step
    RowSet active_c_;
    RowSet loading_c_; // rows that flowed in the last step: the predictor's tangent
    std::array<HingeReport, 2> committed_end_{};

    // Trial state.
    Eigen::Vector3d e_t_ = Eigen::Vector3d::Zero();
    Eigen::Vector3d q_t_ = Eigen::Vector3d::Zero();
    Eigen::Vector3d flow_t_ = Eigen::Vector3d::Zero();
    RowSet active_t_;
    RowValues gamma_t_;
    double curvature_t_ = 0.0; // Σγ·(−M_p″)/M_p of active capacity rows
    bool frozen_ = false;
    bool unloading_predictor_ = false; // until the next commit
    // The rows' hardening relative to the end's elastic stiffness: the material's hardening
    // ratio b where its law hardens (the moment rises past M_p(N) as the hinge turns), else
    // the regularising one.
    double row_hardening_ = regularising_hardening;
    double stiffened_ = 0.0; // a floor on row_hardening_ for the step (stiffen_capacity)
    bool consistent_ = true;
};

} // namespace plastica
