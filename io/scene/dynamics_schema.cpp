#include "dynamics_schema.hpp"

namespace plastica {

std::vector<KeySpec> transient_keys(bool first) {
    std::vector<KeySpec> keys{
        number("time_step", dimension::time).positive()
            .about("`transient`: Δt of every step (a step that fails is cut and retaken, then grows back to it)"),
        number("duration", dimension::time).positive().about("`transient`: the stage's length in time"),
        one_of("integrator", {"newmark", "hht"}).fallback(std::string("newmark"))
            .about("`transient`: Newmark's average acceleration (γ = 1/2, β = 1/4: no numerical damping, period "
                   "elongation ≈ (ωΔt)²/12), or Hilber–Hughes–Taylor, which damps modes with ωΔt ≳ 1"),
        number("alpha").between(-1.0 / 3.0, 0.0).fallback(-0.05).about("`hht`: α in [−1/3, 0]; 0 is Newmark's average acceleration"),
    };
    if (first)
        keys.push_back(one_of("mass", {"consistent", "lumped"}).fallback(std::string("consistent"))
                           .about("members' mass matrix: `consistent` (Hermitian transverse, linear axial, rotary inertia, in the "
                                  "frame of each member's chord: 10 elements give a cantilever's first four frequencies within "
                                  "0.1 %) or `lumped` (ρAℓ/2 and ρIℓ/2 at each end: a diagonal matrix, frequencies low by "
                                  "O(ℓ²)); also `plastica modes`'"));
    return keys;
}

namespace {

TableSpec mass_table() {
    return {"mass", true, "", {
        point("at", dimension::length).about("the node's point"),
        whole("node", 0, 1'000'000'000).about("a node id instead of `at`"),
        number("m", dimension::mass).at_least(0.0).needed().about("the mass of each translation"),
        number("rotational", dimension::rotational_mass).at_least(0.0).fallback(0.0).about("the rotational inertia"),
    }};
}

TableSpec damping_table() {
    return {"damping", false, "", {
        number("ratio").between(0.0, 1.0).about("ζ of the two `modes`: Rayleigh's α_M = 2ζω₁ω₂/(ω₁+ω₂), β_K = 2ζ/(ω₁+ω₂), "
                                               "ω from the modes of the state where the first transient stage starts"),
        other("modes", "two whole numbers").follows("`[1, 2]`").about("the modes `ratio` is given for"),
        number("alpha_m", dimension::frequency).at_least(0.0).fallback(0.0).about("α_M of C = α_M M + β_K K, instead of `ratio`"),
        number("beta_k", dimension::time).at_least(0.0).fallback(0.0).about("β_K of C = α_M M + β_K K, instead of `ratio`"),
        one_of("stiffness", {"committed", "tangent", "initial"}).fallback(std::string("committed"))
            .about("the K of β_K, as OpenSees' `rayleigh` separates them: the last committed step's tangent (it follows "
                   "yielding and rotation, and stays fixed within a step), the tangent at each iteration, or the "
                   "undeformed, unloaded structure's (which damps rigid rotations of members that have turned)"),
    }};
}

TableSpec time_series_table() {
    return {"time_series", true, "kind", {
        text("pattern").needed().about("the load pattern whose factor follows the series in transient stages"),
        one_of("kind", {"harmonic", "pulse", "table"}).needed().about("the series' form"),
        number("amplitude").fallback(1.0).of("harmonic").about("the factor's amplitude"),
        number("period", dimension::time).positive().needed().of("harmonic").about("the period"),
        number("phase").fallback(0.0).of("harmonic").about("radians: amplitude·sin(2π(t − start)/period + phase)"),
        number("start", dimension::time).at_least(0.0).fallback(0.0).of("harmonic").about("zero before it"),
        number("amplitude").fallback(1.0).of("pulse").about("the pulse's peak factor"),
        number("start", dimension::time).at_least(0.0).fallback(0.0).of("pulse").about("the pulse begins"),
        number("width", dimension::time).positive().needed().of("pulse").about("its length; zero after it"),
        one_of("shape", {"half_sine", "rectangular", "triangular"}).fallback(std::string("half_sine")).of("pulse")
            .about("the pulse's form"),
        other("times", "list of increasing times").needed().of("table").about("the points in time"),
        other("values", "list of numbers").needed().of("table").about("the factor at each time: linear between, zero after the last"),
    }};
}

TableSpec ground_motion_table() {
    return {"ground_motion", true, "", {
        text("file").needed().about("a PEER AT2 record (four header lines, `NPTS`, `DT`, values in g), or a text file of "
                                     "accelerations, one or more a line, with `time_step`; relative to the scene file"),
        number("time_step", dimension::time).positive().follows("the AT2 header's DT").about("the record's sampling step"),
        one_of("direction", {"x", "y"}).fallback(std::string("x")).about("the base moves along this axis"),
        number("scale").fallback(1.0).about("multiplies the record"),
        other("units", "`\"g\"` or an acceleration").follows("`\"g\"`")
            .about("what one unit of the record is: g (9.80665 m/s² in the scene's units, which need [units]), or an "
                   "acceleration such as `\"1 m/s2\"`"),
    }};
}

TableSpec initial_velocity_table() {
    return {"initial_velocity", true, "", {
        other("on", "`\"all\"`, a `[[line]]`/`[[arc]]` name, or a list of names").about("the members whose nodes move"),
        point("at", dimension::length).about("one node instead of `on`"),
        whole("node", 0, 1'000'000'000).about("a node id instead of `at`"),
        point("v", dimension::velocity).fallback(0.0).about("[vx, vy] of the rigid velocity"),
        number("spin", dimension::frequency).fallback(0.0).about("ω of the rigid velocity v + ω × (x − about), radians per time"),
        point("about", dimension::length).follows("[0, 0]").about("the centre of `spin`"),
    }};
}

} // namespace

std::vector<TableSpec> dynamics_table_specs() {
    return {mass_table(), damping_table(), time_series_table(), ground_motion_table(), initial_velocity_table()};
}

} // namespace plastica
