// The N–M chart's path names its element end as Python and ParaView count it, from 0, with the
// member it belongs to.
#include "render_helpers.hpp"
#include "section_path.hpp"

#include <catch2/catch.hpp>

#include <string>

using namespace plastica;
using namespace plastica::testing;
using namespace plastica::render;

TEST_CASE("The most loaded end is named by its element from 0 and its member", "[render][sections]") {
    const Model model = read_scene(std::string(PLASTICA_SOURCE_DIR) + "/models/gallery/portal_frame.toml");
    const fs::path series = solved_series_of(model, 1000, "section_path");
    const SectionPath path = most_loaded_end(open_series(series.string()));
    // "element 23 (from 0), end j, member 'right column'": that element is the member's.
    const std::string prefix = "element ";
    REQUIRE(path.where.rfind(prefix, 0) == 0);
    const int element = std::stoi(path.where.substr(prefix.size()));
    REQUIRE(element >= 0);
    REQUIRE(static_cast<std::size_t>(element) < model.elements.size());
    const int member = model.elements[static_cast<std::size_t>(element)].member;
    REQUIRE(member >= 0);
    CHECK_THAT(path.where, Catch::Contains("(from 0)") && Catch::EndsWith("member '" + model.member_names[static_cast<std::size_t>(member)] + "'"));
    CHECK(path.axial_force.size() == path.moment.size());
}
