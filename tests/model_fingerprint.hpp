// A scene's model as text, bit for bit, for tests that compare two ways of writing one scene.
#pragma once

#include "analysis/path_following.hpp"
#include "model/model.hpp"

#include <sstream>
#include <string>

namespace plastica {

// What a scene makes of its keys, bit for bit: the model's main values and two steps of its run.
inline std::string fingerprint(Model m) {
    std::ostringstream s;
    s.precision(17);
    s << m.name << '|' << m.title << '|' << m.nodes.size() << '|' << m.elements.size() << '|' << m.sections.size() << '|'
      << m.supports.size() << '|' << m.loads.size() << '|' << m.springs.size() << '|' << m.stages.size() << '|'
      << m.report.load_label << '|' << m.report.displacement_label << '|' << m.report.load_scale << '|'
      << m.report.length_unit << m.report.force_unit << '|' << static_cast<int>(m.analysis.scheme) << '|'
      << m.analysis.initial_increment << '|' << m.analysis.max_steps << '|' << m.analysis.residual_tolerance << '|'
      << m.analysis.target_load_factor.value_or(-1) << '|' << m.analysis.target_displacement.value_or(-1) << '|';
    for (const Node& n : m.nodes) s << n.x << ',' << n.y << ';';
    s << m.analysis.max_iterations << '|' << m.analysis.min_increment << '|' << m.analysis.max_increment << '|'
      << m.analysis.allow_crossing << '|' << m.analysis.displacement_tolerance << '|';
    for (const SectionSpec& sec : m.sections) {
        s << sec.name << ',' << sec.area << ',' << sec.inertia << ',' << sec.fibres.size() << ',' << sec.mass_per_length << ',';
        if (sec.steel) {
            s << sec.steel->fy << ',' << sec.steel->ultimate_strain << ',' << sec.steel->law;
            for (const auto& [key, value] : sec.steel->parameters) s << ',' << key << '=' << value;
        }
        s << ';';
    }
    for (const NodalLoad& l : m.loads) s << l.node << ':' << l.value[0] << ',' << l.value[1] << ',' << l.value[2] << ';';
    for (const FoundationSpring& f : m.springs)
        s << f.kx << ',' << f.ky << ',' << f.krot << ',' << f.unilateral << f.anchored << f.base << ',' << f.direction[0] << ',' << f.direction[1] << ';';
    for (const BaseLine& b : m.bases)
        s << b.point[0] << ',' << b.point[1] << ',' << b.normal[0] << ',' << b.normal[1] << ',' << b.motion[0] << ',' << b.motion[1] << ',' << b.pattern << ';';
    for (const SectionSpec& sec : m.sections)
        s << static_cast<int>(sec.plasticity) << static_cast<int>(sec.formulation) << ',' << sec.integration_points << ',' << sec.segments << ','
          << sec.segment_grading << ',' << sec.axial_strain_per_segment << ',' << sec.depth << ';';
    for (const StageSpec& st : m.stages)
        s << static_cast<int>(st.scheme) << ',' << st.increment << ',' << st.adaptive << ',' << st.pattern << ',' << st.control.node << ','
          << st.control.dof << ',' << st.control.sign << ';';
    s << m.analysis.control.node << ',' << m.analysis.control.dof << ',' << m.analysis.control.sign << ',' << m.analysis.pattern << ','
      << m.analysis.adaptive << ',' << m.analysis.desired_iterations << ',' << m.report.exact << ',' << m.report.mirror_x.value_or(-1e300) << '|';
    m.analysis.max_steps = 2;
    PathFollowing analysis(m);
    analysis.run({[&](const StepResult& r) {
        for (double u : r.displacement) s << u << ',';
    }});
    return s.str();
}

} // namespace plastica
