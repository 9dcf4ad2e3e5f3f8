// Reads one TOML table of a scene with located errors: typed, range-checked values as the scene
// schema declares them (io/scene/scene_schema.hpp), and at the end a check that every key is declared
// (with the nearest declared key as a suggestion). Given the scene's units, a number of a named
// dimension may also be written as a string with its unit.
#pragma once

#include "scene_error.hpp"
#include "scene_schema.hpp"
#include "units.hpp"

#include <toml++/toml.h>

#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace plastica {

// The longest text a scene may hold (a title, a label, a name): drawn whole, so bounded.
inline constexpr std::size_t max_text_bytes = 1024;

class TomlTableReader {
public:
    // Reads `table` as io/scene/scene_schema.cpp declares `spec`: every typed read below takes the
    // key's type, range, dimension and default from there, and asking for a key the schema
    // does not declare is a programming error (std::logic_error).
    TomlTableReader(const toml::table& table, std::string file, std::string path, const TableSpec& spec,
                    const UnitSystem* units = nullptr);

    bool has(const std::string& key) const;
    int line_of(const std::string& key) const;
    int line() const { return line_; }
    const std::string& file() const { return file_; }
    std::string qualified(const std::string& key) const;

    // The value of the table's group key ("shape", "law") selects its further keys; a key of
    // another group is refused here, naming its group.
    void choose_group(const std::string& value);

    // A number (with [units], a string with its unit), in its declared range: left out, the
    // declared default, or an error if it is required. `d` where other keys set the dimension.
    double number(const std::string& key);
    double number(const std::string& key, Dimension d);
    // Left out: `fallback`, a default that follows from other keys.
    double number_or(const std::string& key, double fallback);
    double number_or(const std::string& key, double fallback, Dimension d);
    int integer(const std::string& key);
    int integer_or(const std::string& key, int fallback);
    bool boolean(const std::string& key);
    bool boolean_or(const std::string& key, bool fallback);
    // A string of at most max_text_bytes and no control character but tab.
    std::string string(const std::string& key);
    std::string string_or(const std::string& key, const std::string& fallback);
    std::string choice(const std::string& key);
    std::string choice_or(const std::string& key, const std::string& fallback);
    std::array<double, 2> point(const std::string& key);
    std::array<double, 2> point(const std::string& key, Dimension d);
    // A point [x, y] given as an item of an array under `key` (a list of points).
    std::array<double, 2> point_in(const toml::node& item, const std::string& key, Dimension d) const;
    const UnitSystem* units() const { return units_; }
    const toml::node* node(const std::string& key);            // marks the key as used
    const toml::table* table(const std::string& key);
    const toml::array* array(const std::string& key);

    // Throws for the first key the schema does not declare here, suggesting the nearest.
    void finish() const;

    [[noreturn]] void fail(const std::string& key, const std::string& what) const;

private:
    const KeySpec& declared(const std::string& key) const;
    // The value of a number node or a "value unit" string; nullopt for anything else.
    std::optional<double> value_of(const toml::node& n, const std::string& key, Dimension d) const;
    double checked_number(const KeySpec& k, Dimension d);
    std::optional<double> optional_number(const std::string& key, Dimension d); // nullopt when left out
    [[noreturn]] void missing(const KeySpec& k, const char* what) const;

    const toml::table& table_;
    std::string file_;
    std::string path_;
    int line_;
    std::set<std::string> used_;
    const TableSpec& spec_;
    std::string group_;
    const UnitSystem* units_;
};

// The message for a value outside a key's range ("expected a positive number, got -1").
std::string out_of_range_message(const KeySpec& k, double value);

int line_of(const toml::node& node);
std::string nearest_key(const std::string& key, const std::vector<std::string>& candidates);

} // namespace plastica
