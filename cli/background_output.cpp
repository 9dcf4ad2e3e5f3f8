#include "background_output.hpp"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <utility>

namespace plastica::cli {

namespace {

// The memory a copy of the step takes (its vectors' contents and the records they hold).
std::size_t bytes_of(const StepResult& step) {
    std::size_t bytes = sizeof(StepResult) + sizeof(double) * (step.displacement.size() + step.reaction.size() + step.applied_load.size()) +
                        sizeof(ElementResult) * step.elements.size() + sizeof(SpringResult) * step.springs.size();
    for (const ElementResult& e : step.elements) bytes += sizeof(SectionReport) * e.sections.size();
    return bytes;
}

} // namespace

BackgroundOutput::BackgroundOutput(Sink sink, std::size_t capacity, std::size_t batch, std::chrono::milliseconds latency,
                                   std::size_t budget)
    : sink_(std::move(sink)), capacity_(capacity), batch_(std::min(batch, capacity)), budget_(budget), latency_(latency),
      worker_([this] { work(); }) {}

BackgroundOutput::~BackgroundOutput() { finish(); }

void BackgroundOutput::push(const StepResult& step) {
    const std::size_t limit = std::min(capacity_, std::max<std::size_t>(2, budget_ / bytes_of(step)));
    std::unique_ptr<StepResult> copy;
    {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [&] { return queue_.size() < limit || failure_; });
        if (failure_) throw std::runtime_error(failure_->message);
        if (!spare_.empty()) {
            copy = std::move(spare_.back()); // the most recently written: its memory is the warmest
            spare_.pop_back();
        }
    }
    // Copied outside the lock (the writer may go on meanwhile; only this thread adds steps,
    // so the queue cannot have filled up in between).
    if (copy)
        *copy = step;
    else
        copy = std::make_unique<StepResult>(step);
    bool wake = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        queue_.push_back(std::move(copy));
        wake = queue_.size() >= std::min(batch_, limit);
    }
    if (wake) changed_.notify_all();
}

void BackgroundOutput::finish() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        closing_ = true;
    }
    changed_.notify_all();
    if (worker_.joinable()) worker_.join();
}

std::optional<OutputFailure> BackgroundOutput::failure() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return failure_;
}

void BackgroundOutput::work() {
    for (;;) {
        std::unique_lock<std::mutex> lock(mutex_);
        while (queue_.empty() && !closing_) changed_.wait_for(lock, latency_);
        if (queue_.empty()) return; // closing, and everything written
        // The step stays queued while it is written: the queue's length bounds the steps
        // held in memory, the one being written included.
        const StepResult& step = *queue_.front();
        lock.unlock();
        std::optional<OutputFailure> failed;
        try {
            sink_(step);
        } catch (const std::exception& e) {
            failed = OutputFailure{step.step, e.what()};
        }
        lock.lock();
        spare_.push_back(std::move(queue_.front()));
        queue_.pop_front();
        if (failed) {
            failure_ = std::move(failed);
            queue_.clear(); // steps after a failed one are not written
        }
        changed_.notify_all();
        if (failure_) return;
    }
}

} // namespace plastica::cli
