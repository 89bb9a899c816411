// SPDX-License-Identifier: Apache-2.0
#include "bench/gnuplot.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <ctime>

#include <fcntl.h>
#include <pthread.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace cmfilter::bench {

namespace {

std::string errno_text(int error) { return std::strerror(error); }

// Both ends close on exec, so gnuplot inherits only the ends dup2'd onto its
// standard streams.
bool make_pipe(int fds[2]) { return ::pipe2(fds, O_CLOEXEC) == 0; }

void close_fd(int& fd)
{
    if (fd >= 0) ::close(fd);
    fd = -1;
}

// Writes all of `text` to `fd`. A reader that has gone away makes it fail
// with EPIPE rather than raise SIGPIPE: the signal is blocked on this thread
// while writing, and one it raised is taken back before unblocking.
bool write_all(int fd, const std::string& text)
{
    sigset_t pipe_signal, previous, pending;
    sigemptyset(&pipe_signal);
    sigaddset(&pipe_signal, SIGPIPE);
    sigpending(&pending);
    const bool was_pending = sigismember(&pending, SIGPIPE) == 1;
    pthread_sigmask(SIG_BLOCK, &pipe_signal, &previous);
    std::size_t done = 0;
    bool ok = true;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            ok = false;
            if (errno == EPIPE && !was_pending) {
                const timespec none{0, 0};
                while (sigtimedwait(&pipe_signal, nullptr, &none) < 0 && errno == EINTR) {}
            }
            break;
        }
        done += static_cast<std::size_t>(n);
    }
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    return ok;
}

std::string read_all(int fd)
{
    std::string text;
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        text.append(buffer, static_cast<std::size_t>(n));
    }
    return text;
}

}  // namespace

Expected<std::string> run_gnuplot(const std::string& program)
{
    int input[2] = {-1, -1}, output[2] = {-1, -1};
    if (!make_pipe(input) || !make_pipe(output)) {
        const int error = errno;
        close_fd(input[0]), close_fd(input[1]), close_fd(output[0]), close_fd(output[1]);
        return io_error("cannot make a pipe to gnuplot: " + errno_text(error));
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, input[0], STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, output[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, output[1], STDERR_FILENO);
    char name[] = "gnuplot";
    char* argv[] = {name, nullptr};
    pid_t pid = -1;
    const int spawned = posix_spawnp(&pid, name, &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    close_fd(input[0]);
    close_fd(output[1]);
    if (spawned != 0) {
        close_fd(input[1]);
        close_fd(output[0]);
        return io_error("cannot start gnuplot: " + errno_text(spawned));
    }
    // The program is a few kilobytes, far less than a pipe holds: writing it
    // all before reading cannot wait on gnuplot's output.
    write_all(input[1], program);
    close_fd(input[1]);
    const std::string printed = read_all(output[0]);
    close_fd(output[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) return io_error("cannot wait for gnuplot: " + errno_text(errno));
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return printed;
    if (WIFSIGNALED(status))
        return io_error("gnuplot died of signal " + std::to_string(WTERMSIG(status)) +
                        (printed.empty() ? std::string() : ": " + printed));
    return io_error(printed.empty() ? "gnuplot exited with status " + std::to_string(WEXITSTATUS(status)) : printed);
}

}  // namespace cmfilter::bench
