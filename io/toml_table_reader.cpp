#include "toml_table_reader.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace plastica {

int line_of(const toml::node& node) {
    return static_cast<int>(node.source().begin.line);
}

std::string nearest_key(const std::string& key, const std::vector<std::string>& candidates) {
    // Levenshtein distance; a suggestion is made only for a plausible misspelling.
    auto distance = [](const std::string& a, const std::string& b) {
        std::vector<std::size_t> row(b.size() + 1);
        for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
        for (std::size_t i = 1; i <= a.size(); ++i) {
            std::size_t diag = row[0];
            row[0] = i;
            for (std::size_t j = 1; j <= b.size(); ++j) {
                const std::size_t up = row[j];
                row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
                diag = up;
            }
        }
        return row[b.size()];
    };
    std::string best;
    std::size_t best_distance = 3;
    for (const std::string& c : candidates) {
        const std::size_t d = distance(key, c);
        if (d < best_distance) {
            best_distance = d;
            best = c;
        }
    }
    return best;
}

TomlTableReader::TomlTableReader(const toml::table& table, std::string file, std::string path, const UnitSystem* units)
    : table_(table), file_(std::move(file)), path_(std::move(path)),
      line_(plastica::line_of(static_cast<const toml::node&>(table))), units_(units) {}

bool TomlTableReader::has(const std::string& key) const { return table_.contains(key); }

int TomlTableReader::line_of(const std::string& key) const {
    const toml::node* n = table_.get(key);
    return n ? plastica::line_of(*n) : line_;
}

std::string TomlTableReader::qualified(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
}

void TomlTableReader::fail(const std::string& key, const std::string& what) const {
    throw SceneError(file_, key.empty() ? line_ : line_of(key), key.empty() ? path_ : qualified(key), what);
}

const toml::node* TomlTableReader::node(const std::string& key) {
    used_.insert(key);
    return table_.get(key);
}

std::optional<double> TomlTableReader::value_of(const toml::node& n, const std::string& key, Dimension d) const {
    if (n.is_number()) return n.value<double>();
    if (!n.is_string()) return std::nullopt;
    const std::string text = *n.value<std::string>();
    const auto fail_here = [&](const std::string& what) -> void {
        throw SceneError(file_, plastica::line_of(n), qualified(key), what);
    };
    if (d == dimension::none) fail_here("expected a number: this value is a pure number, without a unit");
    if (!units_)
        fail_here("\"" + text + "\" is a string: a value with a unit needs a [units] table naming the scene's units "
                  "(e.g. [units] length = \"m\", force = \"kN\"); without one, write a number");
    try {
        return units_->to_scene(text, d);
    } catch (const UnitError& e) {
        fail_here(e.what());
    }
    return std::nullopt;
}

double TomlTableReader::number(const std::string& key, Dimension d) {
    const toml::node* n = node(key);
    if (!n) fail("", "missing required key '" + key + "' (a number)");
    const std::optional<double> v = value_of(*n, key, d);
    if (!v) fail(key, d == dimension::none || !units_ ? "expected a number" : "expected a number, or a string with its unit");
    if (!std::isfinite(*v)) fail(key, "expected a finite number, got " + std::to_string(*v));
    return *v;
}

double TomlTableReader::positive(const std::string& key, Dimension d) {
    const double v = number(key, d);
    if (!(v > 0.0)) {
        std::ostringstream s;
        s << "expected a positive number, got " << v;
        fail(key, s.str());
    }
    return v;
}

std::optional<double> TomlTableReader::optional_number(const std::string& key, Dimension d) {
    if (!has(key)) {
        used_.insert(key);
        return std::nullopt;
    }
    return number(key, d);
}

double TomlTableReader::number_or(const std::string& key, double fallback, Dimension d) {
    return has(key) ? number(key, d) : (used_.insert(key), fallback);
}

double TomlTableReader::positive_or(const std::string& key, double fallback, Dimension d) {
    return has(key) ? positive(key, d) : (used_.insert(key), fallback);
}

int TomlTableReader::integer(const std::string& key, int min, int max) {
    const toml::node* n = node(key);
    if (!n) fail("", "missing required key '" + key + "' (a whole number)");
    if (!n->is_integer()) fail(key, "expected a whole number");
    const int64_t v = *n->value<int64_t>();
    if (v < min || v > max)
        fail(key, "expected a whole number from " + std::to_string(min) + " to " +
                      std::to_string(max) + ", got " + std::to_string(v));
    return static_cast<int>(v);
}

int TomlTableReader::integer_or(const std::string& key, int fallback, int min, int max) {
    return has(key) ? integer(key, min, max) : (used_.insert(key), fallback);
}

bool TomlTableReader::boolean_or(const std::string& key, bool fallback) {
    if (!has(key)) {
        used_.insert(key);
        return fallback;
    }
    const toml::node* n = node(key);
    if (!n->is_boolean()) fail(key, "expected true or false");
    return *n->value<bool>();
}

std::string TomlTableReader::string(const std::string& key) {
    const toml::node* n = node(key);
    if (!n) fail("", "missing required key '" + key + "' (a string)");
    if (!n->is_string()) fail(key, "expected a string");
    return *n->value<std::string>();
}

std::string TomlTableReader::string_or(const std::string& key, const std::string& fallback) {
    return has(key) ? string(key) : (used_.insert(key), fallback);
}

std::string TomlTableReader::choice(const std::string& key, std::initializer_list<const char*> options,
                                    const std::string& fallback) {
    return choice(key, std::vector<std::string>(options.begin(), options.end()), fallback);
}

std::string TomlTableReader::choice(const std::string& key, const std::vector<std::string>& options,
                                    const std::string& fallback) {
    const std::string v = string_or(key, fallback);
    std::string list;
    for (const std::string& o : options) {
        if (v == o) return v;
        list += (list.empty() ? "'" : ", '") + o + "'";
    }
    fail(key, "expected one of " + list + ", got '" + v + "'");
}

std::array<double, 2> TomlTableReader::point(const std::string& key, Dimension d) {
    const toml::node* n = node(key);
    if (!n) fail("", "missing required key '" + key + "' (a point [x, y])");
    return point_in(*n, key, d);
}

std::array<double, 2> TomlTableReader::point_in(const toml::node& item, const std::string& key, Dimension d) const {
    const toml::array* a = item.as_array();
    std::optional<double> x, y;
    if (a && a->size() == 2) x = value_of((*a)[0], key, d), y = value_of((*a)[1], key, d);
    if (!x || !y)
        throw SceneError(file_, plastica::line_of(item), qualified(key),
                         std::string("expected a point [x, y] of two numbers") + (units_ && d != dimension::none ? " (or strings with units)" : ""));
    if (!std::isfinite(*x) || !std::isfinite(*y)) throw SceneError(file_, plastica::line_of(item), qualified(key), "expected finite coordinates");
    return {*x, *y};
}

const toml::table* TomlTableReader::table(const std::string& key) {
    const toml::node* n = node(key);
    if (!n) return nullptr;
    if (!n->is_table()) fail(key, "expected a table");
    return n->as_table();
}

const toml::array* TomlTableReader::array(const std::string& key) {
    const toml::node* n = node(key);
    if (!n) return nullptr;
    if (!n->is_array()) fail(key, "expected an array");
    return n->as_array();
}

void TomlTableReader::finish(std::initializer_list<const char*> known_keys) const {
    finish(std::vector<std::string>(known_keys.begin(), known_keys.end()));
}

void TomlTableReader::finish(const std::vector<std::string>& known) const {
    for (auto&& [k, v] : table_) {
        const std::string key(k.str());
        if (used_.count(key) || std::find(known.begin(), known.end(), key) != known.end()) continue;
        const std::string near = nearest_key(key, known);
        throw SceneError(file_, plastica::line_of(v), qualified(key),
                         "unknown key" + (near.empty() ? std::string() : "; did you mean '" + near + "'?"));
    }
}

} // namespace plastica
