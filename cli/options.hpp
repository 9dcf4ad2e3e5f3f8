// Shared option parsing for the subcommands (Boost.Program_options): a bad option is a
// message and exit code 2, --help prints the command's description.
#pragma once

#include "commands.hpp"

#include <boost/program_options.hpp>
#include <optional>
#include <string>

namespace plastica::cli {

namespace po = boost::program_options;

// Parses args; returns an exit code when the command should stop (help shown or bad input).
std::optional<int> parse_options(const Args& args, const std::string& usage_line,
                                 const po::options_description& options,
                                 const po::positional_options_description& positional,
                                 po::variables_map& values);

} // namespace plastica::cli
