// The robustness matrix's crushing cases: the gallery's steel rings crushed between plates and
// its pipe flattened until the walls meet, under every scheme, with hardening and with the
// paper's perfectly plastic law.
#include "crushing_cases.hpp"

#include "embedded_scenes.hpp"
#include "robustness_cases.hpp"

#include <cmath>
#include <string>

namespace plastica {

using Steps = std::vector<StepResult>;

void append_crushing_cases(std::vector<StabilityCase>& cases) {
    const auto done = RunStatus::completed;
    // Steel rings crushed between plates to 65 % of their diameter (fibre sections, hardening
    // 1e-4·E): R/h 10, 20, 40 under load control of the plate's travel (as shipped), under
    // displacement control of the top and under arc length; the plate force within 0.95–1.07
    // of DeRuntz & Hodge's crush load (4M_p/R)/√(1 − (δ/D)²) from δ = 0.2 D on
    // (tests/test_crushing.cpp measures 0.962–1.059).
    // The same with refined plastic hinges of the hardening steel (rows hardening by b).
    for (const bool hinges : {false, true})
    for (const double r_over_h : {10.0, 20.0, 40.0})
        for (const char* scheme : {"load_control", "displacement_control", "arc_length"}) {
            const bool by_displacement = std::string(scheme) == "displacement_control";
            // The plates act along the members: 1e4·EI/R³ spread over the element length πR/50.
            const double h = 100.0 / r_over_h, k = 1e4 * 210000.0 * h * h * h / 12.0 / 1e6 / (M_PI * 100.0 / 50.0);
            std::vector<std::pair<std::string, std::string>> edits{{"h = 5.0", "h = " + std::to_string(h)},
                                                                   {"ky = \"3482 MPa\"", "ky = " + std::to_string(k)},
                                                                   {"ky = \"3482 MPa\"", "ky = " + std::to_string(k)}};
            if (by_displacement)
                edits.insert(edits.end(), {{"scheme = \"load_control\"", "scheme = \"displacement_control\""},
                                           {"target_load_factor = 130.0", "target_displacement = 130.0"}});
            else if (std::string(scheme) == "arc_length")
                edits.push_back({"scheme = \"load_control\"", "scheme = \"arc_length\""});
            if (hinges) edits.push_back({"plasticity = \"distributed\"", "plasticity = \"hinges\""});
            const double mp = 355.0 * h * h / 4.0;
            const std::string how = by_displacement ? ", displacement control" : std::string(scheme) == "arc_length" ? ", arc length" : ", load control of the plate";
            cases.push_back({hinges ? "steel ring crushed between plates, hardening hinges" : "steel ring crushed between plates, fibre sections",
                             "R/h " + std::to_string(static_cast<int>(r_over_h)) + how,
                             edited(embedded_scene("gallery/steel_ring_crushed"), edits), done,
                             [mp](const Steps& steps, const RunSummary&) -> std::string {
                                 const double R = 100.0, D = 2.0 * R, P0 = 4.0 * mp / R;
                                 if (steps.back().load_factor < 0.64 * D)
                                     return "the plates approached by " + std::to_string(steps.back().load_factor) + " only";
                                 for (const StepResult& r : steps) {
                                     if (r.load_factor < 0.2 * D) continue;
                                     const double ratio = r.load / (P0 / std::sqrt(1.0 - std::pow(r.load_factor / D, 2)));
                                     if (ratio < 0.95 || ratio > 1.07)
                                         return "P/P_DH = " + std::to_string(ratio) + " at δ = " + std::to_string(r.load_factor);
                                 }
                                 return "";
                             }});
        }
    // The same ring with the paper's law (elastic–perfectly plastic fibres, their default 30
    // layers), the scene's own plates along the members: R/h 10, 20, 40 × the three schemes to
    // 65 % of the diameter, within 0.95–1.05 of DeRuntz & Hodge from δ = 0.2 D on
    // (tests/test_member_contact.cpp measures 0.981–1.018).
    const std::pair<std::string, std::string> perfectly_plastic{"law = \"kinematic_hardening\"\nhardening_ratio = 1e-4\n", "law = \"bilinear\"\n"};
    for (const double r_over_h : {10.0, 20.0, 40.0})
        for (const char* scheme : {"load_control", "displacement_control", "arc_length"}) {
            const bool by_displacement = std::string(scheme) == "displacement_control";
            const double h = 100.0 / r_over_h, mp = 355.0 * h * h / 4.0;
            std::vector<std::pair<std::string, std::string>> edits{perfectly_plastic, {"h = 5.0", "h = " + std::to_string(h)},
                                                                   {"scheme = \"load_control\"", "scheme = \"" + std::string(scheme) + "\""}};
            if (by_displacement) edits.push_back({"target_load_factor = 130.0", "target_displacement = 130.0"});
            const std::string how = by_displacement ? ", displacement control" : std::string(scheme) == "arc_length" ? ", arc length" : ", load control of the plate";
            cases.push_back({"steel ring crushed between plates, perfectly plastic fibres",
                             "R/h " + std::to_string(static_cast<int>(r_over_h)) + how,
                             edited(embedded_scene("gallery/steel_ring_crushed"), edits), done,
                             [mp](const Steps& steps, const RunSummary&) -> std::string {
                                 const double D = 200.0, P0 = 4.0 * mp / 100.0;
                                 if (steps.back().load_factor < 0.64 * D)
                                     return "the plates approached by " + std::to_string(steps.back().load_factor) + " only";
                                 for (const StepResult& r : steps) {
                                     if (r.load_factor < 0.2 * D) continue;
                                     const double ratio = r.load / (P0 / std::sqrt(1.0 - std::pow(r.load_factor / D, 2)));
                                     if (std::abs(ratio - 1.0) > 0.05)
                                         return "P/P_DH = " + std::to_string(ratio) + " at δ = " + std::to_string(r.load_factor);
                                 }
                                 return "";
                             }});
        }
    // The flattening test: the steel ring pressed on until its walls meet (self-contact), under
    // load control of the plate's travel (as shipped), displacement control of the top and arc length.
    for (const char* scheme : {"load_control", "displacement_control", "arc_length"}) {
        const bool by_displacement = std::string(scheme) == "displacement_control";
        std::vector<std::pair<std::string, std::string>> edits;
        if (by_displacement)
            edits = {{"scheme = \"load_control\"", "scheme = \"displacement_control\""},
                     {"target_load_factor = 195.0", "target_displacement = 195.0"}};
        else if (std::string(scheme) == "arc_length")
            edits = {{"scheme = \"load_control\"", "scheme = \"arc_length\""}};
        cases.push_back({"steel pipe ring flattened until its walls meet",
                         by_displacement ? "displacement control" : std::string(scheme) == "arc_length" ? "arc length" : "load control of the plate",
                         edited(embedded_scene("gallery/steel_pipe_flattened"), edits), done,
                         [](const Steps& steps, const RunSummary&) -> std::string {
                             // The plate's travel (load control) or the top's (displacement control).
                             const double travel = std::max(steps.back().load_factor, steps.back().control_displacement);
                             if (travel < 195.0 - 1e-6) return "the walls came " + std::to_string(travel) + " closer only";
                             return steps.back().surface_contacts.empty() ? "the walls met without touching" : "";
                         }});
    }
    // Flattened with the paper's law, under load control of the plate and arc length. (Under displacement control the top stops 0.08 mm short of 2R − h,
    // its walls pressed together: the travel it controls no longer grows.)
    for (const char* scheme : {"load_control", "arc_length"}) {
        const auto edits = std::vector<std::pair<std::string, std::string>>{
            perfectly_plastic, {"scheme = \"load_control\"", "scheme = \"" + std::string(scheme) + "\""}};
        cases.push_back({"steel pipe ring flattened until its walls meet, perfectly plastic",
                         std::string(scheme) == "arc_length" ? "arc length" : "load control of the plate",
                         edited(embedded_scene("gallery/steel_pipe_flattened"), edits), done,
                         [](const Steps& steps, const RunSummary&) -> std::string {
                             if (steps.back().load_factor < 195.0 - 1e-6) return "the plate travelled " + std::to_string(steps.back().load_factor) + " only";
                             return steps.back().surface_contacts.empty() ? "the walls met without touching" : "";
                         }});
    }
}

} // namespace plastica
