// Text inside XML and HTML attributes and elements: the five characters that would end them.
#pragma once

#include <string>

namespace plastica {

// Appends the escaped text to `out`.
inline void append_xml_escaped(std::string& out, const std::string& text) {
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&apos;"; break;
        default: out += c;
        }
    }
}

inline std::string xml_escaped(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    append_xml_escaped(out, text);
    return out;
}

} // namespace plastica
