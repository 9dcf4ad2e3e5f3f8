// Scenes of plastic theory shared by the hinge and the distributed-plasticity tests: a steel
// rectangle 10 × 20 whose collapse displacements are tiny (fy/E = 1.25e-6), so first-order
// plastic theory holds; with an even number of fibres M_p = fy·b·h²/4 = 250 000 exactly.
#pragma once

#include "analysis_helpers.hpp"

#include <string>

namespace plastica::testing {

constexpr double rectangle_Mp = 250.0 * 10.0 * 20.0 * 20.0 / 4.0;

// Scene header with material and section "s"; `plasticity` is a value of the section key.
inline std::string plastic_beam_header(const std::string& plasticity) {
    return "[scene]\nname = \"plastic\"\n[[material]]\nname = \"steel\"\nE = 2.0e8\nfy = 250.0\n"
           "[[section]]\nname = \"s\"\nmaterial = \"steel\"\nshape = \"rectangle\"\nb = 10.0\nh = 20.0\n"
           "fibres = 10\nplasticity = \"" + plasticity + "\"\n";
}

// Displacement control of one DOF ("ux" pushes +x, "uy" pushes −y) to a target.
inline std::string displacement_control(double x, double y, const std::string& dof, double increment, double target) {
    return "[analysis]\nscheme = \"displacement_control\"\nincrement = " + num(increment) +
           "\nadaptive = false\ncontrol_at = [" + num(x) + ", " + num(y) + "]\ncontrol_dof = \"" + dof +
           "\"\ncontrol_sign = " + (dof == "uy" ? "-1.0" : "1.0") + "\ntarget_displacement = " + num(target) +
           "\nmax_steps = 2000\n";
}

} // namespace plastica::testing
