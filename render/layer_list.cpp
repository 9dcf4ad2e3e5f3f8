#include "layer_list.hpp"
#include "layers/layers.hpp"
#include "render_error.hpp"

#include "result_schema.hpp"

#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <functional>

namespace plastica::render {

namespace {

struct LayerKind {
    const char* name; // for --hide and --show
    std::function<std::unique_ptr<Layer>(const SeriesSummary&, vtkUnstructuredGrid*, vtkPolyData*)> make; // null: not needed
    bool on_request = false; // drawn only when --show names it
};

// Drawing order, which is also the legend's order.
const std::vector<LayerKind>& kinds() {
    static const std::vector<LayerKind> all = {
        {"initial", [](const SeriesSummary&, vtkUnstructuredGrid* first, vtkPolyData*) { return initial_shape_layer(first); }},
        {"base",
         [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData* base) -> std::unique_ptr<Layer> {
             if (!base || (base->GetNumberOfLines() == 0 && base->GetNumberOfVerts() == 0)) return nullptr;
             return base_layer(s, base);
         }},
        {"hinges",
         [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData*) -> std::unique_ptr<Layer> {
             return s.inelastic ? hinge_layer(s) : nullptr;
         }},
        {"releases",
         [](const SeriesSummary&, vtkUnstructuredGrid* first, vtkPolyData*) -> std::unique_ptr<Layer> {
             return first && first->GetCellData()->GetArray(result::name::released) ? release_layer() : nullptr;
         }},
        {"contact",
         [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData*) -> std::unique_ptr<Layer> {
             return s.any_contact ? contact_layer(s) : nullptr;
         }},
        {"surface_contact",
         [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData*) -> std::unique_ptr<Layer> {
             return s.max_surface_contact_force > 0 ? surface_contact_layer(s) : nullptr;
         }},
        {"supports", [](const SeriesSummary& s, vtkUnstructuredGrid* first, vtkPolyData*) { return support_layer(s, first); }},
        {"loads",
         [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData*) -> std::unique_ptr<Layer> {
             return s.loads.max_force > 0 || s.loads.max_moment > 0 ? load_layer(s) : nullptr;
         }},
        {"reactions",
         [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData*) -> std::unique_ptr<Layer> {
             return s.reactions.max_force > 0 || s.reactions.max_moment > 0 ? reaction_layer(s) : nullptr;
         },
         true},
    };
    return all;
}

std::string listed(const std::vector<std::string>& names) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    return list;
}

} // namespace

std::vector<std::string> hideable_layers() {
    std::vector<std::string> names;
    for (const LayerKind& k : kinds())
        if (!k.on_request) names.push_back(k.name);
    return names;
}

std::vector<std::string> on_request_layers() {
    std::vector<std::string> names;
    for (const LayerKind& k : kinds())
        if (k.on_request) names.push_back(k.name);
    return names;
}

namespace {

bool named(const std::vector<std::string>& list, const char* name) { return std::find(list.begin(), list.end(), name) != list.end(); }

void check_names(const LayerChoice& choice) {
    const std::vector<std::string> names = hideable_layers(), requested = on_request_layers();
    for (const std::string& h : choice.hide)
        if (!named(names, h.c_str()))
            throw RenderError("--hide takes " + listed(names) + " (got '" + h + "')");
    for (const std::string& s : choice.show)
        if (!named(requested, s.c_str()))
            throw RenderError("--show takes " + listed(requested) + " (got '" + s + "')");
}

} // namespace

std::vector<std::unique_ptr<Layer>> make_layers(const SeriesSummary& summary, vtkUnstructuredGrid* first_step,
                                                vtkPolyData* base, const LayerChoice& choice) {
    check_names(choice);
    std::vector<std::unique_ptr<Layer>> layers;
    for (const LayerKind& k : kinds()) {
        if (k.on_request ? !named(choice.show, k.name) : named(choice.hide, k.name)) continue;
        if (auto layer = k.make(summary, first_step, base)) layers.push_back(std::move(layer));
    }
    return layers;
}

std::vector<std::string> layer_choice_notes(const SeriesSummary& summary, vtkUnstructuredGrid* first_step,
                                            vtkPolyData* base, const LayerChoice& choice) {
    check_names(choice);
    std::vector<std::string> notes;
    for (const LayerKind& k : kinds()) {
        const bool hidden = !k.on_request && named(choice.hide, k.name), shown = k.on_request && named(choice.show, k.name);
        if ((hidden || shown) && !k.make(summary, first_step, base))
            notes.push_back(std::string(hidden ? "--hide " : "--show ") + k.name + " changes nothing: this series has no " + k.name +
                            " to draw");
    }
    return notes;
}

} // namespace plastica::render
