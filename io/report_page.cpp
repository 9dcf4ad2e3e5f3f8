#include "report_page.hpp"

#include "xml_text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
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

std::string file_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ReportError("cannot read " + path.string());
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// A picture embedded whole, with its caption.
std::string figure(const fs::path& picture, const std::string& caption) {
    const std::string type = picture.extension() == ".gif" ? "image/gif" : "image/png";
    return "<figure><img alt=\"" + xml_escaped(caption) + "\" src=\"data:" + type + ";base64," + base64(file_bytes(picture)) +
           "\"><figcaption>" + xml_escaped(caption) + "</figcaption></figure>\n";
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

} // namespace

std::string run_page(const std::string& folder) {
    const fs::path dir(folder);
    const fs::path run_json = dir / "run.json";
    if (!fs::exists(run_json)) throw ReportError(folder + " holds no run.json: not a result folder of plastica run");
    const nlohmann::json run = nlohmann::json::parse(file_bytes(run_json), nullptr, false);
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
    std::vector<std::pair<std::string, std::string>> rows{{"steps", number(run.value("steps", 0))},
                                                          {"Newton iterations", number(run.value("iterations", 0))},
                                                          {"cut steps", number(run.value("cut_steps", 0))}};
    if (run.contains("accepted_by"))
        rows.push_back({"accepted by the residual / by stagnation",
                        number(run["accepted_by"].value("residual", 0)) + " / " + number(run["accepted_by"].value("stagnation", 0))});
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
    // The pictures the folder holds.
    std::string pictures;
    for (const auto& [file, caption] : std::vector<std::pair<std::string, std::string>>{
             {"chart.png", load + " against " + displacement},
             {"contact_sheet.png", "nine steps across the run"},
             {"shapes.png", "deformed shapes"},
             {scene + ".gif", "the animation"}})
        if (fs::exists(dir / file)) pictures += figure(dir / file, caption);
    std::vector<fs::path> frames;
    if (fs::is_directory(dir / "frames"))
        for (const auto& f : fs::directory_iterator(dir / "frames"))
            if (f.path().extension() == ".png") frames.push_back(f.path());
    std::sort(frames.begin(), frames.end());
    if (!frames.empty()) {
        // Up to four key frames: the first, the last and two evenly between.
        std::vector<std::size_t> chosen;
        for (int k = 0; k < 4; ++k) {
            const std::size_t index = (frames.size() - 1) * static_cast<std::size_t>(k) / 3;
            if (chosen.empty() || chosen.back() != index) chosen.push_back(index);
        }
        pictures += "<h2>Key frames</h2>\n<div class=\"row\">\n";
        for (std::size_t index : chosen) pictures += figure(frames[index], frames[index].stem().string());
        pictures += "</div>\n";
    }
    body += pictures.empty() ? "<p>This folder holds no pictures (the run was made with --no-render or --curves-only).</p>\n"
                             : pictures;
    return page(scene + ": " + status, body);
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
