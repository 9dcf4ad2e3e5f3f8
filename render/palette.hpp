// The colours of every picture, named once. Chosen to stay apart from each other and from the
// cool–warm map of the coloured field: greys for what does not move, green for contact forces,
// crimson for applied loads, gold to purple for plastic hinges.
#pragma once

namespace plastica::render {

struct Rgb {
    unsigned char r, g, b;
    double red() const { return r / 255.0; }
    double green() const { return g / 255.0; }
    double blue() const { return b / 255.0; }
};

namespace colour {
constexpr Rgb background{255, 255, 255};
constexpr Rgb title_band{236, 239, 243};
constexpr Rgb text{25, 25, 25};
constexpr Rgb initial_shape{200, 200, 200};
constexpr Rgb outline{40, 40, 40};
constexpr Rgb base{70, 70, 70};
constexpr Rgb hatching{130, 130, 130};
constexpr Rgb spring_anchor{90, 90, 90};
constexpr Rgb contact_force{0, 140, 60};
constexpr Rgb surface_contact_force{110, 160, 20}; // a yellower green: contact of the members' own surfaces
constexpr Rgb support{55, 65, 85};
constexpr Rgb load{190, 20, 60};
constexpr Rgb reaction{0, 150, 170};
constexpr Rgb hinge_yielding_low{250, 215, 40};  // just past first yield
constexpr Rgb hinge_yielding_high{245, 130, 0};  // close to the capacity
constexpr Rgb hinge_plastic{150, 30, 170};        // at the capacity M_p(N)
constexpr Rgb hinge_failed{0, 0, 0};              // a fibre strained past failure
constexpr Rgb curve_full{190, 190, 190};
constexpr Rgb curve_progress{31, 90, 180};
constexpr Rgb current_point{215, 25, 28};
} // namespace colour

// Blends two colours, t = 0 gives a, t = 1 gives b.
inline Rgb mix(Rgb a, Rgb b, double t) {
    auto lerp = [t](unsigned char x, unsigned char y) {
        return static_cast<unsigned char>(x + (y - x) * (t < 0 ? 0 : t > 1 ? 1 : t) + 0.5);
    };
    return {lerp(a.r, b.r), lerp(a.g, b.g), lerp(a.b, b.b)};
}

} // namespace plastica::render
