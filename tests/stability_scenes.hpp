// Scenes shared by the stability tests (test_buckling.cpp, test_bifurcation.cpp).
#pragma once

#include <string>

namespace plastica::testing {

// A column of length 1 along y, EI = 1, in `elements` elements, pressed by 1 at its top.
inline std::string column(const std::string& base_fix, const std::string& top_fix, int elements) {
    std::string top = top_fix.empty() ? "" : "[[support]]\nat = [0.0, 1.0]\nfix = [" + top_fix + "]\n";
    return R"(
[scene]
name = "column"
[[material]]
name = "m"
E = 1.0e3
[[section]]
name = "s"
material = "m"
A = 10.0
I = 1.0e-3
[[line]]
start = [0.0, 0.0]
end = [0.0, 1.0]
elements = )" + std::to_string(elements) + R"(
section = "s"
[[support]]
at = [0.0, 0.0]
fix = [)" + base_fix + "]\n" + top + R"(
[[load]]
at = [0.0, 1.0]
fy = -1.0
[analysis]
scheme = "load_control"
increment = 0.1
target_load_factor = 1.0
)";
}

} // namespace plastica::testing
