#include "dynamics/time_stepper.hpp"

#include "dynamics/excitation.hpp"
#include "dynamics/initial_acceleration.hpp"
#include "dynamics/modal_analysis.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

namespace {

// A time step moves no load factor: the loads' factors are those of the step's end.
class FixedLoadFactor final : public IncrementConstraint {
public:
    double load_change(int, const Eigen::VectorXd&, const Eigen::VectorXd&, const Eigen::VectorXd&) override { return 0.0; }
};

std::vector<int> equations_of(const StructuralSystem& system) {
    std::vector<int> eq(static_cast<std::size_t>(system.dof_count()));
    for (int d = 0; d < system.dof_count(); ++d) eq[static_cast<std::size_t>(d)] = system.equation(d);
    return eq;
}

} // namespace

TimeStepper::TimeStepper(const Model& model, StructuralSystem& system)
    : model_(model), system_(system), mass_(model, model.dynamics.mass, equations_of(system), system.free_count()) {
    system_.keep_member_forces();
}

void TimeStepper::note_initial_tangent() { initial_tangent_ = system_.tangent(); }

std::array<double, 2> TimeStepper::ground_at(double t) const {
    std::array<double, 2> a{0.0, 0.0};
    for (const GroundMotionSpec& g : model_.dynamics.ground_motions) a[static_cast<std::size_t>(g.direction)] += ground_acceleration(g, t);
    return a;
}

void TimeStepper::set_damping(const TransientSpec&, const Eigen::VectorXd& u) {
    const DampingSpec& d = model_.dynamics.damping;
    damping_set_ = true;
    if (!d.present()) return;
    damping_.alpha_m = d.alpha_m;
    damping_.beta_k = d.beta_k;
    if (d.ratio) {
        // Rayleigh's coefficients that give modes i and j the ratio ζ (Chopra, Dynamics of
        // Structures, 2012, §11.4): α_M = 2ζωᵢωⱼ/(ωᵢ+ωⱼ), β_K = 2ζ/(ωᵢ+ωⱼ).
        const int highest = std::max(d.modes[0], d.modes[1]);
        const NaturalModes modes = lowest_modes(system_.tangent(), mass_.assemble(u), highest);
        if (static_cast<int>(modes.omega_squared.size()) < highest)
            throw ModalError("damping names mode " + std::to_string(highest) + ", but the structure has " +
                             std::to_string(modes.omega_squared.size()) + " modes with mass");
        const double wi = std::sqrt(std::max(0.0, modes.omega_squared[static_cast<std::size_t>(d.modes[0] - 1)]));
        const double wj = std::sqrt(std::max(0.0, modes.omega_squared[static_cast<std::size_t>(d.modes[1] - 1)]));
        damping_.alpha_m = 2.0 * *d.ratio * wi * wj / (wi + wj);
        damping_.beta_k = 2.0 * *d.ratio / (wi + wj);
    }
}

void TimeStepper::begin_stage(const TransientSpec& spec, const Eigen::VectorXd& u, double load_factor) {
    spec_ = spec;
    stage_start_ = time_;
    const Eigen::VectorXd no_prescribed = Eigen::VectorXd::Zero(u.size());
    system_.evaluate(u, no_prescribed, load_factor, false);
    DynamicState& s = state_;
    s.x = system_.gather(u);
    if (!started_) {
        Eigen::VectorXd v = Eigen::VectorXd::Zero(u.size());
        for (const InitialVelocity& iv : model_.dynamics.initial_velocities) {
            v[dofs_per_node * iv.node] = iv.velocity[0];
            v[dofs_per_node * iv.node + 1] = iv.velocity[1];
            v[dofs_per_node * iv.node + 2] = iv.rotation_rate;
        }
        s.v = system_.gather(v);
    }
    if (s.v.size() != s.x.size()) s.v = Eigen::VectorXd::Zero(s.x.size());
    if (!damping_set_) set_damping(spec, u);
    if (model_.dynamics.damping.stiffness == DampingSpec::Stiffness::committed) committed_tangent_ = system_.tangent();
    const SparseMatrix M = mass_.assemble(u);
    s.internal = system_.gather(system_.internal_force());
    s.members = system_.gather(system_.member_internal_force());
    s.ground = Eigen::VectorXd::Zero(s.x.size());
    const std::array<double, 2> ground = ground_at(time_);
    for (int d = 0; d < 2; ++d)
        if (ground[static_cast<std::size_t>(d)] != 0.0) s.ground -= ground[static_cast<std::size_t>(d)] * mass_.influence(u, d);
    s.external = system_.gather(system_.external_force(load_factor)) + s.ground;
    s.damping = Eigen::VectorXd::Zero(s.x.size());
    if (damping_.alpha_m != 0.0) s.damping += damping_.alpha_m * (M * s.v);
    const SparseMatrix& K = model_.dynamics.damping.stiffness == DampingSpec::Stiffness::initial ? initial_tangent_ : system_.tangent();
    if (damping_.beta_k != 0.0 && K.rows() == s.v.size()) s.damping += damping_.beta_k * (K * s.v);
    // The acceleration in equilibrium at the start, the ground's included; DOFs without mass
    // follow the massed ones (dynamics/initial_acceleration.hpp).
    s.a = initial_acceleration(M, system_.tangent(), s.external - s.internal - s.damping);
    if (!started_) {
        kinetic_start_ = kinetic_energy(u);
        strain_start_ = strain_energy();
        started_ = true;
    }
    reference_scale_ = std::max({reference_scale_, s.external.norm(), s.internal.norm(), (M * s.a).norm()});
}

NewtonResult TimeStepper::step(double dt, Eigen::VectorXd& u, double load_factor, const NewtonSettings& settings,
                               const FreezeAfter& freeze, LinearSolver& solver, const IterationHook& hook) {
    const DampingSpec::Stiffness k = model_.dynamics.damping.stiffness;
    damping_.fixed_stiffness = k == DampingSpec::Stiffness::initial ? &initial_tangent_
                             : k == DampingSpec::Stiffness::committed ? &committed_tangent_ : nullptr;
    trial_ = std::make_unique<TransientProblem>(system_, mass_, u, state_, NewmarkCoefficients(spec_.alpha, dt), damping_,
                                                load_factor, ground_at(time_ + dt), freeze.contact, freeze.hinges, freeze.fibres);
    trial_->set_reference_scale(reference_scale_);
    FixedLoadFactor constraint;
    return solve_increment(*trial_, constraint, settings, solver, hook);
}

void TimeStepper::commit(double dt) {
    const DynamicState& s0 = state_;
    const DynamicState& s1 = trial_->state();
    const Eigen::VectorXd dx = s1.x - s0.x;
    // Trapezoidal work of each force over the step.
    auto work = [&](const Eigen::VectorXd& f0, const Eigen::VectorXd& f1) { return 0.5 * (f0 + f1).dot(dx); };
    external_ += work(s0.external - s0.ground, s1.external - s1.ground);
    ground_ += work(s0.ground, s1.ground);
    members_ += work(s0.members, s1.members);
    contact_ += work(s0.internal - s0.members, s1.internal - s1.members);
    damped_ += work(s0.damping, s1.damping);
    reference_scale_ = std::max(reference_scale_, trial_->own_scale());
    state_ = s1;
    // On the stage's grid of time steps, time is counted in steps (a sum of ten thousand
    // increments of 0.01 would drift off 100 by round-off).
    time_ += dt;
    const double steps = std::round((time_ - stage_start_) / spec_.time_step);
    if (std::abs(time_ - stage_start_ - steps * spec_.time_step) <= 1e-9 * spec_.time_step) time_ = stage_start_ + steps * spec_.time_step;
    if (model_.dynamics.damping.stiffness == DampingSpec::Stiffness::committed) committed_tangent_ = system_.tangent();
}

double TimeStepper::kinetic_energy(const Eigen::VectorXd& u) const {
    Eigen::VectorXd v = Eigen::VectorXd::Zero(u.size());
    system_.scatter(state_.v, v);
    return 0.5 * v.dot(mass_.times(u, v));
}

double TimeStepper::strain_energy() const {
    // ½ qᵀ f q with the elastic flexibility of the basic forces: L/EA on N, and L/6EI·[2 −1; −1 2]
    // on the end moments (sagging at i is −q₁).
    double energy = 0.0;
    const std::vector<CorotationalBeam>& beams = system_.elements();
    for (std::size_t e = 0; e < beams.size(); ++e) {
        const SectionSpec& s = model_.sections[static_cast<std::size_t>(model_.elements[e].section)];
        const BeamForces f = beams[e].forces();
        const double L = beams[e].initial_length(), EA = s.E * s.area, EI = s.E * s.inertia;
        energy += 0.5 * f.axial * f.axial * L / EA +
                  L / (6.0 * EI) * (f.moment_i * f.moment_i + f.moment_i * f.moment_j + f.moment_j * f.moment_j);
    }
    return energy;
}

void TimeStepper::fill(const Eigen::VectorXd& u, StepResult& out) {
    out.time = time_;
    Eigen::VectorXd full = Eigen::VectorXd::Zero(u.size());
    system_.scatter(state_.v, full);
    out.velocity.assign(full.data(), full.data() + full.size());
    full.setZero();
    system_.scatter(state_.a, full);
    out.acceleration.assign(full.data(), full.data() + full.size());
    EnergyTerms& e = out.energy;
    e.kinetic = kinetic_energy(u);
    e.strain = strain_energy();
    e.plastic = members_ - (e.strain - strain_start_);
    e.damping = damped_;
    e.contact = contact_;
    e.external = external_;
    e.ground = ground_;
    const double balance = (e.kinetic - kinetic_start_) + members_ + e.damping + e.contact - e.external - e.ground;
    // Against the largest term so far: a term passing through zero would inflate the error.
    energy_scale_ = std::max({energy_scale_, std::abs(e.kinetic), std::abs(kinetic_start_), std::abs(e.strain), std::abs(e.plastic),
                              std::abs(e.damping), std::abs(e.contact), std::abs(e.external), std::abs(e.ground)});
    e.error = energy_scale_ > 0.0 ? std::abs(balance) / energy_scale_ : 0.0;
}

} // namespace plastica
