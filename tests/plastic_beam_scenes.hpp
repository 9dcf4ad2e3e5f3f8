// Scenes of plastic theory shared by the hinge and the distributed-plasticity tests: a steel
// rectangle 10 × 20 whose collapse displacements are tiny (fy/E = 1.25e-6), so first-order
// plastic theory holds; with an even number of fibres M_p = fy·b·h²/4 = 250 000 exactly.
#pragma once

#include "analysis_helpers.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include <string>

namespace plastica::testing {

constexpr double rectangle_Mp = 250.0 * 10.0 * 20.0 * 20.0 / 4.0;

// Scene header with material and section "s"; `plasticity` is a value of the section key.
inline std::string plastic_beam_header(const std::string& plasticity) {
    return "[scene]\nname = \"plastic\"\n[[material]]\nname = \"steel\"\nE = 2.0e8\nfy = 250.0\n"
           "[[section]]\nname = \"s\"\nmaterial = \"steel\"\nshape = \"rectangle\"\nb = 10.0\nh = 20.0\n"
           "fibres = 10\nplasticity = \"" + plasticity + "\"\n" +
           // The tests of plastic-zone members by displacement name it: left open, a scene
           // without contact takes force-based members.
           (plasticity == "distributed" ? "formulation = \"displacement\"\n" : "");
}

// A fixed-fixed beam 2000 long of section "s" under a central point load (elements: a count,
// or a placeholder the caller replaces).
inline std::string fixed_fixed_beam(const std::string& elements) {
    return "[[line]]\nstart = [0.0, 0.0]\nend = [2000.0, 0.0]\nelements = " + elements +
           "\nsection = \"s\"\n[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n"
           "[[support]]\nat = [2000.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n[[load]]\nat = [1000.0, 0.0]\nfy = -1.0\n";
}

// The same span propped at its right end (uy only).
inline std::string propped_cantilever(const std::string& elements) {
    return "[[line]]\nstart = [0.0, 0.0]\nend = [2000.0, 0.0]\nelements = " + elements +
           "\nsection = \"s\"\n[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n"
           "[[support]]\nat = [2000.0, 0.0]\nfix = [\"uy\"]\n[[load]]\nat = [1000.0, 0.0]\nfy = -1.0\n";
}

// A fixed-base portal frame of section "s", 4000 high and 8000 wide (4, 8 and 4 elements),
// under H = V = λ: H at the left joint, V at mid-span. Beam mechanism 8Mp/L = Mp/1000, sway
// 4Mp/h = Mp/1000, combined λ(H h + V L/2) = 6 Mp → λ = 0.75 Mp/1000, which governs.
inline std::string portal_frame() {
    return R"([[line]]
start = [0.0, 0.0]
end = [0.0, 4000.0]
elements = 4
section = "s"
[[line]]
start = [0.0, 4000.0]
end = [8000.0, 4000.0]
elements = 8
section = "s"
[[line]]
start = [8000.0, 4000.0]
end = [8000.0, 0.0]
elements = 4
section = "s"
[[support]]
at = [0.0, 0.0]
fix = ["ux", "uy", "rz"]
[[support]]
at = [8000.0, 0.0]
fix = ["ux", "uy", "rz"]
[[load]]
at = [0.0, 4000.0]
fx = 1.0
[[load]]
at = [4000.0, 4000.0]
fy = -1.0
)";
}

// Displacement control of one DOF ("ux" pushes +x, "uy" pushes −y) to a target.
inline std::string displacement_control(double x, double y, const std::string& dof, double increment, double target) {
    return "[analysis]\nscheme = \"displacement_control\"\nincrement = " + num(increment) +
           "\nadaptive = false\ncontrol_at = [" + num(x) + ", " + num(y) + "]\ncontrol_dof = \"" + dof +
           "\"\ncontrol_sign = " + (dof == "uy" ? "-1.0" : "1.0") + "\ntarget_displacement = " + num(target) +
           "\nmax_steps = 2000\n";
}

// A cantilever 1000 long of a 10 × 20 rectangle (400 layers, distributed plasticity with four
// points) under a tip load P in 50 equal steps; material_keys add to E and fy (a law).
inline std::string tip_loaded_rectangle_cantilever(double E, double fy, const std::string& material_keys, int elements, double P) {
    return "[scene]\nname = \"tip\"\n[[material]]\nname = \"steel\"\nE = " + num(E) + "\nfy = " + num(fy) + "\n" +
           material_keys +
           "[[section]]\nname = \"s\"\nmaterial = \"steel\"\nshape = \"rectangle\"\nb = 10.0\nh = 20.0\nfibres = 400\n"
           "plasticity = \"distributed\"\nformulation = \"displacement\"\nintegration_points = 4\n"
           "[[line]]\nstart = [0.0, 0.0]\nend = [1000.0, 0.0]\nelements = " + std::to_string(elements) +
           "\nsection = \"s\"\n[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n"
           "[[load]]\nat = [1000.0, 0.0]\nfy = -1.0\n"
           "[analysis]\nscheme = \"load_control\"\nincrement = " + num(P / 50.0) +
           "\nadaptive = false\ntarget_load_factor = " + num(P) + "\nresidual_tolerance = 1e-10\nmax_steps = 100\n";
}

// tests/frames/portal_weak_columns.toml (HEB 200 columns, IPE 300 beam, 250 kN on each column
// top and 100 kN sideways, × λ) with fibre sections along every member: `section_keys` follow
// plasticity = "distributed"; n elements per member, fixed increments of 0.001 of sway.
inline std::string weak_column_portal_in_fibres(int elements, const std::string& section_keys) {
    std::string text = scene_file_text("tests/frames/portal_weak_columns.toml");
    for (std::size_t at = text.find("elements = 8"); at != std::string::npos; at = text.find("elements = 8", at + 1))
        text.replace(at, 12, "elements = " + std::to_string(elements));
    for (const std::string web : {"web_thickness = 0.009\n", "web_thickness = 0.0071\n"})
        text.replace(text.find(web), web.size(),
                     web + "plasticity = \"distributed\"\n" +
                         (section_keys.find("formulation") == std::string::npos ? "formulation = \"displacement\"\n" : "") + section_keys);
    text.replace(text.find("increment = 0.002"), 17, "increment = 0.001\nadaptive = false");
    return text;
}

// The peak load factor of a run; with a tolerance > 0, also checks that every section of every
// step carries its element's axial force within it.
inline double peak_load_factor(const Run& run, double axial_tolerance = 0.0) {
    double peak = 0.0;
    for (const StepResult& s : run.steps) {
        peak = std::max(peak, s.load_factor);
        if (axial_tolerance <= 0.0) continue;
        for (const ElementResult& e : s.elements)
            for (const SectionReport& section : e.sections) CHECK(std::abs(section.axial_force - e.forces.axial) < axial_tolerance);
    }
    return peak;
}

} // namespace plastica::testing
