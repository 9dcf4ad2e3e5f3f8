// The mesh as a scene's members are generated, apart from reading (no TOML, testable on its
// own): nodes at one point are shared, so that lines and arcs join; explicit nodes keep their
// ids; the same member twice is refused; each generated member's nodes and elements are listed
// under its name. The scene reader turns a MeshError into a located error.
#pragma once

#include "member_geometry.hpp"
#include "node_index.hpp"

#include "model/model.hpp"

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace plastica {

struct MeshError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class MeshBuilder {
public:
    MeshBuilder(Model& model, int max_elements) : model_(model), max_elements_(max_elements) {}

    // The structure's size so far, which sets the tolerances of "the same point".
    void enlarge(double extent) { size_scale_ = std::max(size_scale_, extent); }
    double size_scale() const { return size_scale_; }

    // The node at (x, y), shared with an earlier one there.
    int shared_node(double x, double y);
    // A [[node]] with its id; throws for an id used twice or a point another explicit node holds.
    int explicit_node(int id, double x, double y);
    // Null for an id no explicit node has.
    const int* node_of_id(int id) const;
    // The node within a millionth of the structure's size of p, or −1 (points naming nodes).
    int node_near(const Point& p) const;
    // Throws for coincident nodes, an element given twice, or too many elements.
    void add_element(int a, int b, int section);
    // Points into shared nodes and elements, listed under `name`; returns the first and last
    // element's index.
    std::pair<int, int> add_member(const std::string& name, const std::vector<Point>& points, int section);

    const std::map<std::string, std::vector<int>>& member_nodes() const { return member_nodes_; }
    const std::map<std::string, std::vector<int>>& member_elements() const { return member_elements_; }
    // After every member: throws for an explicit node no element uses, and takes the
    // structure's extent into the size.
    void finish();

    std::string describe(int node) const;

private:
    double merge_tolerance(double x, double y) const;

    Model& model_;
    int max_elements_;
    NodeIndex index_;
    std::map<int, int> node_ids_;
    std::set<std::pair<int, int>> joined_; // node pairs with an element
    std::map<std::string, std::vector<int>> member_nodes_;
    std::map<std::string, std::vector<int>> member_elements_;
    double size_scale_ = 0.0;
};

} // namespace plastica
