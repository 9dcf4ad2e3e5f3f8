#include "layer_list.hpp"
#include "layers/layers.hpp"
#include "render_error.hpp"

#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <functional>

namespace plastica::render {

namespace {

struct LayerKind {
    const char* name; // for --hide
    std::function<std::unique_ptr<Layer>(const SeriesSummary&, vtkUnstructuredGrid*, vtkPolyData*)> make; // null: not needed
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
        {"contact",
         [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData*) -> std::unique_ptr<Layer> {
             return s.any_contact ? contact_layer(s) : nullptr;
         }},
        {"supports", [](const SeriesSummary& s, vtkUnstructuredGrid* first, vtkPolyData*) { return support_layer(s, first); }},
        {"loads",
         [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData*) -> std::unique_ptr<Layer> {
             return s.max_load_force > 0 || s.max_load_moment > 0 ? load_layer(s) : nullptr;
         }},
    };
    return all;
}

} // namespace

std::vector<std::string> hideable_layers() {
    std::vector<std::string> names;
    for (const LayerKind& k : kinds()) names.push_back(k.name);
    return names;
}

std::vector<std::unique_ptr<Layer>> make_layers(const SeriesSummary& summary, vtkUnstructuredGrid* first_step,
                                                vtkPolyData* base, const std::vector<std::string>& hidden) {
    const std::vector<std::string> names = hideable_layers();
    for (const std::string& h : hidden)
        if (std::find(names.begin(), names.end(), h) == names.end()) {
            std::string list;
            for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
            throw RenderError("--hide takes " + list + " (got '" + h + "')");
        }
    std::vector<std::unique_ptr<Layer>> layers;
    for (const LayerKind& k : kinds()) {
        if (std::find(hidden.begin(), hidden.end(), k.name) != hidden.end()) continue;
        if (auto layer = k.make(summary, first_step, base)) layers.push_back(std::move(layer));
    }
    return layers;
}

} // namespace plastica::render
