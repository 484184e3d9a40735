#include "crossdiv/verification/harness/program_server.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>
#include <mutex>
#include <optional>
#include <thread>

#include "sanitizer.h"
#include "spawn_setup.h"

extern char** environ;

namespace crossdiv::verification {
namespace {

/// The descriptor a server answers on (the protocol in program_server.h).
constexpr int kAnswerFd = 3;

/// A server whose stderr has grown past this is started afresh after the run, so that its file
/// in the temporary folder stays small however long the suite.
constexpr off_t kMaxServerStderrBytes = 16 << 20;

/// How long a server is given to exit on the end of its input before its group is killed.
constexpr double kExitGraceSeconds = 2.0;

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Writes all of `text` to the pipe `fd`; false when its reader has gone. The SIGPIPE such a
/// write raises is blocked in this thread and taken back, so a dead server cannot end the
/// harness (nor the Python interpreter that hosts it) and no process-wide handler is changed.
bool write_all(int fd, const std::string& text) {
    sigset_t pipe_signal, before;
    sigemptyset(&pipe_signal);
    sigaddset(&pipe_signal, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_signal, &before);
    sigset_t pending;
    sigpending(&pending);
    const bool already_pending = sigismember(&pending, SIGPIPE) == 1;
    bool ok = true;
    for (size_t done = 0; done < text.size();) {
        const ssize_t n = write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            ok = false;
            break;
        }
        done += static_cast<size_t>(n);
    }
    if (!ok && !already_pending) {
        const timespec now{0, 0};
        while (sigtimedwait(&pipe_signal, nullptr, &now) < 0 && errno == EINTR) {}
    }
    pthread_sigmask(SIG_SETMASK, &before, nullptr);
    return ok;
}

off_t file_size(int fd) {
    struct stat st {};
    return fstat(fd, &st) == 0 ? st.st_size : 0;
}

/// Every ProgramServer of this process (and the copies a fork made of its parent's), for
/// stop_program_servers; never destroyed, as the children's registry is not: a server may
/// be destroyed as the process exits, after other statics.
struct Servers {
    std::mutex mutex;
    std::vector<ProgramServer*> all;
};
Servers& servers() {
    static Servers* s = new Servers;
    return *s;
}

/// What the server wrote on stderr from `offset` on, as stderr_summary puts it.
std::string stderr_since(int fd, off_t offset) { return stderr_summary(head_and_tail(fd, 64 * 1024, offset)); }

}  // namespace

struct ProgramServer::Process {
    pid_t pid = 0;
    int requests = -1;  ///< our end of its standard input
    int answers = -1;   ///< our end of its descriptor 3
    int stderr_fd = -1; ///< its stderr file, read at offsets
    bool reaped = false;  ///< already waited for: its pid may be another process's now
    std::string pending;  ///< answer bytes read past the last full line
    std::optional<RegisteredChild> registration;

    void close_pipes() {
        for (int* fd : {&requests, &answers, &stderr_fd})
            if (*fd >= 0) {
                close(*fd);
                *fd = -1;
            }
    }
};

ProgramServer::ProgramServer(std::vector<std::string> argv, std::string label)
    : argv_(std::move(argv)), label_(std::move(label)), owner_(getpid()) {
    const std::lock_guard lock(servers().mutex);
    servers().all.push_back(this);
}

ProgramServer::~ProgramServer() {
    {
        const std::lock_guard lock(servers().mutex);
        std::erase(servers().all, this);
    }
    if (owner_ != getpid()) {
        // A forked copy: the server and its folder are the parent's; leave both to it.
        if (process_) process_->close_pipes();
        (void)process_.release();
        (void)folder_.release();
        return;
    }
    stop(false);
}

bool ProgramServer::start(std::string& error) {
    if (!folder_) folder_ = std::make_unique<TemporaryFolder>(label_ + "-server");
    const std::string stderr_path = (folder_->path() / "stderr.txt").string();
    int to_server[2], from_server[2];
    if (pipe2(to_server, O_CLOEXEC) != 0) {
        error = std::string("cannot make a pipe: ") + std::strerror(errno);
        return false;
    }
    if (pipe2(from_server, O_CLOEXEC) != 0) {
        error = std::string("cannot make a pipe: ") + std::strerror(errno);
        close(to_server[0]);
        close(to_server[1]);
        return false;
    }
    SpawnSetup setup;
    // Its ends of the pipes at 0 and 3 (dup2 clears close-on-exec on the copies); our ends stay
    // close-on-exec, so no other program we start holds them.
    posix_spawn_file_actions_adddup2(&setup.actions, to_server[0], STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&setup.actions, from_server[1], kAnswerFd);
    posix_spawn_file_actions_addopen(&setup.actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&setup.actions, STDERR_FILENO, stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addchdir_np(&setup.actions, folder_->path().c_str());
    setup.own_process_group();
    std::vector<char*> args;
    for (const std::string& a : argv_) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    keep_adopting_orphans();
    pid_t pid = 0;
    const int e = posix_spawnp(&pid, args[0], &setup.actions, &setup.attributes, args.data(), environ);
    close(to_server[0]);
    close(from_server[1]);
    if (e != 0) {
        close(to_server[1]);
        close(from_server[0]);
        error = "cannot start " + argv_[0] + ": " + std::strerror(e);
        return false;
    }
    process_ = std::make_unique<Process>();
    process_->pid = pid;
    process_->requests = to_server[1];
    process_->answers = from_server[0];
    process_->registration.emplace(pid, ChildRole::ProgramGroup);
#ifndef CROSSDIV_ADDRESS_SANITIZER
    const rlimit memory{static_cast<rlim_t>(kProgramMemoryBytes), static_cast<rlim_t>(kProgramMemoryBytes)};
    prlimit(pid, RLIMIT_DATA, &memory, nullptr);
#endif
    process_->stderr_fd = open(stderr_path.c_str(), O_RDONLY | O_CLOEXEC);
    ++starts_;
    return true;
}

bool ProgramServer::stop(bool at_once, ProcessResult* result) {
    if (!process_) return true;
    Process& p = *process_;
    if (p.requests >= 0) {
        close(p.requests);  // the end of its input: a server that keeps the protocol exits
        p.requests = -1;
    }
    int status = 0;
    bool ended_itself = false;
    if (p.reaped) {
        p.close_pipes();
        process_.reset();
        reap_adopted_orphans();  // what it started, re-parented here
        return true;
    }
    const auto t0 = std::chrono::steady_clock::now();
    for (auto pause = std::chrono::microseconds(200); !at_once && seconds_since(t0) < kExitGraceSeconds;) {
        const pid_t done = waitpid(p.pid, &status, WNOHANG);
        if (done == p.pid) {
            ended_itself = true;
            break;
        }
        if (done < 0 && errno != EINTR) break;
        std::this_thread::sleep_for(pause);
        pause = std::min(pause * 2, std::chrono::microseconds(20000));
    }
    // Whatever it started goes with it, in its group or re-parented here.
    kill(-p.pid, SIGKILL);
    if (!ended_itself)
        while (waitpid(p.pid, &status, 0) < 0 && errno == EINTR) {}
    reap_adopted_orphans();
    if (result && ended_itself) {
        if (WIFSIGNALED(status)) result->signal = WTERMSIG(status);
        else if (WIFEXITED(status)) result->exit_code = WEXITSTATUS(status);
    }
    p.close_pipes();
    process_.reset();
    return ended_itself;
}

ServedRun ProgramServer::run(const std::vector<std::string>& args, double timeout_seconds) {
    ServedRun out;
    ProcessResult& r = out.process;
    if (owner_ != getpid()) {
        // Forked from the process that started it: this process starts a server of its own.
        if (process_) process_->close_pipes();
        (void)process_.release();
        (void)folder_.release();
        owner_ = getpid();
        next_id_ = 1;
    }
    if (process_) {
        // Ended since its last run (killed from outside, or it exited after answering): a new
        // one takes this run, which owes nothing to the last one's end.
        int status = 0;
        const pid_t done = waitpid(process_->pid, &status, WNOHANG);
        if (done == process_->pid || (done < 0 && errno == ECHILD)) {
            process_->reaped = true;
            stop(true);
        }
    }
    const auto t0 = std::chrono::steady_clock::now();
    if (!process_) {
        if (!start(r.start_error)) return out;
        out.started_now = true;
    }
    r.started = true;
    Process& p = *process_;
    const off_t stderr_from = file_size(p.stderr_fd);
    const long long id = next_id_++;
    const nlohmann::json request{{"id", id}, {"args", args}};
    // A server that has died since its last run (killed from outside) reads nothing: the write
    // fails and the run is that server's death.
    const bool sent = write_all(p.requests, request.dump() + "\n");

    // The answer: one line on its descriptor 3, read as it comes.
    std::string line;
    bool answered = false, ended = false;
    while (sent && !answered) {
        const size_t newline = p.pending.find('\n');
        if (newline != std::string::npos) {
            line = p.pending.substr(0, newline);
            p.pending.erase(0, newline + 1);
            answered = true;
            break;
        }
        const double left = timeout_seconds - seconds_since(t0);
        if (left <= 0) {
            r.timed_out = true;
            break;
        }
        pollfd fd{p.answers, POLLIN, 0};
        const int ready = poll(&fd, 1, static_cast<int>(std::min(left * 1000.0, 1e9)) + 1);
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0) continue;  // time is checked at the top
        char buffer[4096];
        const ssize_t n = read(p.answers, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            ended = true;  // it closed descriptor 3 or died
            break;
        }
        p.pending.append(buffer, static_cast<size_t>(n));
        if (p.pending.size() > 4096 && p.pending.find('\n') == std::string::npos) {
            line = p.pending;
            answered = true;  // a "line" without end: read as an answer, found out of turn below
        }
    }
    r.seconds = seconds_since(t0);

    if (answered) {
        // "ID STATUS"
        long long got_id = 0;
        int status = 0, used = 0;
        if (std::sscanf(line.c_str(), "%lld %d%n", &got_id, &status, &used) == 2 && got_id == id &&
            line.find_first_not_of(" \t\r", static_cast<size_t>(used)) == std::string::npos && status >= 0 && status < 256) {
            r.exit_code = status;
            out.stderr_text = stderr_since(p.stderr_fd, stderr_from);
            if (file_size(p.stderr_fd) > kMaxServerStderrBytes) stop(false);
            return out;
        }
        out.out_of_turn = true;
        out.stderr_text = "answered '" + line.substr(0, 200) + "' to request " + std::to_string(id);
        stop(true);
        return out;
    }
    out.stderr_text = stderr_since(p.stderr_fd, stderr_from);
    if (r.timed_out) {
        stop(true);  // killed with its group; the next run starts it again
        return out;
    }
    // It died in the run, or closed its answers: how it ended is how the run ended.
    if (!stop(false, &r) || (r.signal == 0 && r.exit_code == 0)) {
        out.out_of_turn = true;
        out.stderr_text = std::string(ended ? "closed its answers" : "could not be sent the request") +
                          " without ending with a failure" + (out.stderr_text.empty() ? "" : "; stderr: " + out.stderr_text);
    }
    return out;
}

void stop_program_servers() {
    const std::lock_guard lock(servers().mutex);
    for (ProgramServer* s : servers().all)
        if (s->owner_ == getpid()) {
            s->stop(false);
            s->folder_.reset();
        }
}

}  // namespace crossdiv::verification
