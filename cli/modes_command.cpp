// plastica modes: the natural modes of a scene's structure, at its unloaded state or at a step of
// its run (hinges, fibres and contacts as they stand there): modes.csv with periods,
// frequencies and effective modal masses, a VTU series of the shapes, and their pictures.
#include "shape_command.hpp"

#include "analysis/eigen_at_step.hpp"

#include <cmath>
#include <sstream>

namespace plastica::cli {

namespace {

std::string modes_table(const ModalResult& modes) {
    std::ostringstream out;
    out.precision(10);
    out << "mode,period,frequency,omega,effective_mass_x,effective_mass_y,share_x,share_y\n";
    for (const ModeRow& m : modes.modes)
        out << m.mode << ',' << m.period << ',' << m.frequency << ',' << m.omega << ',' << m.effective_mass_x << ','
            << m.effective_mass_y << ',' << (modes.mass_x > 0.0 ? m.effective_mass_x / modes.mass_x : 0.0) << ','
            << (modes.mass_y > 0.0 ? m.effective_mass_y / modes.mass_y : 0.0) << '\n';
    return out.str();
}

ShapesFound find_modes(const Model& model, int count, int step) {
    ModesAtStep found = modes_at_step(model, count, step);
    ShapesFound out;
    out.state = std::move(found.state);
    out.table = modes_table(found.modes);
    for (const ModeRow& m : found.modes.modes) {
        std::ostringstream line;
        line << "mode " << m.mode << ": T = " << m.period << ", f = " << m.frequency << ", M_x = " << m.effective_mass_x
             << ", M_y = " << m.effective_mass_y;
        out.shapes.push_back({m.mode, m.shape, m.frequency, std::isfinite(m.period) ? m.period : 0.0, line.str()});
    }
    return out;
}

} // namespace

int modes_command(const Args& args) {
    ShapeCommand command;
    command.name = "modes";
    command.usage = "plastica modes SCENE [-n N] [--step K] [-o DIR]";
    command.what = "modes to find";
    command.table_file = "modes.csv";
    command.title = "Modes";
    command.load_label = "frequency";
    command.displacement_label = "period";
    command.find = find_modes;
    return shape_command(args, command);
}

} // namespace plastica::cli
