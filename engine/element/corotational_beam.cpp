#include "element/corotational_beam.hpp"

#include <array>
#include <cmath>

namespace plastica {

namespace {
double wrap_to_pi(double angle) {
    // Nearly always already in range: skip the costly remainder then.
    return std::abs(angle) <= M_PI ? angle : std::remainder(angle, 2.0 * M_PI);
}

// r = [−c −s 0 c s 0]ᵀ and z = [s −c 0 −s c 0]ᵀ of a chord along (c, s).
struct ChordVectors {
    double r[6], z[6];
    ChordVectors(double c, double s) : r{-c, -s, 0.0, c, s, 0.0}, z{s, -c, 0.0, -s, c, 0.0} {}
};

// The rows of B at a chord of length L along (c, s): the stretch's r, and the end rotations'
// relative to the chord, b + e₃ and b + e₆ with b = −z/L.
struct BasicRows {
    Vector6 stretch, rotation_i, rotation_j;
    BasicRows(double c, double s, double L) {
        const ChordVectors chord(c, s);
        for (int k = 0; k < 6; ++k) {
            stretch[k] = chord.r[k];
            rotation_i[k] = rotation_j[k] = -chord.z[k] / L;
        }
        rotation_i[2] += 1.0;
        rotation_j[5] += 1.0;
    }
};
} // namespace

CorotationalBeam::CorotationalBeam(const Node& a, const Node& b, std::unique_ptr<BasicLaw> law, bool first_order)
    : dx0_(b.x - a.x), dy0_(b.y - a.y), first_order_(first_order), law_(std::move(law)) {
    L0_ = std::hypot(dx0_, dy0_);
    c0_ = dx0_ / L0_;
    s0_ = dy0_ / L0_;
    length_trial_ = length_committed_ = L0_;
    c_trial_ = c0_;
    s_trial_ = s0_;
}

CorotationalBeam::CorotationalBeam(const CorotationalBeam& o)
    : dx0_(o.dx0_), dy0_(o.dy0_), L0_(o.L0_), c0_(o.c0_), s0_(o.s0_), first_order_(o.first_order_),
      law_(o.law_->clone()), alpha_committed_(o.alpha_committed_), alpha_trial_(o.alpha_trial_),
      length_trial_(o.length_trial_), c_trial_(o.c_trial_), s_trial_(o.s_trial_),
      q_trial_(o.q_trial_), q_committed_(o.q_committed_),
      length_committed_(o.length_committed_) {}

void CorotationalBeam::compute(const Vector6& d, Vector6& force, Matrix6* tangent) {
    const double ddx = d[3] - d[0];
    const double ddy = d[4] - d[1];
    if (first_order_) {
        compute_first_order(d, ddx, ddy, force, tangent);
        return;
    }
    const double dx = dx0_ + ddx;
    const double dy = dy0_ + ddy;
    // Chords are far from hypot's overflow range: the square root of the sum is exact enough.
    const double L = std::sqrt(dx * dx + dy * dy);
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

    Eigen::Matrix3d k_basic; // kept by the law for tangent()
    law_->trial(e, q_trial_, k_basic);
    alpha_trial_ = alpha;
    length_trial_ = L;
    c_trial_ = c;
    s_trial_ = s;
    // f = Bᵀ q, the sums in the order of Eigen's fixed-size product (as the tangent below).
    const double N = q_trial_[0], Mi = q_trial_[1], Mj = q_trial_[2];
    const ChordVectors chord(c, s);
    // b = −z/L with two divisions instead of six: the second node's entries are the first's
    // negated (exactly), the rotations' are −0/L = −0.
    const double b0 = -s / L, b1 = c / L;
    const double bending[6] = {b0, b1, -0.0, -b0, -b1, -0.0};
    for (int i = 0; i < 6; ++i)
        force[i] = chord.r[i] * N + (bending[i] + (i == 2 ? 1.0 : 0.0)) * Mi + (bending[i] + (i == 5 ? 1.0 : 0.0)) * Mj;
    if (tangent) this->tangent(*tangent);
}

void CorotationalBeam::compute_first_order(const Vector6& d, double ddx, double ddy, Vector6& force, Matrix6* tangent) {
    // The chord's stretch and turn projected on the initial chord: e = B₀ d.
    const double along = c0_ * ddx + s0_ * ddy, across = c0_ * ddy - s0_ * ddx;
    alpha_trial_ = across / L0_;
    const Eigen::Vector3d e(along, d[2] - alpha_trial_, d[5] - alpha_trial_);
    Eigen::Matrix3d k_basic;
    law_->trial(e, q_trial_, k_basic);
    const BasicRows B(c0_, s0_, L0_);
    force = B.stretch * q_trial_[0] + B.rotation_i * q_trial_[1] + B.rotation_j * q_trial_[2];
    if (tangent) this->tangent(*tangent);
}

void CorotationalBeam::tangent(Matrix6& k, double axial_force) const {
    // Bᵀ·k_b·B + z zᵀ N/L + (r zᵀ + z rᵀ)(M_i + M_j)/L², with the rows of B being r, b + e₃ and
    // b + e₆ (b = −z/L). r and z vanish at the rotations and change sign from the first node to
    // the second: every row of K is α·r + β·z plus, at the rotations, a row of Bᵀ·k_b, and the
    // second node's translation rows are the first node's negated.
    const double inverse_L = 1.0 / length_trial_;
    const double c = c_trial_, s = s_trial_;
    Eigen::Matrix3d kb;
    law_->trial_tangent(kb);
    // At first order the equilibrium is on the initial chord: no geometric terms.
    const double axial = first_order_ ? 0.0 : axial_force * inverse_L;
    const double shear = first_order_ ? 0.0 : (q_trial_[1] + q_trial_[2]) * inverse_L * inverse_L;
    // Row `row` of K from w, its row of Bᵀ·k_b, and r_i, z_i.
    auto fill = [&](int row, const double w[3], double r, double z) {
        const double alpha = w[0] + shear * z;
        const double beta = axial * z + shear * r - (w[1] + w[2]) * inverse_L;
        k(row, 0) = -alpha * c + beta * s;
        k(row, 1) = -alpha * s - beta * c;
        k(row, 2) = w[1];
        k(row, 3) = -k(row, 0);
        k(row, 4) = -k(row, 1);
        k(row, 5) = w[2];
    };
    // The first node's translations: r = (−c, −s), z = (s, −c).
    for (int i = 0; i < 2; ++i) {
        const double r = i == 0 ? -c : -s, z = i == 0 ? s : -c, b = -z * inverse_L;
        const double w[3] = {r * kb(0, 0) + b * (kb(1, 0) + kb(2, 0)), r * kb(0, 1) + b * (kb(1, 1) + kb(2, 1)),
                             r * kb(0, 2) + b * (kb(1, 2) + kb(2, 2))};
        fill(i, w, r, z);
        for (int col = 0; col < 6; ++col) k(i + 3, col) = -k(i, col);
    }
    // The rotations: rows 1 and 2 of k_b.
    const double w2[3] = {kb(1, 0), kb(1, 1), kb(1, 2)}, w5[3] = {kb(2, 0), kb(2, 1), kb(2, 2)};
    fill(2, w2, 0.0, 0.0);
    fill(5, w5, 0.0, 0.0);
}


double CorotationalBeam::axial_force_rate(const Vector6& rate) const {
    Eigen::Matrix3d kb;
    law_->trial_tangent(kb);
    const BasicRows B(c_trial_, s_trial_, length_trial_);
    return kb(0, 0) * B.stretch.dot(rate) + kb(0, 1) * B.rotation_i.dot(rate) + kb(0, 2) * B.rotation_j.dot(rate);
}

void CorotationalBeam::geometric_stiffness(double N, Matrix6& k, bool cubic) const {
    const double L = length_trial_;
    const ChordVectors chord(c_trial_, s_trial_);
    const Eigen::Map<const Vector6> z(chord.z);
    k.noalias() = (N / L) * z * z.transpose();
    if (!cubic) return;
    const BasicRows B(c_trial_, s_trial_, L);
    const std::array<bool, 2> released = law_->released_ends();
    if (released[0] && released[1]) return;
    if (released[0] || released[1]) {
        const Vector6& held = released[0] ? B.rotation_j : B.rotation_i;
        k.noalias() += (N * L / 5.0) * held * held.transpose();
        return;
    }
    const double a = N * L / 30.0;
    k.noalias() += 4.0 * a * (B.rotation_i * B.rotation_i.transpose() + B.rotation_j * B.rotation_j.transpose());
    k.noalias() -= a * (B.rotation_i * B.rotation_j.transpose() + B.rotation_j * B.rotation_i.transpose());
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
