#include "member_geometry.hpp"

#include <cmath>

namespace plastica {

std::vector<Point> line_points(const Point& a, const Point& b, int elements) {
    std::vector<Point> points;
    points.reserve(static_cast<std::size_t>(elements) + 1);
    for (int k = 0; k <= elements; ++k) {
        const double t = static_cast<double>(k) / elements;
        points.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
    return points;
}

std::vector<Point> arc_points(const Point& c, double radius, double start_angle, double end_angle, int elements) {
    std::vector<Point> points;
    points.reserve(static_cast<std::size_t>(elements) + 1);
    const double sweep = end_angle - start_angle;
    for (int k = 0; k <= elements; ++k) {
        const double t = (start_angle + sweep * k / elements) * M_PI / 180.0;
        points.push_back({c[0] + radius * std::cos(t), c[1] + radius * std::sin(t)});
    }
    return points;
}

} // namespace plastica
