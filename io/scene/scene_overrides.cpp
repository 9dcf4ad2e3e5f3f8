#include "scene_overrides.hpp"

#include "scene_reader.hpp"
#include "scene_schema.hpp"
#include "toml_table_reader.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

namespace plastica {

namespace {

struct Segment {
    std::string key;
    std::string selector; // inside [...]: an index from 1 or a name; empty for a plain key
    bool indexed = false;
};

[[noreturn]] void fail(const Override& o, const std::string& what) {
    throw SceneError("--set " + o.path, 0, "", what);
}

std::vector<Segment> split(const Override& o) {
    std::vector<Segment> segments;
    std::stringstream in(o.path);
    for (std::string part; std::getline(in, part, '.');) {
        Segment s;
        const auto open = part.find('[');
        if (open != std::string::npos) {
            if (part.back() != ']' || open == 0) fail(o, "expected KEY, KEY[index] or KEY[name] between the dots");
            s.key = part.substr(0, open);
            s.selector = part.substr(open + 1, part.size() - open - 2);
            s.indexed = true;
            if (s.selector.empty()) fail(o, "expected an index from 1 or a name inside [ ]");
        } else {
            s.key = part;
        }
        if (s.key.empty()) fail(o, "expected a key path such as analysis.increment or material[steel].fy");
        segments.push_back(s);
    }
    if (segments.empty()) fail(o, "expected a key path such as analysis.increment or material[steel].fy");
    return segments;
}

// The value as TOML; a bare word (distributed, hinges) is taken as a string.
toml::table parse_value(const Override& o) {
    try {
        return toml::parse("value = " + o.value);
    } catch (const toml::parse_error&) {
        const bool word = !o.value.empty() && std::all_of(o.value.begin(), o.value.end(), [](unsigned char c) {
            return std::isalnum(c) || c == '_' || c == '-';
        });
        if (!word) fail(o, "cannot read '" + o.value + "' as a TOML value (quote strings with spaces)");
        toml::table t;
        t.insert("value", o.value);
        return t;
    }
}

// A path is TABLE.KEY or TABLE[index or name].KEY of a table and key the scene schema declares.
void check_against_schema(const Override& o, const std::vector<Segment>& segments) {
    const auto suggestion = [](const std::string& name, const std::vector<std::string>& known) {
        const std::string near = nearest_key(name, known);
        return near.empty() ? std::string() : "; did you mean '" + near + "'?";
    };
    const TableSpec* table = find_scene_table(segments.front().key);
    if (!table) fail(o, "a scene has no table '" + segments.front().key + "'" + suggestion(segments.front().key, scene_table_names()));
    // A key of a table inside a key (a section's slab.width, rebars[2].area) is checked by the
    // reader of that table.
    const KeySpec* holder = segments.size() == 3 ? table->find_anywhere(segments[1].key) : nullptr;
    const bool nested = holder && holder->kind == ValueKind::other;
    if (segments.size() != 2 && !nested) fail(o, "expected " + table->name + (table->array ? "[index or name]" : "") + ".KEY");
    if (table->array && !segments.front().indexed)
        fail(o, "'" + table->name + "' is a list: name one, e.g. " + table->name + "[1]." + segments.back().key);
    if (!table->array && segments.front().indexed) fail(o, "[" + table->name + "] is one table, not a list");
    if (!nested && !table->find_anywhere(segments.back().key))
        fail(o, table->heading() + " has no key '" + segments.back().key + "'" + suggestion(segments.back().key, table->all_key_names()));
}

// Applies one override to the parsed scene; returns the path as the reader names it
// (tables of an array by their index from 1), to recognise the reader's errors.
std::string apply(toml::table& root, const Override& o) {
    const std::vector<Segment> segments = split(o);
    check_against_schema(o, segments);
    toml::table* table = &root;
    std::string canonical;
    for (std::size_t k = 0; k + 1 < segments.size(); ++k) {
        const Segment& s = segments[k];
        canonical += (canonical.empty() ? "" : ".") + s.key;
        toml::node* node = table->get(s.key);
        if (!s.indexed) {
            if (!node) node = &table->insert(s.key, toml::table{}).first->second;
            table = node->as_table();
            if (!table) fail(o, "'" + s.key + "' is not a table" + (node->is_array() ? " (a list: name one, e.g. " + s.key + "[1])" : ""));
            continue;
        }
        toml::array* list = node ? node->as_array() : nullptr;
        if (!list) fail(o, "the scene has no [[" + s.key + "]]");
        std::size_t chosen = list->size();
        if (std::all_of(s.selector.begin(), s.selector.end(), [](unsigned char c) { return std::isdigit(c); })) {
            // Compared as text first: an index of any length is refused without overflowing.
            const bool fits = s.selector.size() <= 9;
            chosen = fits ? std::stoul(s.selector) - 1 : list->size();
            if (chosen >= list->size())
                fail(o, "the scene has " + std::to_string(list->size()) + " [[" + s.key + "]] table(s), not " + s.selector);
        } else {
            std::vector<std::string> names;
            for (std::size_t i = 0; i < list->size(); ++i)
                if (const toml::table* t = (*list)[i].as_table()) {
                    names.push_back((*t)["name"].value_or(std::string()));
                    if (names.back() == s.selector) chosen = i;
                }
            if (chosen == list->size()) {
                const std::string near = nearest_key(s.selector, names);
                fail(o, "no [[" + s.key + "]] named '" + s.selector + "'" + (near.empty() ? std::string() : "; did you mean '" + near + "'?"));
            }
        }
        table = (*list)[chosen].as_table();
        if (!table) fail(o, "[[" + s.key + "]] " + s.selector + " is not a table");
        canonical += "[" + std::to_string(chosen + 1) + "]";
    }
    const Segment& last = segments.back();
    if (last.indexed) fail(o, "the last part of the path names a key, not a table");
    toml::table value = parse_value(o);
    table->insert_or_assign(last.key, std::move(*value.get("value")));
    return canonical + (canonical.empty() ? "" : ".") + last.key;
}

} // namespace

Override parse_override(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0) throw SceneError("--set " + text, 0, "", "expected KEY=VALUE, e.g. material[steel].fy=250");
    return {text.substr(0, eq), text.substr(eq + 1)};
}

Model read_scene(const std::string& path, const std::vector<Override>& overrides) {
    if (overrides.empty()) return read_scene(path);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path, 0, "", "cannot open the scene file");
    std::ostringstream text;
    text << in.rdbuf();
    return read_scene_text(text.str(), path, overrides);
}

Model read_scene_text(const std::string& text, const std::string& path, const std::vector<Override>& overrides) {
    toml::table root;
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        throw SceneError(path, static_cast<int>(e.source().begin.line), "", std::string(e.description()));
    }
    std::vector<std::pair<std::string, const Override*>> applied;
    for (const Override& o : overrides) applied.emplace_back(apply(root, o), &o);
    try {
        return read_scene_table(root, path);
    } catch (const SceneError& e) {
        // An error about an overridden key names the override, not a line of the file.
        for (auto it = applied.rbegin(); it != applied.rend(); ++it)
            if (e.key() == it->first) throw SceneError("--set " + it->second->path, 0, "", e.reason());
        throw;
    }
}

} // namespace plastica
