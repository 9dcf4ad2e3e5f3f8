// What a scene says about motion in time: masses, damping, time series, ground motions and
// initial velocities (plain data, read by io/scene/dynamics_reader.cpp; used by engine/dynamics/).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace plastica {

// Consistent: each member's Hermitian (cubic) transverse and linear axial mass in the frame of
// its current chord, with rotary inertia ρI; lumped: ρAL/2 on each end's translations and
// ρIL/2 on its rotation (engine/dynamics/mass_matrix.hpp).
enum class MassKind { consistent, lumped };

// Newmark's average acceleration (γ = 1/2, β = 1/4), or Hilber–Hughes–Taylor α in [−1/3, 0].
enum class Integrator { newmark, hht };

struct TransientSpec {
    double time_step = 0.0;
    double duration = 0.0;
    Integrator integrator = Integrator::newmark;
    double alpha = 0.0; // HHT's α; 0 is Newmark's average acceleration
};

// [[mass]]: a nodal mass (translations) and rotational inertia.
struct NodalMass {
    int node = 0;
    double mass = 0.0;
    double rotational = 0.0;
};

// [[time_series]]: the factor of a load pattern in time t (seconds from the first transient
// stage's start).
struct TimeSeriesSpec {
    enum class Kind { harmonic, pulse, table } kind = Kind::harmonic;
    enum class Shape { rectangular, half_sine, triangular } shape = Shape::half_sine; // a pulse's
    int pattern = 0;
    double amplitude = 1.0;
    double period = 1.0;   // harmonic
    double phase = 0.0;    // harmonic, radians
    double start = 0.0;    // harmonic and pulse
    double width = 0.0;    // pulse
    std::vector<double> times, values; // table: linear between, zero after the last
};

// [[ground_motion]]: a uniform base acceleration in x or y (model units), sampled every
// time_step from t = 0; zero after the record ends.
struct GroundMotionSpec {
    int direction = 0; // 0: x, 1: y
    double time_step = 0.0;
    std::vector<double> acceleration;
    std::string source; // the file it came from, for messages and run.json
};

// [[initial_velocity]]: a rigid velocity v + ω × (x − about) of the nodes named, their
// rotations turning at ω.
struct InitialVelocity {
    int node = 0;
    std::array<double, 2> velocity{0.0, 0.0};
    double rotation_rate = 0.0;
};

// [damping]: Rayleigh, C = α_M M + β_K K, by two modes' ratio or by its coefficients. The K
// is OpenSees' choice of `rayleigh αM βK βKinit βKcomm`: the tangent at each iteration, the
// initial (the unloaded, undeformed structure's), or the last committed step's.
struct DampingSpec {
    enum class Stiffness { initial, tangent, committed } stiffness = Stiffness::committed;
    std::optional<double> ratio;   // ζ of modes[0] and modes[1]; else alpha_m, beta_k as given
    std::array<int, 2> modes{1, 2};
    double alpha_m = 0.0;
    double beta_k = 0.0;
    bool present() const { return ratio.has_value() || alpha_m != 0.0 || beta_k != 0.0; }
};

struct DynamicsSpec {
    MassKind mass = MassKind::consistent;
    std::vector<NodalMass> masses;
    std::vector<TimeSeriesSpec> series;
    std::vector<GroundMotionSpec> ground_motions;
    std::vector<InitialVelocity> initial_velocities;
    DampingSpec damping;
    // Whether anything makes the structure move in time without a static load.
    bool excites() const { return !series.empty() || !ground_motions.empty() || !initial_velocities.empty(); }
};

} // namespace plastica
