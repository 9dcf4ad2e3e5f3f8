#include "interruption.hpp"

#include <signal.h>

#include <atomic>

namespace plastica::render {

namespace {
std::atomic<bool> stop_requested{false};
extern "C" void on_stop_signal(int) { request_render_stop(); }
} // namespace

void request_render_stop() noexcept { stop_requested.store(true); }
bool render_stop_requested() noexcept { return stop_requested.load(); }
void throw_if_render_stopped() {
    if (stop_requested.load()) throw RenderInterrupted();
}

struct StopOnSignal::Saved {
    struct sigaction interrupt {}, terminate {};
};

StopOnSignal::StopOnSignal() : saved_(new Saved) {
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0;
    sigaction(SIGINT, &action, &saved_->interrupt);
    sigaction(SIGTERM, &action, &saved_->terminate);
}

StopOnSignal::~StopOnSignal() {
    sigaction(SIGINT, &saved_->interrupt, nullptr);
    sigaction(SIGTERM, &saved_->terminate, nullptr);
    delete saved_;
}

} // namespace plastica::render
