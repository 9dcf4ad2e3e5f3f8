// Writes converged steps on a thread of its own, so that creating and filling the files of
// one step overlaps solving the next ones (the second core of a workstation is otherwise idle
// while the analysis waits on the file system). The analysis hands over a copy of each step;
// a bounded queue holds those not yet written, so a slow disk holds the analysis back instead
// of filling memory. The first step the sink cannot take (a full disk) ends the writing: later
// steps are dropped, and the analysis hears of the failure at its next step.
// A written step's storage is kept for the next copy: a step's vectors are then assigned into
// room already there, not allocated by one thread and freed by the other (which had cost the
// analysis thread a tenth of its samples in the allocator).
// Steps are handed over in batches: waking the writer costs the analysis a system call and
// the writer a switch (tens of µs on a virtual machine), more than a step of a small model
// takes to solve. The writer is woken when `batch` steps wait; otherwise it looks for steps
// every `latency`, so that no step waits longer than that to be written.
// The queue holds at most `capacity` steps and, beyond two, at most `budget` bytes of them:
// each queued copy is memory touched for the first time, which costs a page fault per 4 kB
// (about 15 µs on this virtual machine): the elastic ring's 18 kB steps in a queue of 64 took
// 160 more faults than in one of 16, and a large model's steps would hold gigabytes.
#pragma once

#include "analysis/step_result.hpp"

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace plastica::cli {

struct OutputFailure {
    int step = 0;        // the step that could not be written
    std::string message; // what the sink threw
};

class BackgroundOutput {
public:
    using Sink = std::function<void(const StepResult&)>;
    explicit BackgroundOutput(Sink sink, std::size_t capacity = 64, std::size_t batch = 8,
                              std::chrono::milliseconds latency = std::chrono::milliseconds(20),
                              std::size_t budget = 256 * 1024);
    ~BackgroundOutput();
    BackgroundOutput(const BackgroundOutput&) = delete;
    BackgroundOutput& operator=(const BackgroundOutput&) = delete;

    // Queues a copy of the step (waits while the queue is full). Throws std::runtime_error
    // with the sink's message once a step could not be written.
    void push(const StepResult& step);
    // Waits until every queued step is written, or the sink failed, and ends the thread.
    void finish();
    std::optional<OutputFailure> failure() const;

private:
    void work();

    Sink sink_;
    std::size_t capacity_;
    std::size_t batch_;
    std::size_t budget_;
    std::chrono::milliseconds latency_;
    mutable std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<std::unique_ptr<StepResult>> queue_;   // the steps not yet written, the first being written
    std::vector<std::unique_ptr<StepResult>> spare_;  // written steps, the last written last
    bool closing_ = false;
    std::optional<OutputFailure> failure_;
    std::thread worker_;
};

} // namespace plastica::cli
