#include "units.hpp"

#include <array>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace plastica {

namespace {

struct Unit {
    const char* symbol;
    double si;         // in metres, newtons and seconds
    Dimension dimension;
};

// SI prefixes are spelt out per unit: "Mm" (megametre) next to "mm" invites mistakes.
constexpr double lbf = 4.4482216152605, inch = 0.0254;
constexpr std::array<Unit, 22> units{{
    {"m", 1.0, dimension::length},
    {"mm", 1e-3, dimension::length},
    {"cm", 1e-2, dimension::length},
    {"km", 1e3, dimension::length},
    {"in", inch, dimension::length},
    {"ft", 12 * inch, dimension::length},
    {"N", 1.0, dimension::force},
    {"kN", 1e3, dimension::force},
    {"MN", 1e6, dimension::force},
    {"lbf", lbf, dimension::force},
    {"kip", 1e3 * lbf, dimension::force},
    {"Pa", 1.0, dimension::stress},
    {"kPa", 1e3, dimension::stress},
    {"MPa", 1e6, dimension::stress},
    {"GPa", 1e9, dimension::stress},
    {"psi", lbf / (inch * inch), dimension::stress},
    {"ksi", 1e3 * lbf / (inch * inch), dimension::stress},
    {"kg", 1.0, {-1, 1, 2}},
    {"t", 1e3, {-1, 1, 2}},
    {"s", 1.0, {0, 0, 1}},
    {"ms", 1e-3, {0, 0, 1}},
    {"rad", 1.0, dimension::none}, // a rotational spring's "kN*m/rad"
}};

const Unit* find_unit(const std::string& symbol) {
    for (const Unit& u : units)
        if (symbol == u.symbol) return &u;
    return nullptr;
}

Dimension scaled(Dimension d, int power) { return {d.length * power, d.force * power, d.time * power}; }
Dimension sum(Dimension a, Dimension b) { return {a.length + b.length, a.force + b.force, a.time + b.time}; }

struct Quantity {
    double si = 1.0;
    Dimension dimension;
};

// A product of units with powers, '/' dividing by every factor after it: "kN/m", "kN*m",
// "kN·m/rad", "N/mm^2", "N/mm²", "mm4", "m/s^2".
Quantity parse_unit(const std::string& text) {
    Quantity q;
    std::size_t i = 0;
    int sign = 1;
    bool expect_factor = true;
    auto fail = [&](const std::string& why) -> void {
        throw UnitError("unit '" + text + "': " + why);
    };
    while (i < text.size()) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == ' ') {
            ++i;
            continue;
        }
        if (c == '/' || c == '*' || text.compare(i, 2, "\xC2\xB7") == 0) { // '·' in UTF-8
            if (expect_factor) fail("an operator without a unit before it");
            if (c == '/') sign = -1;
            i += c == 0xC2 ? 2 : 1;
            expect_factor = true;
            continue;
        }
        std::size_t j = i;
        while (j < text.size() && std::isalpha(static_cast<unsigned char>(text[j]))) ++j;
        if (j == i) fail("expected a unit symbol at '" + text.substr(i) + "'");
        const std::string symbol = text.substr(i, j - i);
        const Unit* u = find_unit(symbol);
        if (!u) fail("unknown unit '" + symbol + "' (known: m mm cm km in ft, N kN MN lbf kip, Pa kPa MPa GPa psi ksi, kg t, s, rad; "
                     "products with * or ·, quotients with /)");
        i = j;
        int power = 1;
        if (i < text.size() && text[i] == '^') ++i;
        if (text.compare(i, 2, "\xC2\xB2") == 0) power = 2, i += 2;      // ²
        else if (text.compare(i, 2, "\xC2\xB3") == 0) power = 3, i += 2; // ³
        else if (text.compare(i, 3, "\xE2\x81\xB4") == 0) power = 4, i += 3; // ⁴
        else if (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) power = text[i++] - '0';
        if (!expect_factor) fail("two units without * or / between them");
        q.si *= std::pow(u->si, sign * power);
        q.dimension = sum(q.dimension, scaled(u->dimension, sign * power));
        expect_factor = false;
    }
    if (expect_factor) fail("expected a unit after the number");
    return q;
}

std::string power_text(const char* base, int p) {
    if (p == 1) return base;
    const char* superscripts[] = {"", "", "²", "³", "⁴"};
    return std::string(base) + (p >= 2 && p <= 4 ? superscripts[p] : "^" + std::to_string(p));
}

} // namespace

std::string describe(Dimension d, bool with_example) {
    struct Named {
        Dimension d;
        const char* what;
        const char* example;
    };
    static const Named known[] = {
        {dimension::length, "a length", "300 mm"},
        {dimension::area, "an area", "78.1 cm2"},
        {dimension::second_moment, "a second moment of area", "8356 cm4"},
        {dimension::force, "a force", "250 kN"},
        {dimension::moment, "a moment, force·length", "120 kN*m"},
        {dimension::force_per_length, "a force per length", "-49.1 kN/m"},
        {dimension::stress, "a stress, force/length²", "210 GPa"},
        {dimension::mass_density, "a mass density", "7850 kg/m3"},
        {dimension::acceleration, "an acceleration", "-9.81 m/s2"},
        {dimension::none, "a pure number", nullptr},
        {dimension::mass, "a mass, force·time²/length", "120 kg"},
        {dimension::rotational_mass, "a rotational inertia, force·length·time²", nullptr},
        {dimension::time, "a time", "0.01 s"},
        {dimension::velocity, "a velocity", "2 m/s"},
        {dimension::frequency, "a rate, 1/time", nullptr},
    };
    for (const Named& n : known)
        if (n.d == d) return std::string(n.what) + (with_example && n.example ? std::string(" (e.g. \"") + n.example + "\")" : "");
    std::string text;
    for (auto [base, p] : {std::pair{"force", d.force}, std::pair{"length", d.length}, std::pair{"time", d.time}})
        if (p > 0) text += (text.empty() ? "" : "·") + power_text(base, p);
    std::string below;
    for (auto [base, p] : {std::pair{"force", d.force}, std::pair{"length", d.length}, std::pair{"time", d.time}})
        if (p < 0) below += (below.empty() ? "" : "·") + power_text(base, -p);
    return "a quantity of " + (text.empty() ? std::string("1") : text) + (below.empty() ? "" : "/" + below);
}

UnitSystem::UnitSystem(std::string length, std::string force) : length_(std::move(length)), force_(std::move(force)) {
    const Unit* l = find_unit(length_);
    if (!l || l->dimension != dimension::length) throw UnitError("'" + length_ + "' is not a length unit (m, mm, cm, km, in, ft)");
    const Unit* f = find_unit(force_);
    if (!f || f->dimension != dimension::force) throw UnitError("'" + force_ + "' is not a force unit (N, kN, MN, lbf, kip)");
    metres_ = l->si;
    newtons_ = f->si;
}

double UnitSystem::to_scene(const std::string& text, Dimension expected) const {
    const char* begin = text.c_str();
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin || !std::isfinite(value))
        throw UnitError("expected a number and its unit, e.g. \"300 mm\", got \"" + text + "\"");
    const std::string unit_text = text.substr(static_cast<std::size_t>(end - begin));
    if (unit_text.find_first_not_of(' ') == std::string::npos)
        throw UnitError("\"" + text + "\" has no unit: write it as a number (in the scene's units) or with its unit");
    const Quantity q = parse_unit(unit_text);
    if (q.dimension != expected) {
        std::ostringstream s;
        s << "'" << unit_text.substr(unit_text.find_first_not_of(' ')) << "' is " << describe(q.dimension, false)
          << ", but this value is " << describe(expected, true);
        throw UnitError(s.str());
    }
    // SI value over the size of one scene unit of this dimension (time in seconds).
    return value * q.si / (std::pow(metres_, expected.length) * std::pow(newtons_, expected.force));
}

} // namespace plastica
