// Names and texts that come from a scene, a command line or a result folder someone else wrote:
// what may become part of a file name, and what a text field may hold.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace plastica {

// 1 to 64 letters, digits, '_' or '-': a scene's name, which names its output folder and files.
bool is_plain_name(const std::string& name);
// Any name as a file stem of that alphabet: other characters become '_', and it is cut to 64
// characters. "HEB 200" → "HEB_200", "../x" → "___x".
std::string file_stem_for(const std::string& name);
// A relative path of plain components (no '..', no '.', no empty or absolute part, no control
// character): a file named inside a folder by what that folder holds.
bool is_plain_relative_path(const std::string& path);
// Why a text may not be used, or nothing: a NUL or another control character (tab aside), or
// more than max_bytes bytes. The reason names the first offending character's position.
std::optional<std::string> text_problem(const std::string& text, std::size_t max_bytes);
// Control characters (tab included) or NUL anywhere: a value that must stay on one line and be
// one argument of a command.
bool has_control_character(const std::string& text);

} // namespace plastica
