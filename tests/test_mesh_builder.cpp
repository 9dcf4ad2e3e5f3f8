// The mesh built from generated members without a scene file: shared nodes where members meet,
// a closed ring, explicit nodes, and the refusals the reader locates (io/scene/mesh_builder.hpp).
#include "mesh_builder.hpp"

#include <catch2/catch.hpp>

using namespace plastica;

TEST_CASE("Members that meet share their node and a full circle closes on its first node", "[mesh]") {
    Model m;
    MeshBuilder mesh(m, 1000);
    mesh.enlarge(4.0);
    const auto column = mesh.add_member("column", line_points({0.0, 0.0}, {0.0, 4.0}, 4), 0);
    const auto beam = mesh.add_member("beam", line_points({0.0, 4.0}, {6.0, 4.0}, 3), 0);
    CHECK(column == std::pair<int, int>{0, 3});
    CHECK(beam == std::pair<int, int>{4, 6});
    CHECK(m.nodes.size() == 8u); // 5 + 4 with the corner shared
    CHECK(mesh.member_nodes().at("beam").front() == mesh.member_nodes().at("column").back());
    CHECK(mesh.member_elements().at("beam") == std::vector<int>{4, 5, 6});
    // Each element knows its member, by its index in the scene's order of names (the VTU's
    // `member` and `member_names`).
    CHECK(m.member_names == std::vector<std::string>{"column", "beam"});
    for (int e = 0; e < 7; ++e) CHECK(m.elements[static_cast<std::size_t>(e)].member == (e < 4 ? 0 : 1));

    Model ring;
    MeshBuilder ring_mesh(ring, 1000);
    ring_mesh.enlarge(2.0);
    ring_mesh.add_member("ring", arc_points({0.0, 0.0}, 1.0, -90.0, 270.0, 12), 0);
    CHECK(ring.nodes.size() == 12u);
    CHECK(ring.elements.size() == 12u);
    CHECK(ring.elements.back().node_j == ring.elements.front().node_i);
    CHECK(ring_mesh.member_nodes().at("ring").size() == 12u);
}

TEST_CASE("Points closer than round-off of the structure's size are one node and farther ones are not", "[mesh]") {
    Model m;
    MeshBuilder mesh(m, 1000);
    mesh.enlarge(1000.0);
    const int a = mesh.shared_node(500.0, 0.0);
    CHECK(mesh.shared_node(500.0 + 1e-8, 0.0) == a); // 1e-11 of the size
    CHECK(mesh.shared_node(500.0 + 1e-3, 0.0) != a); // 1e-6 of the size: a node of its own
    CHECK(mesh.node_near({500.0 + 1e-4, 0.0}) >= 0);  // points naming nodes allow 1e-6 of the size
    CHECK(mesh.node_near({501.0, 0.0}) == -1);
}

TEST_CASE("The mesh refuses a member twice and coincident or unused nodes in words", "[mesh]") {
    Model m;
    MeshBuilder mesh(m, 3);
    mesh.enlarge(1.0);
    const int a = mesh.explicit_node(1, 0.0, 0.0), b = mesh.explicit_node(2, 1.0, 0.0);
    CHECK(*mesh.node_of_id(2) == b);
    CHECK(mesh.node_of_id(3) == nullptr);
    CHECK_THROWS_WITH(mesh.explicit_node(1, 5.0, 5.0), "node id 1 is used twice");
    CHECK_THROWS_WITH(mesh.explicit_node(7, 1.0, 0.0), "node 7 lies on node 2");
    CHECK_THROWS_WITH(mesh.add_element(a, a, 0), "an element's two nodes coincide");
    mesh.add_element(a, b, 0);
    CHECK_THROWS_WITH(mesh.add_element(b, a, 0), "an element between [1, 0] and [0, 0] exists already (given twice, or two generators overlap)");
    const int c = mesh.explicit_node(3, 2.0, 0.0);
    CHECK_THROWS_WITH(mesh.finish(), "node 3 belongs to no element");
    mesh.add_element(b, c, 0);
    mesh.finish();
    CHECK(mesh.size_scale() == 2.0);
    const int d = mesh.shared_node(3.0, 0.0), e = mesh.shared_node(4.0, 0.0);
    mesh.add_element(c, d, 0);
    CHECK_THROWS_WITH(mesh.add_element(d, e, 0), "more than 3 elements");
}
