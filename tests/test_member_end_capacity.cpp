// Every member end of a hinged frame stays within its own capacity M_p(N) at its own axial
// force, and the utilisation it reports is that ratio (engine/analysis/hinge_allocation.hpp).
// The capacity checked against is the fibre polygon's, as `plastica section` prints it
// (engine/section/section_curves.hpp); the hinge's smooth curve through the polygon's corners
// lies on or above it by less than the 1e-3 allowed here for the I-sections tested.
#include "analysis_helpers.hpp"
#include "section/fibre_section.hpp"

#include <catch2/catch.hpp>

using namespace plastica;
using namespace plastica::testing;

namespace {

struct EndCheck {
    double worst = 0.0;          // largest |M| / M_p(N) over every step and hinged member end
    double worst_report_gap = 0.0; // largest |reported utilisation − that ratio|
    int worst_step = -1, worst_element = -1;
};

EndCheck check_member_ends(const Run& run) {
    std::vector<FibreSection> sections;
    for (const SectionSpec& s : run.model.sections) sections.emplace_back(s);
    EndCheck c;
    for (const StepResult& step : run.steps) {
        for (std::size_t e = 0; e < step.elements.size(); ++e) {
            const ElementResult& r = step.elements[e];
            if (!r.hinged) continue;
            const FibreSection& section = sections[run.model.elements[e].section];
            for (int end = 0; end < 2; ++end) {
                const double m = end == 0 ? r.forces.moment_i : r.forces.moment_j;
                const double cap = section.hinge_moment_capacity(r.forces.axial, m >= 0.0 ? 1.0 : -1.0);
                const double ratio = cap > 0.0 ? std::abs(m) / cap : 0.0;
                if (ratio > c.worst) c.worst = ratio, c.worst_step = step.step, c.worst_element = static_cast<int>(e);
                // The reported utilisation is the smooth hinge curve's ratio: within the curves'
                // difference of the polygon's.
                c.worst_report_gap = std::max(c.worst_report_gap, std::abs(r.hinge[end].utilisation - ratio));
            }
        }
    }
    return c;
}

Run run_frame(const std::string& relative) {
    return run_model(read_scene(std::string(PLASTICA_SOURCE_DIR) + "/" + relative));
}

} // namespace

TEST_CASE("No member end of a hinged frame exceeds its own M_p(N), and each reports its own utilisation", "[plasticity][frames]") {
    // Weak columns and a beam weaker at N = 0 (the joint's hinge belongs in the column once it
    // carries its axial load), a beam stronger at any N, one section throughout under heavy
    // gravity (the column's M_p(N) is a sixth below the beam's), two bays, three storeys, and
    // gravity held while the sway is pushed.
    const char* scene = GENERATE("tests/frames/portal_weak_columns.toml", "tests/frames/portal_strong_beam.toml",
                                 "tests/frames/three_storey_frame.toml", "tests/frames/portal_gravity_push.toml",
                                 "models/gallery/portal_frame.toml",
                                 "models/gallery/two_bay_frame.toml");
    CAPTURE(scene);
    const Run run = run_frame(scene);
    REQUIRE(run.summary.status == RunStatus::completed);
    const EndCheck c = check_member_ends(run);
    CAPTURE(c.worst, c.worst_step, c.worst_element, c.worst_report_gap);
    CHECK(c.worst <= 1.001);
    CHECK(c.worst_report_gap <= 1e-3);
    CHECK(c.worst > 0.99); // the frames are pushed far enough to form hinges
}

TEST_CASE("The ends of a reinforced-concrete column with hinges stay within their capacity by strain limits", "[plasticity][concrete]") {
    // The gallery's RC column with refined hinges: its ends yield at the section's capacity by
    // strain limits (the hinge's curve for a section with concrete), pushed far past the peak.
    std::string scene = scene_file_text("models/gallery/rc_column.toml");
    const std::string from = "plasticity = \"distributed\"\nformulation = \"force\"";
    scene.replace(scene.find(from), from.size(), "plasticity = \"hinges\"");
    const Run run = run_scene(scene);
    REQUIRE(run.summary.status == RunStatus::completed);
    const EndCheck c = check_member_ends(run);
    CAPTURE(c.worst, c.worst_step, c.worst_element, c.worst_report_gap);
    CHECK(c.worst <= 1.001);
    CHECK(c.worst > 0.99);
}
