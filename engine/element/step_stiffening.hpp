// A stuck step taken with a fibre member stiffened (analysis/path_limits.cpp): an elastic spring
// of `ratio` times the member's stiffness acts in parallel on the step's increment of the basic
// deformations, and the force it gathers over the step is kept, as a hardening law keeps the
// stress its plastic strain added. Where a perfectly plastic zone has lost all its bending
// stiffness and the plate no longer touches it (a crushed ring's crown that floats off the
// plate), only the laws' regularisation is left to hold it, and Newton runs off along it.
#pragma once

#include <Eigen/Dense>

namespace plastica {

class StepStiffening {
public:
    explicit StepStiffening(const Eigen::Matrix3d& elastic) : elastic_(elastic) {}

    // 0 ends the stiffening; the force gathered so far stays.
    void set(double ratio) { ratio_ = ratio; }

    // Adds the spring's and the kept force to a trial response at e.
    void add(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) {
        trial_ = e;
        if (ratio_ > 0.0) {
            q += ratio_ * (elastic_ * (e - committed_));
            k += ratio_ * elastic_;
        }
        q += kept_;
    }
    void commit() {
        if (ratio_ > 0.0) kept_ += ratio_ * (elastic_ * (trial_ - committed_));
        committed_ = trial_;
    }
    void revert() { trial_ = committed_; }

private:
    Eigen::Matrix3d elastic_;
    double ratio_ = 0.0;
    Eigen::Vector3d committed_ = Eigen::Vector3d::Zero(); // the basic deformations at the last commit
    Eigen::Vector3d trial_ = Eigen::Vector3d::Zero();
    Eigen::Vector3d kept_ = Eigen::Vector3d::Zero();
};

} // namespace plastica
