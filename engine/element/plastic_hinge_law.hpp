// Refined plastic hinges at both ends of an elastic beam (concentrated plasticity, CS-ASA
// style): each end is a pseudo-spring S = (6EI/L)·η/(1 − η) with η = EI_T/EI of the end
// section from the Strain Compatibility Method, in series with the elastic beam (Chan & Chui
// 2000); η = 1 keeps the end rigid, η = 0 makes it a free hinge. Forces are integrated
// incrementally from the committed state; an end that would leave the N–M capacity curve is
// returned onto it (no drift), and an end whose moment decreases unloads elastically. The
// axial stiffness stays EA/L; EA_T of each end section is reported, not applied.
#pragma once

#include "element/basic_law.hpp"
#include "section/fibre_section.hpp"

#include <array>

namespace plastica {

class PlasticHingeLaw final : public BasicLaw {
public:
    PlasticHingeLaw(const SectionSpec& section, double L0);

    void trial(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) override;
    void commit() override;
    void revert() override;
    bool has_hinges() const override { return true; }
    HingeReport hinge(int end) const override { return committed_end_[end]; }
    Eigen::Vector3d plastic_deformation() const override;
    std::unique_ptr<BasicLaw> clone() const override {
        return std::make_unique<PlasticHingeLaw>(*this);
    }

private:
    // Section moment at an end from the basic end moments: the sagging moment EI·dθ/ds is
    // −M_i at the first end and +M_j at the second.
    static double section_moment(const Eigen::Vector3d& q, int end) {
        return end == 0 ? -q[1] : q[2];
    }
    Eigen::Matrix3d stiffness(const std::array<double, 2>& eta, double axial_ratio) const;
    double capacity(int end, double N, double m) const;

    double EA_, EI_, L0_;
    std::array<FibreSection, 2> sections_;
    Eigen::Vector3d e_committed_ = Eigen::Vector3d::Zero();
    Eigen::Vector3d q_committed_ = Eigen::Vector3d::Zero();
    Eigen::Vector3d e_trial_ = Eigen::Vector3d::Zero();
    Eigen::Vector3d q_trial_ = Eigen::Vector3d::Zero();
    std::array<HingeReport, 2> committed_end_{};
};

} // namespace plastica
