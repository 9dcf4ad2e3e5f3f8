#include "mesh_builder.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace plastica {

double MeshBuilder::merge_tolerance(double x, double y) const {
    return 1e-9 * std::max({1.0, std::abs(x), std::abs(y), size_scale_});
}

int MeshBuilder::shared_node(double x, double y) {
    if (const int k = index_.find(x, y, merge_tolerance(x, y)); k >= 0) return k;
    model_.nodes.push_back({x, y});
    const int node = static_cast<int>(model_.nodes.size()) - 1;
    index_.add(x, y, node);
    return node;
}

int MeshBuilder::explicit_node(int id, double x, double y) {
    if (node_ids_.count(id)) throw MeshError("node id " + std::to_string(id) + " is used twice");
    if (const int k = index_.find(x, y, merge_tolerance(x, y)); k >= 0)
        for (const auto& [other, node] : node_ids_)
            if (node == k) throw MeshError("node " + std::to_string(id) + " lies on node " + std::to_string(other));
    model_.nodes.push_back({x, y});
    const int node = static_cast<int>(model_.nodes.size()) - 1;
    node_ids_[id] = node;
    index_.add(x, y, node);
    return node;
}

const int* MeshBuilder::node_of_id(int id) const {
    const auto it = node_ids_.find(id);
    return it == node_ids_.end() ? nullptr : &it->second;
}

int MeshBuilder::node_near(const Point& p) const { return index_.find(p[0], p[1], 1e-6 * size_scale_); }

std::string MeshBuilder::describe(int node) const {
    std::ostringstream s;
    s << "[" << model_.nodes[static_cast<std::size_t>(node)].x << ", " << model_.nodes[static_cast<std::size_t>(node)].y << "]";
    return s.str();
}

void MeshBuilder::add_element(int a, int b, int section) {
    if (a == b) throw MeshError("an element's two nodes coincide");
    // The same member twice would double its stiffness without a word.
    const auto pair = std::minmax(a, b);
    if (!joined_.insert({pair.first, pair.second}).second)
        throw MeshError("an element between " + describe(a) + " and " + describe(b) +
                        " exists already (given twice, or two generators overlap)");
    if (static_cast<int>(model_.elements.size()) >= max_elements_)
        throw MeshError("more than " + std::to_string(max_elements_) + " elements");
    model_.elements.push_back({a, b, section});
}

std::pair<int, int> MeshBuilder::add_member(const std::string& name, const std::vector<Point>& points, int section) {
    const int first = static_cast<int>(model_.elements.size());
    const int member = static_cast<int>(model_.member_names.size());
    model_.member_names.push_back(name);
    std::vector<int>& nodes = member_nodes_[name];
    int previous = shared_node(points.front()[0], points.front()[1]);
    nodes.push_back(previous);
    for (std::size_t k = 1; k < points.size(); ++k) {
        const int next = shared_node(points[k][0], points[k][1]); // a full circle closes on its first node
        add_element(previous, next, section);
        model_.elements.back().member = member;
        member_elements_[name].push_back(static_cast<int>(model_.elements.size()) - 1);
        if (next != nodes.front()) nodes.push_back(next);
        previous = next;
    }
    return {first, static_cast<int>(model_.elements.size()) - 1};
}

void MeshBuilder::finish() {
    std::vector<bool> used(model_.nodes.size(), false);
    for (const ElementSpec& e : model_.elements) used[static_cast<std::size_t>(e.node_i)] = used[static_cast<std::size_t>(e.node_j)] = true;
    for (const auto& [id, node] : node_ids_)
        if (!used[static_cast<std::size_t>(node)]) throw MeshError("node " + std::to_string(id) + " belongs to no element");
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for (const Node& n : model_.nodes) {
        xmin = std::min(xmin, n.x), xmax = std::max(xmax, n.x);
        ymin = std::min(ymin, n.y), ymax = std::max(ymax, n.y);
    }
    enlarge(std::max(xmax - xmin, ymax - ymin));
}

} // namespace plastica
