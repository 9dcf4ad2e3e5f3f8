#include "report_page.hpp"

#include "bounded_file.hpp"
#include "safe_names.hpp"

#include "xml_text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace plastica {

namespace fs = std::filesystem;

namespace {


std::string base64(const std::string& bytes) {
    static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                           static_cast<unsigned char>(bytes[i + 2]);
        for (int shift : {18, 12, 6, 0}) out += alphabet[(v >> shift) & 63];
    }
    if (i < bytes.size()) {
        const bool two = i + 1 < bytes.size();
        const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (two ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0u);
        out += alphabet[(v >> 18) & 63];
        out += alphabet[(v >> 12) & 63];
        out += two ? alphabet[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

// A picture embedded whole, with its caption.
std::string figure_of_bytes(const std::string& bytes, const std::string& type, const std::string& caption) {
    return "<figure><img alt=\"" + xml_escaped(caption) + "\" src=\"data:" + type + ";base64," + base64(bytes) + "\"><figcaption>" +
           xml_escaped(caption) + "</figcaption></figure>\n";
}

std::string picture_type(const std::string& name) { return fs::path(name).extension() == ".gif" ? "image/gif" : "image/png"; }

// A picture of the result folder: read only inside it, never through a symbolic link.
std::string figure(const std::string& folder, const std::string& relative, const std::string& caption) {
    try {
        return figure_of_bytes(read_file_inside(folder, relative, picture_file_limit), picture_type(relative), caption);
    } catch (const FileReadError& e) {
        throw ReportError(e.what());
    }
}

// A picture the user named (a comparison's actual, reference and difference).
std::string figure(const fs::path& picture, const std::string& caption) {
    try {
        return figure_of_bytes(read_bounded_file(picture.string(), picture_file_limit), picture_type(picture.string()), caption);
    } catch (const FileReadError& e) {
        throw ReportError(e.what());
    }
}

const char* style = R"(<style>
body { font-family: sans-serif; margin: 2em; color: #191919; max-width: 1400px; }
h1 { margin-bottom: 0.2em; } .status { font-size: 1.1em; margin: 0.3em 0 1em; }
.completed { color: #1f7a3a; } .stopped { color: #b3261e; }
table { border-collapse: collapse; margin-bottom: 1.5em; } td, th { border: 1px solid #ccc; padding: 4px 10px; text-align: left; }
figure { display: inline-block; margin: 0 1em 1.5em 0; vertical-align: top; } img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 0.9em; color: #555; } .row figure { width: 31%; }
</style>
)";

// Counts the pictures that loaded, for a person and for a headless browser.
const char* loaded_script = R"(<p id="images-loaded">images not counted yet</p>
<script>
window.addEventListener('load', function () {
  var images = Array.prototype.slice.call(document.images);
  var loaded = images.filter(function (i) { return i.complete && i.naturalWidth > 0; }).length;
  document.getElementById('images-loaded').textContent = loaded + ' of ' + images.length + ' images loaded';
});
</script>
)";

std::string page(const std::string& title, const std::string& body) {
    return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + xml_escaped(title) + "</title>\n" + style +
           "</head><body>\n" + body + loaded_script + "</body></html>\n";
}

std::string number(const nlohmann::json& j) {
    if (!j.is_number()) return j.is_string() ? j.get<std::string>() : j.dump();
    std::ostringstream s;
    s.precision(6);
    s << j.get<double>();
    return s.str();
}

// The step of a frame_NNNNNN.png.
int frame_step(const fs::path& frame) {
    const std::string stem = frame.stem().string();
    const auto digits = stem.find_first_of("0123456789");
    return digits == std::string::npos ? -1 : std::atoi(stem.c_str() + digits);
}

// The frames named by what happens in them: the start, the first yield, the peak load and the
// last step, each the drawn frame nearest its step (frames that coincide share one picture and
// both names). Without a curve.csv: the first, the last and two evenly between.
std::vector<std::pair<fs::path, std::string>> key_frames(const std::vector<fs::path>& frames, const std::string& folder,
                                                         const std::string& load_label) {
    std::vector<std::pair<int, std::string>> events;
    std::istringstream in(is_file_inside(folder, "curve.csv") ? read_file_inside(folder, "curve.csv", result_file_limit) : "");
    std::string line;
    if (in && std::getline(in, line)) {
        std::vector<std::string> header;
        std::stringstream h(line);
        for (std::string name; std::getline(h, name, ',');) header.push_back(name);
        const auto column = [&](const char* name) {
            const auto at = std::find(header.begin(), header.end(), name);
            return at == header.end() ? -1 : static_cast<int>(at - header.begin());
        };
        const int step_column = column("step"), load_column = column("load"), hinge_column = column("hinge_count");
        const int critical_column = column("critical_point");
        int first = -1, last = -1, yield = -1, peak = -1, critical = -1;
        std::string critical_kind;
        double peak_load = -1e300;
        while (step_column >= 0 && load_column >= 0 && std::getline(in, line)) {
            std::vector<std::string> cells;
            std::stringstream r(line);
            for (std::string cell; std::getline(r, cell, ',');) cells.push_back(cell);
            if (static_cast<int>(cells.size()) <= std::max({step_column, load_column, hinge_column})) continue;
            const int step = std::atoi(cells[static_cast<std::size_t>(step_column)].c_str());
            const double value = std::atof(cells[static_cast<std::size_t>(load_column)].c_str());
            if (first < 0) first = step;
            last = step;
            if (value > peak_load) peak_load = value, peak = step;
            if (yield < 0 && hinge_column >= 0 && std::atoi(cells[static_cast<std::size_t>(hinge_column)].c_str()) > 0) yield = step;
            if (critical < 0 && critical_column >= 0 && static_cast<std::size_t>(critical_column) < cells.size() &&
                (cells[static_cast<std::size_t>(critical_column)] == "bifurcation" || cells[static_cast<std::size_t>(critical_column)] == "limit_point")) {
                critical = step;
                critical_kind = cells[static_cast<std::size_t>(critical_column)] == "bifurcation" ? "bifurcation" : "limit point";
            }
        }
        if (first >= 0) events.push_back({first, "start"});
        if (yield >= 0) events.push_back({yield, "first yield"});
        if (critical >= 0) events.push_back({critical, critical_kind});
        if (peak >= 0) events.push_back({peak, "peak " + load_label});
        if (last >= 0) events.push_back({last, "last step"});
    }
    std::vector<std::pair<fs::path, std::string>> chosen;
    if (events.empty()) {
        for (int k = 0; k < 4; ++k) {
            const fs::path& f = frames[(frames.size() - 1) * static_cast<std::size_t>(k) / 3];
            if (chosen.empty() || chosen.back().first != f) chosen.push_back({f, k == 0 ? "first drawn" : k == 3 ? "last drawn" : "between"});
        }
        return chosen;
    }
    std::sort(events.begin(), events.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& event : events) {
        const int step = event.first; // named, not a structured binding: lambdas capture it (C++17)
        const std::string& name = event.second;
        const fs::path& nearest = *std::min_element(frames.begin(), frames.end(), [&](const fs::path& a, const fs::path& b) {
            return std::abs(frame_step(a) - step) < std::abs(frame_step(b) - step);
        });
        if (!chosen.empty() && chosen.back().first == nearest) chosen.back().second += ", " + name;
        else chosen.push_back({nearest, name});
    }
    return chosen;
}

// A table with a header row; each row's cells already text.
std::string table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
    std::string t = "<table>\n<tr>";
    for (const std::string& h : header) t += "<th>" + xml_escaped(h) + "</th>";
    t += "</tr>\n";
    for (const auto& row : rows) {
        t += "<tr>";
        for (const std::string& cell : row) t += "<td>" + xml_escaped(cell) + "</td>";
        t += "</tr>\n";
    }
    return t + "</table>\n";
}

std::string point(const nlohmann::json& at) {
    return at.is_array() && at.size() == 2 ? "(" + number(at[0]) + ", " + number(at[1]) + ")" : "";
}

// The model the run computed (run.json "model", io/results/model_description.hpp): sections with their
// capacities, supports, loads by pattern, the analysis and its stages.
std::string model_section(const nlohmann::json& model) {
    std::string html = "<h2>Model</h2>\n";
    auto value = [](const nlohmann::json& j, const char* key) { return j.contains(key) ? number(j[key]) : std::string("–"); };
    std::vector<std::vector<std::string>> rows;
    for (const auto& s : model.value("sections", nlohmann::json::array()))
        rows.push_back({s.value("name", ""), value(s, "E"), value(s, "area"), value(s, "inertia"), value(s, "fy"),
                        s.value("plasticity", ""), value(s, "squash_load"), value(s, "plastic_moment")});
    // Column heads carry the scene's units where it names them ([units] or [report]).
    const std::string L = model.contains("units") ? model["units"].value("length", "") : "";
    const std::string F = model.contains("units") ? model["units"].value("force", "") : "";
    auto in = [&](const std::string& head, const std::string& unit) { return L.empty() || F.empty() ? head : head + " (" + unit + ")"; };
    if (!rows.empty())
        html += "<h3>Sections</h3>\n" + table({"section", in("E", F + "/" + L + "²"), in("A", L + "²"), in("I", L + "⁴"), in("fy", F + "/" + L + "²"),
                                                "plasticity", in("N_y (squash load)", F), in("M_p at N = 0", F + "·" + L)},
                                               rows);
    rows.clear();
    for (const auto& s : model.value("supports", nlohmann::json::array())) {
        std::string fixed;
        for (const auto& d : s.value("fixed", nlohmann::json::array())) fixed += (fixed.empty() ? "" : ", ") + d.get<std::string>();
        rows.push_back({point(s.value("at", nlohmann::json())), fixed});
    }
    if (!rows.empty()) html += "<h3>Supports</h3>\n" + table({"at", "fixed"}, rows);
    rows.clear();
    for (const auto& p : model.value("load_patterns", nlohmann::json::array()))
        if (p.value("loaded_nodes", 0) > 0 || p.contains("pressure_elements") || p.contains("prescribed_displacements"))
            rows.push_back({p.value("name", ""), value(p, "loaded_nodes"), value(p, "sum_fx"), value(p, "sum_fy"), value(p, "sum_moment"),
                        value(p, "pressure_elements"), value(p, "prescribed_displacements")});
    if (!rows.empty())
        html += "<h3>Loads by pattern (at factor 1; line loads lumped to nodes)</h3>\n" +
                table({"pattern", "loaded nodes", "Σ fx", "Σ fy", "Σ moment", "elements under pressure", "prescribed displacements"}, rows);
    if (model.contains("analysis")) {
        const auto& a = model["analysis"];
        std::string target;
        if (a.contains("target") && a["target"].is_object())
            for (const auto& [key, v] : a["target"].items()) target = key + " = " + number(v);
        std::string control;
        if (a.contains("control")) control = a["control"].value("dof", "") + " at " + point(a["control"].value("at", nlohmann::json()));
        rows = {{"scheme", a.value("scheme", "")}, {"pattern driven", a.value("pattern", "")}, {"first increment", value(a, "increment")},
                {"adaptive increments", a.value("adaptive", false) ? "yes" : "no"}, {"target", target}, {"controlled or reported DOF", control},
                {"residual tolerance", value(a, "residual_tolerance")}, {"Newton iterations per step at most", value(a, "max_iterations")},
                {"steps at most", value(a, "max_steps")}};
        html += "<h3>Analysis</h3>\n" + table({"setting", "value"}, rows);
    }
    rows.clear();
    int stage = 2;
    for (const auto& st : model.value("stages", nlohmann::json::array())) {
        std::string target;
        if (st.contains("target") && st["target"].is_object())
            for (const auto& [key, v] : st["target"].items()) target = key + " = " + number(v);
        rows.push_back({std::to_string(stage++), st.value("scheme", ""), st.value("pattern", ""), target});
    }
    if (!rows.empty()) html += "<h3>Further stages</h3>\n" + table({"stage", "scheme", "pattern driven", "target"}, rows);
    return html;
}

} // namespace

namespace {

std::string checked_run_page(const std::string& folder) {
    const fs::path dir(folder);
    const fs::path run_json = dir / "run.json";
    if (!is_file_inside(folder, "run.json")) throw ReportError(folder + " holds no run.json: not a result folder of plastica run");
    const nlohmann::json run = nlohmann::json::parse(read_file_inside(folder, "run.json", result_file_limit), nullptr, false);
    if (run.is_discarded() || !run.is_object() || run.value("program", "") != "plastica")
        throw ReportError(run_json.string() + " is not a run.json of plastica");
    const std::string scene = run.value("scene", "scene"), title = run.value("title", "");
    const std::string status = run.value("status", "unknown");
    std::string body = "<h1>" + xml_escaped(title.empty() ? scene : title) + "</h1>\n<p>scene <b>" + xml_escaped(scene) + "</b> from " +
                       xml_escaped(run.value("scene_file", "")) + ", " + number(run.value("nodes", 0)) + " nodes, " +
                       number(run.value("elements", 0)) + " elements</p>\n";
    body += "<p class=\"status " + std::string(status == "completed" ? "completed" : "stopped") + "\">" + xml_escaped(status) + ": " +
            xml_escaped(run.value("reason", "")) + "</p>\n";
    // The run's figures.
    const std::string load = run.value("load_label", "load"), displacement = run.value("displacement_label", "displacement");
    const int steps = run.value("steps", 0), refined = run.value("refined_steps", 0);
    std::vector<std::pair<std::string, std::string>> rows{
        {"steps (converged, each written)", number(steps)},
        {"Newton iterations (every attempt, cut and retaken ones too)", number(run.value("iterations", 0))},
        {"cut steps (attempts that failed, taken again smaller)", number(run.value("cut_steps", 0))}};
    if (refined > 0)
        rows.push_back({"refined steps (converged, taken again smaller: a hinge yielded too far in one step)", number(refined)});
    if (run.contains("accepted_by")) {
        // Every converged solve counts once by the rule that accepted it: the steps kept and the
        // refined ones taken again.
        const int residual = run["accepted_by"].value("residual", 0), stagnation = run["accepted_by"].value("stagnation", 0);
        std::string accepted = number(residual) + " / " + number(stagnation);
        if (residual + stagnation == steps + refined && refined > 0)
            accepted += " (" + number(steps) + " steps kept + " + number(refined) + " refined)";
        rows.push_back({"converged solves accepted by the residual / by stagnation (the residual stopped falling at round-off)", accepted});
    }
    if (run.contains("peak"))
        rows.push_back({"peak " + load + " (at " + displacement + ")",
                        number(run["peak"].value("load", 0.0)) + " (" + number(run["peak"].value("control_displacement", 0.0)) + ")"});
    if (run.contains("final"))
        rows.push_back({"final " + load + " (at " + displacement + ")",
                        number(run["final"].value("load", 0.0)) + " (" + number(run["final"].value("control_displacement", 0.0)) + ")"});
    if (run.contains("overrides"))
        for (const auto& [key, value] : run["overrides"].items()) rows.push_back({"--set " + key, number(value)});
    if (run.contains("seconds"))
        for (const auto& [stage, seconds] : run["seconds"].items()) rows.push_back({"seconds: " + stage, number(seconds)});
    body += "<table>\n";
    for (const auto& [name, value] : rows) body += "<tr><th>" + xml_escaped(name) + "</th><td>" + xml_escaped(value) + "</td></tr>\n";
    body += "</table>\n";
    if (run.contains("model")) body += model_section(run["model"]);
    // The pictures the folder holds.
    std::string pictures;
    for (const auto& [file, caption] : std::vector<std::pair<std::string, std::string>>{
             {"chart.png", load + " against " + displacement},
             {"contact_sheet.png", "nine steps across the run"},
             {"shapes.png", "deformed shapes"},
             {"hysteresis.png", "base shear against " + displacement},
             {"energy.png", "energy accounts in time"},
             // The scene's name names the animation only where it is a plain name: a run.json
             // from elsewhere may name anything.
             {is_plain_name(scene) ? scene + ".gif" : std::string(), "the animation"}})
        if (!file.empty() && is_file_inside(folder, file)) pictures += figure(folder, file, caption);
    std::vector<fs::path> frames;
    if (fs::is_directory(fs::symlink_status(dir / "frames")))
        for (const auto& f : fs::directory_iterator(dir / "frames"))
            if (f.path().extension() == ".png" && is_file_inside(folder, "frames/" + f.path().filename().string()))
                frames.push_back(f.path().filename());
    std::sort(frames.begin(), frames.end());
    if (!frames.empty()) {
        pictures += "<h2>Key frames</h2>\n<div class=\"row\">\n";
        for (const auto& [frame, name] : key_frames(frames, folder, load))
            pictures += figure(folder, "frames/" + frame.string(), name + " (" + frame.stem().string() + ")");
        pictures += "</div>\n";
    }
    body += pictures.empty() ? "<p>This folder holds no pictures (the run was made with --no-render or --curves-only).</p>\n"
                             : pictures;
    return page(scene + ": " + status, body);
}

} // namespace

std::string run_page(const std::string& folder) {
    try {
        return checked_run_page(folder);
    } catch (const FileReadError& e) {
        throw ReportError(e.what());
    } catch (const nlohmann::json::exception& e) {
        throw ReportError(folder + "/run.json: a value of the wrong type (" + std::string(e.what()) + ")");
    }
}

std::string comparison_page(const std::string& title, const std::string& summary, const std::vector<FailedPicture>& failed) {
    std::string body = "<h1>" + xml_escaped(title) + "</h1>\n<p class=\"status " + (failed.empty() ? "completed" : "stopped") + "\">" +
                       xml_escaped(summary) + "</p>\n";
    for (const FailedPicture& f : failed) {
        body += "<h2>" + xml_escaped(f.name) + "</h2>\n<p>" + xml_escaped(f.why) + "</p>\n<div class=\"row\">\n";
        for (const auto& [path, caption] : {std::pair{f.actual, "rendered now"}, std::pair{f.reference, "stored reference"},
                                            std::pair{f.diff, "difference (red: differing pixels)"}})
            body += !path.empty() && fs::exists(path) ? figure(path, caption) : "<figure><figcaption>" + std::string(caption) + ": none</figcaption></figure>\n";
        body += "</div>\n";
    }
    return page(title, body);
}

} // namespace plastica
