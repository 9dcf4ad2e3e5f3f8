// A study or stability run asked for something the scene cannot give (a parameter it does not
// have, a closed form it does not declare, an unreadable reference curve).
#pragma once

#include <stdexcept>

namespace plastica {

struct StudyError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace plastica
