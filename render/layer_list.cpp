#include "layer_list.hpp"
#include "layers/layers.hpp"
#include "render_error.hpp"

#include <algorithm>
#include <functional>

namespace plastica::render {

// The kinds, one in each file of render/layers/.
LayerKind initial_shape_kind();
LayerKind base_kind();
LayerKind hinge_kind();
LayerKind release_kind();
LayerKind contact_kind();
LayerKind surface_contact_kind();
LayerKind support_kind();
LayerKind load_kind();
LayerKind line_load_kind();
LayerKind reaction_kind();

namespace {

// Drawing order, which is also the legend's order: one line a layer, its kind in its file.
const std::vector<LayerKind>& kinds() {
    static const std::vector<LayerKind> all = {
        initial_shape_kind(), base_kind(), hinge_kind(),  release_kind(),  contact_kind(),
        surface_contact_kind(), support_kind(), line_load_kind(), load_kind(), reaction_kind(),
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
        if (!k.on_request && std::find(names.begin(), names.end(), k.name) == names.end()) names.push_back(k.name);
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
    // A name may stand for several kinds (loads: point and line loads): it changes nothing only
    // where none of them has anything to draw.
    std::vector<std::string> named_here, drawn;
    for (const LayerKind& k : kinds()) {
        const bool hidden = !k.on_request && named(choice.hide, k.name), shown = k.on_request && named(choice.show, k.name);
        if (!hidden && !shown) continue;
        if (std::find(named_here.begin(), named_here.end(), k.name) == named_here.end()) named_here.push_back(k.name);
        if (k.make(summary, first_step, base)) drawn.push_back(k.name);
    }
    std::vector<std::string> notes;
    for (const std::string& name : named_here)
        if (std::find(drawn.begin(), drawn.end(), name) == drawn.end())
            notes.push_back(std::string(named(choice.hide, name.c_str()) ? "--hide " : "--show ") + name + " changes nothing: this series has no " +
                            name + " to draw");
    return notes;
}

} // namespace plastica::render
