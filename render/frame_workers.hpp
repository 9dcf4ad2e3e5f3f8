// Frames drawn on every core: worker processes, forked once the series has been read, each
// with its own OSMesa context and VTK pipeline (VTK's rendering is not meant to be shared
// between threads, and a process of its own keeps each llvmpipe context apart). Worker w of W
// draws frames w, w + W, w + 2W, …; a frame depends only on its step, so the pictures are the
// bytes a single process would draw. Workers report each finished frame to the parent through a
// pipe, and the first error any of them meets is raised in the parent as a RenderError.
#pragma once

#include <cstddef>
#include <functional>

namespace plastica::render {

// Called in a worker after each frame it finished, with the frame's position in the sequence.
using FrameDone = std::function<void(std::size_t frame)>;

// Worker processes to use when the caller leaves it open: one per core this process may run on.
int default_worker_count();

// Runs `draw_share(worker, workers, done)` in `workers` forked processes and returns when all
// have ended. In the parent, `on_started()` is called once the workers run (work of its own, on a
// thread it starts, or files the workers must not inherit), then `on_frame(frame)` in the order
// frames finish (progress, streaming the animation). The parent must not hold an OpenGL
// context or a running thread when it calls this.
void draw_in_workers(int workers, const std::function<void(int worker, int workers, const FrameDone& done)>& draw_share,
                     const std::function<void()>& on_started, const std::function<void(std::size_t frame)>& on_frame);

} // namespace plastica::render
