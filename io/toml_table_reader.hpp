// Reads one TOML table with located errors: typed, range-checked values, and at the end a
// check that every key was known (with the nearest valid key as a suggestion). Given the
// scene's units, a number of a named dimension may also be written as a string with its unit.
#pragma once

#include "scene_error.hpp"
#include "units.hpp"

#include <toml++/toml.h>

#include <array>
#include <initializer_list>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace plastica {

class TomlTableReader {
public:
    TomlTableReader(const toml::table& table, std::string file, std::string path, const UnitSystem* units = nullptr);

    bool has(const std::string& key) const;
    int line_of(const std::string& key) const;
    int line() const { return line_; }
    const std::string& file() const { return file_; }
    std::string qualified(const std::string& key) const;

    // A number, or with a [units] table a string "value unit" of dimension `d` (none: numbers only).
    double number(const std::string& key, Dimension d = dimension::none);   // required, finite
    double positive(const std::string& key, Dimension d = dimension::none); // required, > 0
    std::optional<double> optional_number(const std::string& key, Dimension d = dimension::none);
    double number_or(const std::string& key, double fallback, Dimension d = dimension::none);
    double positive_or(const std::string& key, double fallback, Dimension d = dimension::none);
    int integer(const std::string& key, int min, int max);
    int integer_or(const std::string& key, int fallback, int min, int max);
    bool boolean_or(const std::string& key, bool fallback);
    std::string string(const std::string& key);
    std::string string_or(const std::string& key, const std::string& fallback);
    std::string choice(const std::string& key, std::initializer_list<const char*> options,
                       const std::string& fallback);
    std::string choice(const std::string& key, const std::vector<std::string>& options, const std::string& fallback);
    std::array<double, 2> point(const std::string& key, Dimension d = dimension::none);
    // A point [x, y] given as an item of an array under `key` (a list of points).
    std::array<double, 2> point_in(const toml::node& item, const std::string& key, Dimension d = dimension::none) const;
    const UnitSystem* units() const { return units_; }
    const toml::node* node(const std::string& key);            // marks the key as used
    const toml::table* table(const std::string& key);
    const toml::array* array(const std::string& key);

    // Throws for the first key that was never read.
    void finish(std::initializer_list<const char*> known_keys) const;
    void finish(const std::vector<std::string>& known_keys) const;

    [[noreturn]] void fail(const std::string& key, const std::string& what) const;

private:
    // The value of a number node or a "value unit" string; nullopt for anything else.
    std::optional<double> value_of(const toml::node& n, const std::string& key, Dimension d) const;

    const toml::table& table_;
    std::string file_;
    std::string path_;
    int line_;
    std::set<std::string> used_;
    const UnitSystem* units_;
};

int line_of(const toml::node& node);
std::string nearest_key(const std::string& key, const std::vector<std::string>& candidates);

} // namespace plastica
