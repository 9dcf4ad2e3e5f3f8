// plastica schema: the result schema (every array a series may hold) as a Markdown table, or
// with --scene every scene table's keys (the tables models/README.md carries).
#include "commands.hpp"
#include "options.hpp"

#include "result_schema.hpp"
#include "scene_schema.hpp"

#include <iostream>

namespace plastica::cli {

int schema_command(const Args& args) {
    po::options_description options("Options");
    options.add_options()("scene", po::bool_switch(), "the keys of every scene table, with type, default and meaning");
    po::positional_options_description positional;
    po::variables_map vm;
    if (auto code = parse_options(args, "plastica schema [--scene]", options, positional, vm)) return *code;
    if (!vm["scene"].as<bool>()) {
        std::cout << result::markdown_table();
        return ok;
    }
    for (const TableSpec& table : scene_schema()) std::cout << "## `" << table.heading() << "`\n" << scene_keys_markdown(table) << "\n";
    return ok;
}

} // namespace plastica::cli
