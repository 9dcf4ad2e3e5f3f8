#include "reference_points.hpp"
#include "render_error.hpp"

#include "bounded_file.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace plastica::render {

namespace {

// Two finite numbers separated by a comma (spaces allowed), or nothing.
bool parse_pair(const std::string& line, double& x, double& y) {
    std::string text = line;
    for (char& c : text)
        if (c == ',' || c == ';' || c == '\t') c = ' ';
    std::istringstream in(text);
    std::string rest;
    if (!(in >> x >> y) || (in >> rest)) return false;
    return std::isfinite(x) && std::isfinite(y);
}

} // namespace

ReferencePoints read_reference_points(const std::string& file_and_label) {
    ReferencePoints points;
    const std::string file = reference_points_file(file_and_label);
    if (file.size() < file_and_label.size()) points.label = file_and_label.substr(file.size() + 1);
    if (points.label.empty()) points.label = std::filesystem::path(file).stem().string();
    std::istringstream in;
    try {
        in.str(read_bounded_file(file, result_file_limit));
    } catch (const FileReadError& e) {
        throw RenderError(std::string(e.what()) + ": cannot read the reference points (--overlay-csv FILE:label)");
    }
    std::string line;
    bool header_seen = false;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::size_t start = line.find_first_not_of(" \t\r");
        if (start == std::string::npos || line[start] == '#') continue;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        double x = 0.0, y = 0.0;
        if (parse_pair(line, x, y)) {
            points.displacement.push_back(x);
            points.load.push_back(y);
        } else if (points.displacement.empty() && !header_seen) {
            header_seen = true; // the column names
        } else {
            throw RenderError(file + ":" + std::to_string(number) + ": expected 'displacement, load' as two numbers, got '" +
                              line.substr(0, 200) + "'");
        }
    }
    if (points.displacement.empty()) throw RenderError(file + ": no points (expected lines of 'displacement, load')");
    return points;
}

} // namespace plastica::render
