// A basic law loaded into its plastic range in ten committed steps to `loaded`, then on to
// 1.05 × `loaded`: there, central differences of its end forces against its tangent, column by
// column.
#pragma once

#include "element/basic_law.hpp"
#include "section_shapes.hpp"

#include <catch2/catch.hpp>

namespace plastica::testing {

// A 10 × 20 rectangle of 20 fibres in a steel hardening at 2 % (fy/E = 1.25e-3), for the
// plastic zone: its tangents are smooth between the fibres' kinks.
inline SectionSpec hardening_rectangle(Formulation formulation) {
    SectionSpec s = rectangle_section(2e5, 10.0, 20.0, 20);
    s.steel = bilinear_steel(2e5, 250.0);
    s.steel->law = "kinematic_hardening";
    s.steel->parameters["hardening_ratio"] = 0.02;
    s.plasticity = Plasticity::distributed;
    s.formulation = formulation;
    return s;
}

// h: the step per deformation, small beside the distance to the next fibre's kink.
inline void check_tangent_past(BasicLaw& law, const Eigen::Vector3d& loaded, const Eigen::Vector3d& h) {
    Eigen::Vector3d q;
    Eigen::Matrix3d k;
    for (int step = 1; step <= 10; ++step) {
        law.trial(loaded * (step / 10.0), q, k);
        REQUIRE(law.states_consistent());
        law.commit();
    }
    const Eigen::Vector3d e = loaded * 1.05;
    law.trial(e, q, k);
    REQUIRE(law.states_consistent());
    for (int j = 0; j < 3; ++j) {
        Eigen::Vector3d plus = e, minus = e, q_plus, q_minus;
        Eigen::Matrix3d unused;
        plus[j] += h[j];
        minus[j] -= h[j];
        law.trial(plus, q_plus, unused);
        law.trial(minus, q_minus, unused);
        const Eigen::Vector3d column = (q_plus - q_minus) / (2.0 * h[j]);
        CAPTURE(j, column.transpose(), k.col(j).transpose());
        CHECK((column - k.col(j)).norm() <= 1e-5 * k.col(j).norm());
    }
}

} // namespace plastica::testing
