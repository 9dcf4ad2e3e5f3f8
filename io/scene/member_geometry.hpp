// The generated members of a scene ([[line]], [[arc]]): the points their elements join, first to
// last. The scene builder turns points into shared nodes and elements.
#pragma once

#include <array>
#include <vector>

namespace plastica {

using Point = std::array<double, 2>;

// elements + 1 equally spaced points from start to end.
std::vector<Point> line_points(const Point& start, const Point& end, int elements);
// elements + 1 points on a circle, at equal angles from start_angle to end_angle (degrees,
// counter-clockwise); a full circle's last point is its first.
std::vector<Point> arc_points(const Point& center, double radius, double start_angle, double end_angle, int elements);

} // namespace plastica
