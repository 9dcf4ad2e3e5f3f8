// What `plastica modes` and `plastica buckling` share: a scene's shapes found at a step of its
// run, written as a table and a VTU series of one "step" per shape, then drawn. Each command
// says how its shapes are found, tabled and named (modes_command.cpp, buckling_command.cpp).
#pragma once

#include "commands.hpp"

#include "analysis/step_result.hpp"
#include "model/model.hpp"

#include <functional>
#include <string>
#include <vector>

namespace plastica::cli {

struct Shape {
    int number = 1;
    std::vector<double> displacement; // full DOF vector
    double load = 0.0;                // the curve's value for the shape (a frequency, a load factor)
    double control = 0.0;             // … and its abscissa (a period, the mode's number)
    std::string line;                 // its line on stderr
};

struct ShapesFound {
    StepResult state; // the step they are taken at
    std::vector<Shape> shapes;
    std::string table; // the CSV's text
    std::vector<std::string> notes; // said on stderr before the shapes
};

struct ShapeCommand {
    std::string name;       // "modes"
    std::string usage;      // its synopsis
    std::string what;       // the count's help: "modes to find"
    std::string table_file; // "modes.csv"
    std::string title;      // "Modes"
    std::string load_label, displacement_label; // the series' curve
    // Throws the eigenproblem's error (the analysis stopped early) or std::runtime_error (bad input).
    std::function<ShapesFound(const Model& model, int count, int step)> find;
};

int shape_command(const Args& args, const ShapeCommand& command);

} // namespace plastica::cli
