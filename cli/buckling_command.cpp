// plastica buckling: the critical load factors of a scene's loads and their buckling modes, at
// its unloaded state (K₀ + λK_G) or about a step of its run (the tangent there): buckling.csv,
// a VTU series of the shapes, and their pictures (analysis/linear_buckling.hpp).
#include "shape_command.hpp"

#include "analysis/eigen_at_step.hpp"

#include <sstream>

namespace plastica::cli {

namespace {

std::string buckling_table(const BucklingResult& b, double load_per_factor) {
    std::ostringstream out;
    out.precision(10);
    out << "mode,load_factor,above_state,load\n";
    for (const BucklingMode& m : b.modes)
        out << m.mode << ',' << m.load_factor << ',' << m.above_state << ',' << m.load_factor * load_per_factor << '\n';
    return out.str();
}

ShapesFound find_buckling(const Model& model, int count, int step) {
    BucklingAtStep found = buckling_at_step(model, count, step);
    ShapesFound out;
    out.state = std::move(found.state);
    out.table = buckling_table(found.buckling, model.load_per_factor());
    if (found.buckling.tangent_indefinite)
        out.notes.push_back("the tangent at step " + std::to_string(step) +
                            " has negative pivots: the state lies beyond a bifurcation or limit point, and factors "
                            "below its own are those where the structure lost its stability");
    for (const BucklingMode& m : found.buckling.modes) {
        std::ostringstream line;
        line << "mode " << m.mode << ": load factor " << m.load_factor;
        if (step > 0) line << " (" << m.above_state << " above the state's " << found.buckling.state_load_factor << ")";
        out.shapes.push_back({m.mode, m.shape, m.load_factor, static_cast<double>(m.mode), line.str()});
    }
    return out;
}

} // namespace

int buckling_command(const Args& args) {
    ShapeCommand command;
    command.name = "buckling";
    command.usage = "plastica buckling SCENE [-n N] [--step K] [-o DIR]";
    command.what = "buckling modes to find";
    command.table_file = "buckling.csv";
    command.title = "Buckling modes";
    command.load_label = "critical load factor";
    command.displacement_label = "mode";
    command.find = find_buckling;
    return shape_command(args, command);
}

} // namespace plastica::cli
