// Published or measured points to lay over the load–displacement chart (`--overlay-csv
// FILE:label`): a CSV of displacement, load pairs, one per line; a first line that is not
// numbers is a header; blank lines and lines starting with # are skipped.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace plastica::render {

struct ReferencePoints {
    std::string label;
    std::vector<double> displacement, load;
};

// The file of "FILE:label": the label follows the last colon, unless that colon belongs to the
// path itself (a file of that whole name exists). Inline: the lean plastica names the file as an
// input of its run without linking the drawing.
inline std::string reference_points_file(const std::string& file_and_label) {
    const std::size_t colon = file_and_label.rfind(':');
    return colon == std::string::npos || std::filesystem::exists(file_and_label) ? file_and_label : file_and_label.substr(0, colon);
}

// "FILE:label" (the label defaults to the file's name). Throws RenderError naming the file and
// the line at fault.
ReferencePoints read_reference_points(const std::string& file_and_label);

} // namespace plastica::render
