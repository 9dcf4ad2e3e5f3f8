#include "safe_names.hpp"

#include <algorithm>
#include <cctype>

namespace plastica {

namespace {
bool is_name_character(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; }
bool is_control(char c, bool tab_allowed) {
    const auto u = static_cast<unsigned char>(c);
    return (u < 0x20 && !(tab_allowed && c == '\t')) || u == 0x7f;
}
} // namespace

bool is_plain_name(const std::string& name) {
    return !name.empty() && name.size() <= 64 && std::all_of(name.begin(), name.end(), is_name_character);
}

std::string file_stem_for(const std::string& name) {
    std::string stem;
    for (char c : name.substr(0, 64)) stem += is_name_character(c) ? c : '_';
    return stem.empty() ? "_" : stem;
}

bool is_plain_relative_path(const std::string& path) {
    if (path.empty() || path.front() == '/' || has_control_character(path)) return false;
    std::size_t start = 0;
    while (start <= path.size()) {
        const std::size_t end = std::min(path.find('/', start), path.size());
        const std::string part = path.substr(start, end - start);
        if (part.empty() || part == "." || part == "..") return false;
        start = end + 1;
    }
    return true;
}

std::optional<std::string> text_problem(const std::string& text, std::size_t max_bytes) {
    if (text.size() > max_bytes)
        return "is " + std::to_string(text.size()) + " bytes long, more than the " + std::to_string(max_bytes) + " a text may have";
    for (std::size_t i = 0; i < text.size(); ++i)
        if (is_control(text[i], true))
            return std::string(text[i] == '\0' ? "holds a NUL character" : "holds a control character") + " at position " +
                   std::to_string(i + 1) + " (a text is printed, drawn and written into XML)";
    return std::nullopt;
}

bool has_control_character(const std::string& text) {
    return std::any_of(text.begin(), text.end(), [](char c) { return is_control(c, false); });
}

} // namespace plastica
