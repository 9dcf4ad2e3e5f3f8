// Finds the node at a point within a tolerance in O(log n): nodes sorted by (x, y), and for each
// distinct x within the tolerance only the y-window is scanned. Generators share their end nodes
// through it, and points in a scene name nodes through it; a linear search made a 50 000-element
// ring take seconds to read.
#pragma once

#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <utility>

namespace plastica {

class NodeIndex {
public:
    void add(double x, double y, int node) { nodes_.emplace(std::make_pair(x, y), node); }

    // The node within `tolerance` of (x, y), or −1.
    int find(double x, double y, double tolerance) const {
        const double lowest = -std::numeric_limits<double>::infinity();
        auto column = nodes_.lower_bound({x - tolerance, lowest});
        while (column != nodes_.end() && column->first.first <= x + tolerance) {
            const double cx = column->first.first;
            for (auto it = nodes_.lower_bound({cx, y - tolerance}); it != nodes_.end() && it->first.first == cx &&
                                                                   it->first.second <= y + tolerance;
                 ++it)
                if (std::hypot(it->first.first - x, it->first.second - y) <= tolerance) return it->second;
            // On to the next distinct x.
            column = nodes_.upper_bound({cx, std::numeric_limits<double>::infinity()});
        }
        return -1;
    }

private:
    std::multimap<std::pair<double, double>, int> nodes_;
};

} // namespace plastica
