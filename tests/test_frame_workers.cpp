// The pool of drawing processes on its own: every frame drawn once by the worker it belongs
// to, the parent told of each as it finishes, and a worker's failure raised in the parent.
#include "frame_workers.hpp"
#include "render_error.hpp"

#include <catch2/catch.hpp>

#include <csignal>
#include <cstdlib>
#include <set>
#include <string>

using namespace plastica::render;

TEST_CASE("Workers share the frames and report each one to the parent", "[render][workers]") {
    constexpr std::size_t frames = 23;
    for (int workers : {1, 2, 5}) {
        std::multiset<std::size_t> reported;
        int started = 0;
        draw_in_workers(
            workers,
            [](int worker, int count, const FrameDone& done) {
                for (std::size_t k = static_cast<std::size_t>(worker); k < frames; k += static_cast<std::size_t>(count)) done(k);
            },
            [&] { ++started; }, [&](std::size_t k) { reported.insert(k); });
        CHECK(started == 1);
        REQUIRE(reported.size() == frames);
        for (std::size_t k = 0; k < frames; ++k) CHECK(reported.count(k) == 1);
    }
    CHECK(default_worker_count() >= 1);
}

TEST_CASE("A worker's error or crash reaches the parent", "[render][workers]") {
    auto failure = [](auto draw_share) {
        std::set<std::size_t> reported;
        try {
            draw_in_workers(3, draw_share, [] {}, [&](std::size_t k) { reported.insert(k); });
        } catch (const RenderError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    SECTION("an exception, with its message") {
        CHECK(failure([](int worker, int, const FrameDone& done) {
                  done(static_cast<std::size_t>(worker));
                  if (worker == 1) throw RenderError("step_000007.vtu: unreadable");
              }) == "step_000007.vtu: unreadable");
    }
    SECTION("a crash, by its signal") {
        CHECK_THAT(failure([](int worker, int, const FrameDone&) {
                       if (worker == 2) raise(SIGKILL); // uncatchable, like a crash past any handler
                   }),
                   Catch::Contains("a drawing process ended by signal"));
    }
}
