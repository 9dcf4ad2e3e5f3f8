#include "frame_workers.hpp"
#include "render_error.hpp"
#include "interruption.hpp"

#include "atomic_file.hpp"

#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace plastica::render {

namespace {

// One line per message; a write of at most PIPE_BUF bytes is never interleaved with another
// worker's, so lines arrive whole.
void send_line(int fd, std::string line) {
    std::replace(line.begin(), line.end(), '\n', ' ');
    if (line.size() > 1000) line.resize(1000);
    line += '\n';
    const char* p = line.data();
    std::size_t left = line.size();
    while (left > 0) {
        const ssize_t n = write(fd, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return; // the parent is gone: nothing to tell
        p += n;
        left -= static_cast<std::size_t>(n);
    }
}

[[noreturn]] void work(int fd, int worker, int workers,
                       const std::function<void(int, int, const FrameDone&)>& draw_share) {
    int status = 0;
    // A worker ends at its parent's SIGTERM (the parent's own handler, inherited, would only set a flag here).
    signal(SIGTERM, SIG_DFL);
    signal(SIGINT, SIG_DFL);
    try {
        draw_share(worker, workers, [fd](std::size_t frame) { send_line(fd, "done " + std::to_string(frame)); });
    } catch (const WriteError& e) {
        // Output that could not be written (a full disk) is told apart from bad input.
        send_line(fd, std::string("write-error ") + e.what());
        status = 1;
    } catch (const std::exception& e) {
        send_line(fd, std::string("error ") + e.what());
        status = 1;
    } catch (...) {
        send_line(fd, "error a drawing process failed");
        status = 1;
    }
    // No exit handlers: they belong to the parent (its test framework, its open files).
    _exit(status);
}

void stop_all(const std::vector<pid_t>& pids) {
    for (pid_t pid : pids) kill(pid, SIGTERM);
    for (pid_t pid : pids) waitpid(pid, nullptr, 0);
}

} // namespace

int default_worker_count() {
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
    return static_cast<int>(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));
}

void draw_in_workers(int workers, const std::function<void(int, int, const FrameDone&)>& draw_share,
                     const std::function<void()>& on_started, const std::function<void(std::size_t)>& on_frame) {
    workers = std::max(1, workers);
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw RenderError(std::string("cannot open a pipe to the drawing processes: ") + std::strerror(errno));
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    std::vector<pid_t> pids;
    for (int w = 0; w < workers; ++w) {
        const pid_t pid = fork();
        if (pid == 0) {
            close(fds[0]);
            work(fds[1], w, workers, draw_share);
        }
        if (pid < 0) {
            const int error = errno;
            close(fds[0]);
            close(fds[1]);
            stop_all(pids);
            throw RenderError(std::string("cannot start a drawing process: ") + std::strerror(error));
        }
        pids.push_back(pid);
    }
    close(fds[1]);

    std::string first_error, pending;
    bool failed_to_write = false;
    try {
        on_started();
        char buffer[4096];
        for (;;) {
            const ssize_t n = read(fds[0], buffer, sizeof buffer);
            throw_if_render_stopped();
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) break; // every worker has closed its end
            pending.append(buffer, static_cast<std::size_t>(n));
            for (std::size_t end; (end = pending.find('\n')) != std::string::npos; pending.erase(0, end + 1)) {
                const std::string line = pending.substr(0, end);
                if (line.rfind("done ", 0) == 0) on_frame(std::stoul(line.substr(5)));
                else if (line.rfind("error ", 0) == 0 && first_error.empty()) first_error = line.substr(6);
                else if (line.rfind("write-error ", 0) == 0 && first_error.empty()) first_error = line, failed_to_write = true;
            }
        }
    } catch (...) {
        close(fds[0]);
        stop_all(pids);
        throw;
    }
    close(fds[0]);
    std::string ended_badly;
    for (pid_t pid : pids) {
        int status = 0;
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
        if (WIFSIGNALED(status) && ended_badly.empty())
            ended_badly = std::string("a drawing process ended by signal ") + strsignal(WTERMSIG(status));
        else if (WIFEXITED(status) && WEXITSTATUS(status) != 0 && ended_badly.empty())
            ended_badly = "a drawing process failed (exit " + std::to_string(WEXITSTATUS(status)) + ")";
    }
    throw_if_render_stopped();
    if (failed_to_write) throw WriteError(first_error.substr(12));
    if (!first_error.empty()) throw RenderError(first_error);
    if (!ended_badly.empty()) throw RenderError(ended_badly);
}

} // namespace plastica::render
