// plastica schema: the result schema (every array a series may hold) as a Markdown table.
#include "commands.hpp"
#include "options.hpp"

#include "result_schema.hpp"

#include <iostream>

namespace plastica::cli {

int schema_command(const Args& args) {
    po::options_description options("Options");
    po::positional_options_description positional;
    po::variables_map vm;
    if (auto code = parse_options(args, "plastica schema", options, positional, vm)) return *code;
    std::cout << result::markdown_table();
    return ok;
}

} // namespace plastica::cli
