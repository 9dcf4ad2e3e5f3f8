// Helpers for tests: run a scene given as TOML text and keep every step's result.
#pragma once

#include "analysis/path_following.hpp"
#include "scene_error.hpp"
#include "scene_reader.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace plastica::testing {

struct Run {
    Model model;
    RunSummary summary;
    std::vector<StepResult> steps;
    std::vector<IterationTrace> trace;

    double node_dof(const StepResult& s, double x, double y, int dof) const {
        for (std::size_t k = 0; k < model.nodes.size(); ++k)
            if (std::hypot(model.nodes[k].x - x, model.nodes[k].y - y) < 1e-9 * (1 + std::abs(x) + std::abs(y)))
                return s.displacement[3 * k + dof];
        throw std::runtime_error("no node there");
    }
    double max_load() const {
        double m = -1e300;
        for (const StepResult& s : steps) m = std::max(m, s.load);
        return m;
    }
};

inline Run run_scene(const std::string& toml);
// Runs a model already read (a scene file with overrides, say) to its end.
inline Run run_model(Model model);

// The text of a scene file of the source tree, by its path relative to the tree.
inline std::string scene_file_text(const std::string& relative) {
    std::ifstream in(std::string(PLASTICA_SOURCE_DIR) + "/" + relative);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

inline Run run_scene_file(const std::string& relative) { return run_scene(scene_file_text(relative)); }

// A scene file of the source tree with each `from` (found once) replaced by its `to`.
inline std::string edited_scene(const std::string& relative, const std::vector<std::pair<std::string, std::string>>& edits) {
    std::string text = scene_file_text(relative);
    for (const auto& [from, to] : edits) {
        const std::size_t at = text.find(from);
        if (at == std::string::npos) throw std::runtime_error(relative + " has no '" + from + "'");
        text.replace(at, from.size(), to);
    }
    return text;
}

inline Run run_scene(const std::string& toml) { return run_model(read_scene_text(toml, "test.toml")); }

inline Run run_model(Model model) {
    Run r;
    r.model = std::move(model);
    PathFollowing analysis(r.model);
    r.summary = analysis.run({[&](const StepResult& s) { r.steps.push_back(s); }});
    r.trace = analysis.trace();
    return r;
}

// Linear interpolation of y at x along a path that passes x (first crossing).
template <class GetX, class GetY>
double value_at(const std::vector<StepResult>& steps, double x, GetX gx, GetY gy) {
    for (std::size_t k = 1; k < steps.size(); ++k) {
        const double x0 = gx(steps[k - 1]), x1 = gx(steps[k]);
        if ((x0 - x) * (x1 - x) <= 0.0 && x0 != x1)
            return gy(steps[k - 1]) + (gy(steps[k]) - gy(steps[k - 1])) * (x - x0) / (x1 - x0);
    }
    throw std::runtime_error("the path does not reach the requested value");
}

// The message a scene text is refused with, or "no error".
inline std::string scene_error_of(const std::string& text, const std::string& file_name) {
    try {
        read_scene_text(text, file_name);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "no error";
}

inline std::string num(double v) {
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", v);
    std::string s(b);
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0"; // TOML: a float, not an integer
    return s;
}

// A horizontal cantilever [0, L] clamped at x = 0 with n elements.
inline std::string cantilever(double L, int n, double E, double A, double I, const std::string& loads,
                              const std::string& analysis) {
    return "[scene]\nname = \"cantilever\"\n[[material]]\nname = \"m\"\nE = " + num(E) +
           "\n[[section]]\nname = \"s\"\nmaterial = \"m\"\nA = " + num(A) + "\nI = " +
           num(I) + "\n[[line]]\nstart = [0.0, 0.0]\nend = [" + num(L) +
           ", 0.0]\nelements = " + std::to_string(n) +
           "\nsection = \"s\"\n[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n" + loads +
           "[analysis]\n" + analysis;
}

} // namespace plastica::testing
