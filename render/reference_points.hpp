// Published or measured points to lay over the load–displacement chart (`--overlay-csv
// FILE:label`): a CSV of displacement, load pairs, one per line; a first line that is not
// numbers is a header; blank lines and lines starting with # are skipped.
#pragma once

#include <string>
#include <vector>

namespace plastica::render {

struct ReferencePoints {
    std::string label;
    std::vector<double> displacement, load;
};

// "FILE:label" (the label defaults to the file's name). Throws RenderError naming the file and
// the line at fault.
ReferencePoints read_reference_points(const std::string& file_and_label);

} // namespace plastica::render
