#include "element/corotational_beam.hpp"

#include <cmath>

namespace plastica {

namespace {
double wrap_to_pi(double angle) {
    // Nearly always already in range: skip the costly remainder then.
    return std::abs(angle) <= M_PI ? angle : std::remainder(angle, 2.0 * M_PI);
}
} // namespace

CorotationalBeam::CorotationalBeam(const Node& a, const Node& b, std::unique_ptr<BasicLaw> law)
    : x0_(a.x), y0_(a.y), dx0_(b.x - a.x), dy0_(b.y - a.y), law_(std::move(law)) {
    L0_ = std::hypot(dx0_, dy0_);
    c0_ = dx0_ / L0_;
    s0_ = dy0_ / L0_;
    length_trial_ = length_committed_ = L0_;
}

CorotationalBeam::CorotationalBeam(const CorotationalBeam& o)
    : x0_(o.x0_), y0_(o.y0_), dx0_(o.dx0_), dy0_(o.dy0_), L0_(o.L0_), c0_(o.c0_), s0_(o.s0_),
      law_(o.law_->clone()), alpha_committed_(o.alpha_committed_), alpha_trial_(o.alpha_trial_),
      length_trial_(o.length_trial_), q_trial_(o.q_trial_), q_committed_(o.q_committed_),
      length_committed_(o.length_committed_) {}

void CorotationalBeam::compute(const Vector6& d, Vector6& force, Matrix6* tangent) {
    const double ddx = d[3] - d[0];
    const double ddy = d[4] - d[1];
    const double dx = dx0_ + ddx;
    const double dy = dy0_ + ddy;
    const double L = std::hypot(dx, dy);
    const double c = dx / L;
    const double s = dy / L;
    // Rigid rotation of the chord: atan2 gives it in (−π, π]; unwrap it next to the committed
    // value so that it stays continuous through any number of turns.
    const double raw = std::atan2(c0_ * s - s0_ * c, c0_ * c + s0_ * s);
    const double alpha = alpha_committed_ + wrap_to_pi(raw - alpha_committed_);

    // Stretch (L² − L0²)/(L + L0), with L² − L0² formed from the displacement differences:
    // forming it from coordinates cancels digits (coordinates ~100, EA/L0 ~1e7 in the ring
    // leave a residual floor near 1e-4 of small loads); this way it is exact to round-off of Δ.
    Eigen::Vector3d e;
    e[0] = (ddx * (2.0 * dx0_ + ddx) + ddy * (2.0 * dy0_ + ddy)) / (L + L0_);
    e[1] = d[2] - alpha;
    e[2] = d[5] - alpha;

    Eigen::Vector3d q;
    Eigen::Matrix3d kb;
    law_->trial(e, q, kb);

    Vector6 r, z;
    r << -c, -s, 0.0, c, s, 0.0;
    z << s, -c, 0.0, -s, c, 0.0;
    Eigen::Matrix<double, 3, 6> B;
    B.row(0) = r.transpose();
    B.row(1) = -z.transpose() / L;
    B.row(2) = -z.transpose() / L;
    B(1, 2) += 1.0;
    B(2, 5) += 1.0;

    force.noalias() = B.transpose() * q;
    if (tangent) {
        tangent->noalias() = B.transpose() * kb * B;
        tangent->noalias() += (q[0] / L) * (z * z.transpose());
        tangent->noalias() += ((q[1] + q[2]) / (L * L)) * (r * z.transpose() + z * r.transpose());
    }
    alpha_trial_ = alpha;
    length_trial_ = L;
    q_trial_ = q;
}

void CorotationalBeam::commit() {
    law_->commit();
    alpha_committed_ = alpha_trial_;
    length_committed_ = length_trial_;
    q_committed_ = q_trial_;
}

void CorotationalBeam::revert() {
    law_->revert();
    alpha_trial_ = alpha_committed_;
    length_trial_ = length_committed_;
    q_trial_ = q_committed_;
}

BeamForces CorotationalBeam::forces() const {
    BeamForces f;
    f.axial = q_committed_[0];
    f.moment_i = -q_committed_[1];
    f.moment_j = q_committed_[2];
    f.shear = (q_committed_[1] + q_committed_[2]) / length_committed_;
    return f;
}

} // namespace plastica
