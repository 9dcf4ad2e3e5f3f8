// Stopping a drawing on SIGINT or SIGTERM: the signal handler only sets a flag; the drawing
// checks it between frames and while it waits for its workers, and unwinds, so that its
// temporary files are removed on the way out.
#pragma once

#include <stdexcept>

namespace plastica::render {

struct RenderInterrupted : std::runtime_error {
    RenderInterrupted() : std::runtime_error("interrupted") {}
};

// Async-signal-safe: for a signal handler.
void request_render_stop() noexcept;
bool render_stop_requested() noexcept;
// Throws RenderInterrupted once a stop was requested.
void throw_if_render_stopped();
// Installs a handler for SIGINT and SIGTERM that requests a stop (without SA_RESTART, so that a
// wait on the workers returns), and puts the previous handlers back when it goes.
class StopOnSignal {
public:
    StopOnSignal();
    ~StopOnSignal();
    StopOnSignal(const StopOnSignal&) = delete;
    StopOnSignal& operator=(const StopOnSignal&) = delete;

private:
    struct Saved;
    Saved* saved_;
};

} // namespace plastica::render
