#include "toml_table_reader.hpp"

#include "safe_names.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
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

TomlTableReader::TomlTableReader(const toml::table& table, std::string file, std::string path, const TableSpec& spec,
                                 const UnitSystem* units)
    : table_(table), file_(std::move(file)), path_(std::move(path)),
      line_(plastica::line_of(static_cast<const toml::node&>(table))), spec_(spec), units_(units) {}

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

const KeySpec& TomlTableReader::declared(const std::string& key) const {
    if (const KeySpec* k = spec_.find(key, group_)) return *k;
    throw std::logic_error("io/scene/scene_schema.cpp declares no key '" + key + "' in " + spec_.heading() +
                           (group_.empty() ? "" : " for " + spec_.group_key + " = \"" + group_ + "\""));
}

void TomlTableReader::missing(const KeySpec& k, const char* what) const {
    // A misspelt key is the likelier mistake than a forgotten one: named first, at its own line.
    const std::vector<std::string> known = spec_.key_names(group_);
    for (auto&& [name, value] : table_) {
        const std::string key(name.str());
        if (std::find(known.begin(), known.end(), key) == known.end() && nearest_key(key, {k.name}) == k.name)
            throw SceneError(file_, plastica::line_of(value), qualified(key),
                             "unknown key; did you mean '" + k.name + "'? (missing required key '" + k.name + "', " + what + ")");
    }
    fail("", "missing required key '" + k.name + "' (" + what + ")");
}

void TomlTableReader::choose_group(const std::string& value) {
    group_ = value;
    for (auto&& [name, v] : table_) {
        const std::string key(name.str());
        const KeySpec* elsewhere = spec_.find_anywhere(key);
        if (spec_.find(key, group_) || !elsewhere) continue;
        fail(key, "a key of " + spec_.group_key + " = \"" + elsewhere->group + "\", not of " + spec_.group_key + " = \"" + group_ + "\"");
    }
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

std::string out_of_range_message(const KeySpec& k, double value) {
    std::ostringstream s;
    s << std::setprecision(12);
    const KeyRange& r = k.range;
    const bool lo = std::isfinite(r.min), hi = std::isfinite(r.max);
    const char* what = k.kind == ValueKind::integer ? "a whole number" : "a number";
    if (lo && !hi && r.min == 0.0 && r.min_open) s << "expected a positive number";
    else if (lo && hi && !r.min_open && !r.max_open) s << "expected " << what << " from " << r.min << " to " << r.max;
    else if (lo && hi) s << "expected " << what << " in " << (r.min_open ? "(" : "[") << r.min << ", " << r.max << (r.max_open ? ")" : "]");
    else if (lo) s << "expected " << what << (r.min_open ? " above " : " of at least ") << r.min;
    else s << "expected " << what << (r.max_open ? " below " : " of at most ") << r.max;
    s << ", got " << value;
    return s.str();
}

double TomlTableReader::checked_number(const KeySpec& k, Dimension d) {
    const toml::node* n = node(k.name);
    const std::optional<double> v = value_of(*n, k.name, d);
    if (!v) fail(k.name, d == dimension::none || !units_ ? "expected a number" : "expected a number, or a string with its unit");
    if (!std::isfinite(*v)) fail(k.name, "expected a finite number, got " + std::to_string(*v));
    if (!k.range.contains(*v)) fail(k.name, out_of_range_message(k, *v));
    return *v;
}

double TomlTableReader::number(const std::string& key) { return number(key, declared(key).dimension); }

double TomlTableReader::number(const std::string& key, Dimension d) {
    const KeySpec& k = declared(key);
    if (has(key)) return checked_number(k, d);
    used_.insert(key);
    if (const double* v = std::get_if<double>(&k.fixed_default)) return *v;
    missing(k, "a number");
}

std::optional<double> TomlTableReader::optional_number(const std::string& key, Dimension d) {
    const KeySpec& k = declared(key);
    if (has(key)) return checked_number(k, d);
    used_.insert(key);
    return std::nullopt;
}

double TomlTableReader::number_or(const std::string& key, double fallback) {
    return number_or(key, fallback, declared(key).dimension);
}

double TomlTableReader::number_or(const std::string& key, double fallback, Dimension d) {
    return optional_number(key, d).value_or(fallback);
}

int TomlTableReader::integer(const std::string& key) {
    const KeySpec& k = declared(key);
    const toml::node* n = node(key);
    if (!n) {
        if (const double* v = std::get_if<double>(&k.fixed_default)) return static_cast<int>(*v);
        missing(k, "a whole number");
    }
    if (!n->is_integer()) fail(key, "expected a whole number");
    const int64_t v = *n->value<int64_t>();
    if (!k.range.contains(static_cast<double>(v))) fail(key, out_of_range_message(k, static_cast<double>(v)));
    return static_cast<int>(v);
}

int TomlTableReader::integer_or(const std::string& key, int fallback) {
    declared(key);
    return has(key) ? integer(key) : (used_.insert(key), fallback);
}

bool TomlTableReader::boolean(const std::string& key) {
    const KeySpec& k = declared(key);
    const toml::node* n = node(key);
    if (!n) {
        if (const bool* v = std::get_if<bool>(&k.fixed_default)) return *v;
        missing(k, "true or false");
    }
    if (!n->is_boolean()) fail(key, "expected true or false");
    return *n->value<bool>();
}

bool TomlTableReader::boolean_or(const std::string& key, bool fallback) {
    declared(key);
    return has(key) ? boolean(key) : (used_.insert(key), fallback);
}

std::string TomlTableReader::string(const std::string& key) {
    const KeySpec& k = declared(key);
    const toml::node* n = node(key);
    if (!n) {
        if (const std::string* v = std::get_if<std::string>(&k.fixed_default)) return *v;
        missing(k, "a string");
    }
    if (!n->is_string()) fail(key, "expected a string");
    std::string text = *n->value<std::string>();
    // A text is printed, drawn and written into XML and CSV: one line of a bounded length.
    if (const std::optional<std::string> problem = text_problem(text, max_text_bytes)) fail(key, "the text " + *problem);
    return text;
}

std::string TomlTableReader::string_or(const std::string& key, const std::string& fallback) {
    declared(key);
    return has(key) ? string(key) : (used_.insert(key), fallback);
}

std::string TomlTableReader::choice(const std::string& key) {
    const KeySpec& k = declared(key);
    const std::string v = string(key);
    std::string list;
    for (const std::string& o : k.choices) {
        if (v == o) return v;
        list += (list.empty() ? "'" : ", '") + o + "'";
    }
    fail(key, "expected one of " + list + ", got '" + v + "'");
}

std::string TomlTableReader::choice_or(const std::string& key, const std::string& fallback) {
    declared(key);
    return has(key) ? choice(key) : (used_.insert(key), fallback);
}

std::array<double, 2> TomlTableReader::point(const std::string& key) { return point(key, declared(key).dimension); }

std::array<double, 2> TomlTableReader::point(const std::string& key, Dimension d) {
    const KeySpec& k = declared(key);
    const toml::node* n = node(key);
    if (!n) missing(k, "a point [x, y]");
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
    declared(key);
    const toml::node* n = node(key);
    if (!n) return nullptr;
    if (!n->is_table()) fail(key, "expected a table");
    return n->as_table();
}

const toml::array* TomlTableReader::array(const std::string& key) {
    declared(key);
    const toml::node* n = node(key);
    if (!n) return nullptr;
    if (!n->is_array()) fail(key, "expected an array");
    return n->as_array();
}

void TomlTableReader::finish() const {
    const std::vector<std::string> known = spec_.key_names(group_);
    for (auto&& [k, v] : table_) {
        const std::string key(k.str());
        if (std::find(known.begin(), known.end(), key) != known.end()) continue;
        if (const KeySpec* elsewhere = spec_.find_anywhere(key))
            throw SceneError(file_, plastica::line_of(v), qualified(key),
                             "a key of " + spec_.group_key + " = \"" + elsewhere->group + "\"" +
                                 (group_.empty() ? std::string() : ", not of " + spec_.group_key + " = \"" + group_ + "\""));
        const std::string near = nearest_key(key, known);
        throw SceneError(file_, plastica::line_of(v), qualified(key),
                         "unknown key" + (near.empty() ? std::string() : "; did you mean '" + near + "'?"));
    }
}

} // namespace plastica
