// Numbers with units in a scene: with a [units] table (length and force of the scene), any
// dimensioned value may be written as a string with its unit ("210 GPa", "300 mm",
// "-49.1 kN/m"), converted to the scene's units; a unit of the wrong kind is an error.
#pragma once

#include <stdexcept>
#include <string>

namespace plastica {

// Exponents of length, force and time (a mass is force·time²/length).
struct Dimension {
    int length = 0, force = 0, time = 0;
    bool operator==(const Dimension& o) const { return length == o.length && force == o.force && time == o.time; }
    bool operator!=(const Dimension& o) const { return !(*this == o); }
};

namespace dimension {
inline constexpr Dimension none{};
inline constexpr Dimension length{1, 0, 0};
inline constexpr Dimension area{2, 0, 0};
inline constexpr Dimension second_moment{4, 0, 0};
inline constexpr Dimension force{0, 1, 0};
inline constexpr Dimension moment{1, 1, 0};              // also a rotational spring's force·length per radian
inline constexpr Dimension force_per_length{-1, 1, 0};   // a line load, a spring at a node
inline constexpr Dimension stress{-2, 1, 0};             // also a spring per unit length
inline constexpr Dimension mass_density{-4, 1, 2};
inline constexpr Dimension acceleration{1, 0, -2};
inline constexpr Dimension time{0, 0, 1};
inline constexpr Dimension velocity{1, 0, -1};
inline constexpr Dimension mass{-1, 1, 2};                // force·time²/length
inline constexpr Dimension rotational_mass{1, 1, 2};     // force·length·time²
inline constexpr Dimension frequency{0, 0, -1};
} // namespace dimension

// What a dimension is, for messages: "a stress, force/length²", with an example if asked
// (' (e.g. "210 GPa")').
std::string describe(Dimension d, bool with_example);

class UnitError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class UnitSystem {
public:
    // Throws UnitError for a length that is not a length unit, or a force that is not a force unit.
    UnitSystem(std::string length, std::string force);

    const std::string& length() const { return length_; }
    const std::string& force() const { return force_; }

    // "value unit" in the scene's units; throws UnitError for a malformed text, an unknown unit or
    // a unit of another dimension than `expected`.
    double to_scene(const std::string& text, Dimension expected) const;

private:
    std::string length_, force_;
    double metres_, newtons_; // one scene length in metres, one scene force in newtons
};

} // namespace plastica
