// The one error type of the render stage: what went wrong, naming the file where there is one.
#pragma once

#include <stdexcept>
#include <string>

namespace plastica::render {

struct RenderError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace plastica::render
