// The scene's keys, declared once: for every table its keys with their type, range, dimension,
// default and documentation. The reader validates against it (TomlTableReader), unknown keys
// and `--set` paths are suggested from it, `plastica study` finds the keys it varies in it, and
// the key tables of models/README.md are generated from it (`plastica schema --scene`, checked by
// tests/test_scene_schema.cpp).
#pragma once

#include "units.hpp"

#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace plastica {

enum class ValueKind {
    number,  // a float (or, with [units], a string with its unit)
    integer, // a whole number
    boolean,
    string,
    choice,  // one of a list of strings
    point,   // [x, y]
    other,   // a list or a mixed value the reader checks itself; its type is written out
};

struct KeyRange {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool min_open = false, max_open = false;
    bool contains(double v) const;
    bool bounded() const;
};

using FixedDefault = std::variant<std::monostate, double, bool, std::string>;

struct KeySpec {
    std::string name;
    ValueKind kind = ValueKind::number;
    Dimension dimension = dimension::none;
    std::string dimension_text; // when the dimension follows other keys: how ("a length; rz: none")
    KeyRange range;
    std::vector<std::string> choices;
    FixedDefault fixed_default;  // the value when the key is left out, if it is fixed
    std::string default_text;    // the documented default when it follows from other keys
    bool required = false;
    std::string type_text;       // for ValueKind::other (and a choice that also takes a point)
    std::string group;           // the key belongs to tables whose group key has this value
    bool studied = false;        // `plastica study` may vary it
    std::string doc;

    // Chained declarations: number("E", dimension::stress).positive().required().about("…").
    KeySpec& positive() { range.min = 0.0, range.min_open = true; return *this; }
    KeySpec& at_least(double v) { range.min = v; return *this; }
    KeySpec& between(double lo, double hi) { range.min = lo, range.max = hi; return *this; }
    KeySpec& below(double hi) { range.max = hi, range.max_open = true; return *this; }
    KeySpec& needed() { required = true; return *this; }
    KeySpec& fallback(FixedDefault v) { fixed_default = std::move(v); return *this; }
    KeySpec& follows(std::string text) { default_text = std::move(text); return *this; }
    KeySpec& dimension_follows(std::string text) { dimension_text = std::move(text); return *this; }
    KeySpec& of(std::string g) { group = std::move(g); return *this; }
    KeySpec& varied_in_studies() { studied = true; return *this; }
    KeySpec& about(std::string text) { doc = std::move(text); return *this; }
    KeySpec& or_also(std::string type) { type_text = std::move(type); return *this; }

    // "number > 0, a stress", "whole number 1–16", "`"a"`, `"b"`" for the docs.
    std::string type_description() const;
    // "required", "1e-6", "10 × increment", or "" when there is none.
    std::string default_description() const;
};

KeySpec number(std::string name, Dimension d = dimension::none);
KeySpec whole(std::string name, int min, int max);
KeySpec flag(std::string name, bool fallback);
KeySpec text(std::string name);
KeySpec one_of(std::string name, std::vector<std::string> choices);
KeySpec point(std::string name, Dimension d = dimension::none);
KeySpec other(std::string name, std::string type_text);

struct TableSpec {
    std::string name;
    bool array = false;          // [[name]] rather than [name]
    std::string group_key;       // a key whose value selects further keys ("shape", "law")
    std::vector<KeySpec> keys;

    // The key for a table whose group key has the value `group` ("" = none chosen yet); null if
    // the table declares no such key there.
    const KeySpec* find(const std::string& key, const std::string& group = "") const;
    // The key as declared in any group (for "a key of shape = …" messages); null if undeclared.
    const KeySpec* find_anywhere(const std::string& key) const;
    std::vector<std::string> key_names(const std::string& group) const; // ungrouped keys and the group's
    std::vector<std::string> all_key_names() const;
    std::string heading() const { return name.empty() ? "the top level" : array ? "[[" + name + "]]" : "[" + name + "]"; }
};

// Every table of a scene file, in the order a scene is read.
const std::vector<TableSpec>& scene_schema();
// The table named so; throws std::logic_error for a name the schema does not declare.
const TableSpec& scene_table(const std::string& name);
const TableSpec* find_scene_table(const std::string& name);
// The file's top level: the tables themselves as its keys.
const TableSpec& scene_root_table();
std::vector<std::string> scene_table_names();

// The keys `plastica study` may vary, each once, in the order declared.
std::vector<std::string> studied_keys();

// A table's keys as a Markdown table (key, type, default, meaning), with the markers that
// models/README.md keeps around it.
std::string scene_keys_markdown(const TableSpec& table);
std::string scene_keys_begin_marker(const TableSpec& table);
inline const char* scene_keys_end_marker() { return "<!-- end of generated keys -->"; }

} // namespace plastica
