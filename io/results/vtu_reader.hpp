// Reads back the VTU files of a result series (vtk_xml_format.hpp's layout: appended raw data,
// UInt64 headers, arrays as written or in LZ4 or zlib blocks) into the XmlDataset they were
// written from, value for value. The files may come from someone else (a CI artefact): every
// offset and size is checked against the file, and a file that does not hold what its tags say
// is refused with the reason.
#pragma once

#include "xml_dataset.hpp"

#include <stdexcept>
#include <string>

namespace plastica {

class VtuReadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The dataset of a VTU file's text; `name` stands for the file in messages.
XmlDataset parse_unstructured_grid(const std::string& text, const std::string& name);

} // namespace plastica
