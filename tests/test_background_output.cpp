// The series writer's thread: steps reach the sink in order, and the first one it cannot take
// ends the writing, is reported with its step, and stops the analysis at its next hand-over;
// the queue holds large steps fewer at a time.
#include "background_output.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace plastica;
using namespace plastica::cli;

namespace {
StepResult step(int k) {
    StepResult r;
    r.step = k;
    return r;
}
} // namespace

TEST_CASE("Background output hands every step to the sink in order", "[cli][output]") {
    std::vector<int> written;
    BackgroundOutput output([&](const StepResult& r) { written.push_back(r.step); }, 4);
    for (int k = 0; k < 100; ++k) output.push(step(k)); // more than the queue holds
    output.finish();
    REQUIRE(written.size() == 100u);
    for (int k = 0; k < 100; ++k) CHECK(written[static_cast<std::size_t>(k)] == k);
    CHECK_FALSE(output.failure());
}

TEST_CASE("Background output stops at the first step the sink cannot take", "[cli][output]") {
    std::vector<int> written;
    BackgroundOutput output(
        [&](const StepResult& r) {
            if (r.step == 2) throw std::runtime_error("disk full");
            written.push_back(r.step);
        },
        4);
    bool refused = false;
    for (int k = 0; k < 100 && !refused; ++k) try {
            output.push(step(k));
        } catch (const std::runtime_error& e) {
            refused = true;
            CHECK(std::string(e.what()) == "disk full");
        }
    output.finish();
    CHECK(refused); // the analysis hears of it before its hundredth step
    REQUIRE(output.failure());
    CHECK(output.failure()->step == 2);
    CHECK(output.failure()->message == "disk full");
    CHECK(written == std::vector<int>{0, 1}); // nothing after the failed step
}

TEST_CASE("Background output hands over each step whole, also into the storage of a written one", "[cli][output]") {
    // Steps of changing sizes: a copy into a reused step must leave nothing of the one before.
    const auto varied = [](int k) {
        StepResult r = step(k);
        r.displacement.assign(static_cast<std::size_t>(k % 7), 0.5 * k);
        r.elements.resize(static_cast<std::size_t>((k * 3) % 5));
        for (ElementResult& e : r.elements) e.sections.assign(static_cast<std::size_t>(k % 3), SectionReport{0.0, 0.0, 1.0 * k, 0.0, 0.0});
        return r;
    };
    std::vector<std::string> mismatches;
    BackgroundOutput output(
        [&](const StepResult& r) {
            const StepResult expected = varied(r.step);
            bool same = r.displacement == expected.displacement && r.elements.size() == expected.elements.size();
            for (std::size_t e = 0; same && e < r.elements.size(); ++e) {
                const std::vector<SectionReport>&got = r.elements[e].sections, &want = expected.elements[e].sections;
                same = got.size() == want.size();
                for (std::size_t k = 0; same && k < want.size(); ++k) same = got[k].curvature == want[k].curvature;
            }
            if (!same) mismatches.push_back("step " + std::to_string(r.step));
        },
        3);
    for (int k = 0; k < 200; ++k) output.push(varied(k));
    output.finish();
    CHECK(mismatches.empty());
    CHECK_FALSE(output.failure());
}

TEST_CASE("Background output holds large steps two at a time, small ones up to its capacity", "[cli][output]") {
    // A slow sink: the analysis runs ahead as far as the queue lets it. The step being written
    // counts as queued, so at most `limit` pushed steps are not yet written when the sink runs.
    const auto most_ahead = [](std::size_t doubles) {
        std::atomic<int> pushed{0};
        int written = 0, ahead = 0;
        BackgroundOutput output(
            [&](const StepResult&) {
                ahead = std::max(ahead, pushed.load() - written);
                std::this_thread::sleep_for(std::chrono::milliseconds(2));
                ++written;
            },
            16, 8, std::chrono::milliseconds(20), 256 * 1024);
        for (int k = 0; k < 40; ++k) {
            StepResult r = step(k);
            r.displacement.assign(doubles, 1.0);
            output.push(r);
            ++pushed;
        }
        output.finish();
        return ahead;
    };
    CHECK(most_ahead(100000) <= 2);     // 800 kB a step: two at a time
    const int small = most_ahead(1000); // 8 kB a step: the capacity of 16 binds
    CHECK(small > 2);
    CHECK(small <= 16);
}
