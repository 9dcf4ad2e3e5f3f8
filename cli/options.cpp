#include "options.hpp"

#include <iostream>

namespace plastica::cli {

std::optional<int> parse_options(const Args& args, const std::string& usage_line,
                                 const po::options_description& options,
                                 const po::positional_options_description& positional,
                                 po::variables_map& values) {
    po::options_description all = options;
    all.add_options()("help,h", "show this help");
    try {
        po::store(po::command_line_parser(args).options(all).positional(positional).run(), values);
        if (values.count("help")) {
            std::cout << "Usage: " << usage_line << "\n\n" << all;
            return ok;
        }
        po::notify(values);
    } catch (const po::error& e) {
        std::cerr << "plastica: " << e.what() << "\nUsage: " << usage_line << "\n";
        return bad_input;
    }
    return std::nullopt;
}

} // namespace plastica::cli
