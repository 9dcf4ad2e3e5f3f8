// Which node, element and member each point and cell is: ids counted from 0, as ParaView's
// spreadsheet and Python's arrays count, and each element's member by its scene name, so that
// "the column base" is found by name, not by matching coordinates.
#include "arrays/output_array.hpp"

namespace plastica {

namespace {

using namespace result;

void fill_identities(const StepView& v, XmlDataset& out) {
    const std::size_t n = v.model.nodes.size(), ne = v.model.elements.size();
    XmlArray node = integer_array(name::node_id, n), element = integer_array(name::element_id, ne);
    for (std::size_t i = 0; i < n; ++i) integer(node)[i] = static_cast<std::int32_t>(i);
    for (std::size_t e = 0; e < ne; ++e) integer(element)[e] = static_cast<std::int32_t>(e);
    out.point_data.push_back(std::move(node));
    out.cell_data.push_back(std::move(element));
    if (!v.has(name::member)) return;
    XmlArray member = integer_array(name::member, ne);
    for (std::size_t e = 0; e < ne; ++e) integer(member)[e] = v.model.elements[e].member;
    out.cell_data.push_back(std::move(member));
    XmlArray names;
    names.name = name::member_names;
    names.values = v.model.member_names;
    out.field_data.push_back(std::move(names));
}

} // namespace

OutputGroup identity_arrays() {
    return {{
                {name::node_id, Where::point, Type::int32, 1, Quantity::none, When::always, "the node's index, from 0 (a scene's `node` ids name explicit nodes only)"},
                {name::element_id, Where::cell, Type::int32, 1, Quantity::none, When::always, "the element's index, from 0"},
                {name::member, Where::cell, Type::int32, 1, Quantity::none, When::members, "the element's member: its index in `member_names`, −1 for an `[[element]]` given on its own"},
                {name::member_names, Where::field, Type::text, 1, Quantity::none, When::members, "the `[[line]]` and `[[arc]]` names, in the scene's order"},
            },
            fill_identities};
}

} // namespace plastica
