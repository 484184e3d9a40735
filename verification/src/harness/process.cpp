#include "crossdiv/verification/harness/process.h"

#include <fcntl.h>
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
#include <fstream>
#include <sstream>
#include <thread>

#include "crossdiv/error.h"
#include "crossdiv/verification/harness/interruption.h"
#include "sanitizer.h"

extern char** environ;

namespace crossdiv::verification {
namespace {

std::vector<char*> c_argv(const std::vector<std::string>& argv) {
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    return args;
}

/// posix_spawn's file actions and attributes, released on every path. A program starts with
/// no signal blocked and SIGINT, SIGTERM, SIGHUP at their defaults, whatever this process does
/// with them (stop_cleanly_on_signals blocks them here).
struct SpawnSetup {
    posix_spawn_file_actions_t actions;
    posix_spawnattr_t attributes;
    SpawnSetup() {
        posix_spawn_file_actions_init(&actions);
        posix_spawnattr_init(&attributes);
        sigset_t none, defaults;
        sigemptyset(&none);
        sigemptyset(&defaults);
        for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) sigaddset(&defaults, sig);
        posix_spawnattr_setsigmask(&attributes, &none);
        posix_spawnattr_setsigdefault(&attributes, &defaults);
        posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
    }
    ~SpawnSetup() {
        posix_spawn_file_actions_destroy(&actions);
        posix_spawnattr_destroy(&attributes);
    }
    SpawnSetup(const SpawnSetup&) = delete;
    SpawnSetup& operator=(const SpawnSetup&) = delete;
};

}  // namespace

int run_process(const std::vector<std::string>& argv) {
    if (argv.empty()) throw InputError("run_process: no program given");
    std::vector<char*> args = c_argv(argv);
    std::fflush(nullptr);  // our buffered lines first, then the program's
    SpawnSetup setup;
    pid_t pid = 0;
    if (const int err = posix_spawnp(&pid, args[0], nullptr, &setup.attributes, args.data(), environ); err != 0)
        throw InputError("cannot start " + argv[0] + ": " + std::strerror(err));
    const RegisteredChild registration(pid, ChildRole::Isolated);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw InputError("waiting for " + argv[0] + ": " + std::strerror(errno));
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

ProcessResult run_confined(const std::vector<std::string>& argv, const ProcessLimits& limits) {
    ProcessResult r;
    if (argv.empty()) {
        r.start_error = "no program given";
        return r;
    }
    SpawnSetup setup;
    const char* out = limits.stdout_path.empty() ? "/dev/null" : limits.stdout_path.c_str();
    const char* err = limits.stderr_path.empty() ? "/dev/null" : limits.stderr_path.c_str();
    posix_spawn_file_actions_addopen(&setup.actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&setup.actions, STDOUT_FILENO, out, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&setup.actions, STDERR_FILENO, err, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (!limits.working_dir.empty()) posix_spawn_file_actions_addchdir_np(&setup.actions, limits.working_dir.c_str());
    // Its own process group: a time-out kills the interpreter and whatever it started.
    short flags = 0;
    posix_spawnattr_getflags(&setup.attributes, &flags);
    posix_spawnattr_setflags(&setup.attributes, flags | POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&setup.attributes, 0);

    std::vector<char*> args = c_argv(argv);
    std::fflush(nullptr);
    keep_adopting_orphans();  // in a forked library run too, whatever the program leaves is ours
    const auto t0 = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    pid_t pid = 0;
    if (const int e = posix_spawnp(&pid, args[0], &setup.actions, &setup.attributes, args.data(), environ); e != 0) {
        r.start_error = "cannot start " + argv[0] + ": " + std::strerror(e);
        return r;
    }
    r.started = true;
    const RegisteredChild registration(pid, ChildRole::ProgramGroup);
#ifndef CROSSDIV_ADDRESS_SANITIZER
    // Set as it starts (posix_spawn returns once the program is exec'd; an interpreter takes
    // milliseconds more before it runs the program's first line).
    const rlimit memory{static_cast<rlim_t>(kProgramMemoryBytes), static_cast<rlim_t>(kProgramMemoryBytes)};
    prlimit(pid, RLIMIT_DATA, &memory, nullptr);
#endif
    int status = 0;
    for (auto pause = std::chrono::microseconds(200);;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) break;
        if (elapsed() > limits.timeout_seconds) {
            kill(-pid, SIGKILL);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
            r.timed_out = true;
            break;
        }
        std::this_thread::sleep_for(pause);
        pause = std::min(pause * 2, std::chrono::microseconds(20000));
    }
    // Whatever it left running in its group goes with it, and whatever left the group
    // (setsid) and was re-parented here when its parent ended.
    kill(-pid, SIGKILL);
    reap_adopted_orphans();
    r.seconds = elapsed();
    if (!r.timed_out) {
        if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
        else r.exit_code = WEXITSTATUS(status);
    }
    return r;
}

std::string stderr_summary(std::string s, size_t max_chars) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '\r')) s.pop_back();
    std::string first_report;
    if (s.size() > max_chars) {
        // "==123==ERROR: AddressSanitizer: heap-buffer-overflow ...", "file:line: runtime error: ..."
        for (const char* marker : {"ERROR: AddressSanitizer", "ERROR: LeakSanitizer", "runtime error:", "Sanitizer:"}) {
            const size_t at = s.find(marker);
            if (at == std::string::npos || at >= s.size() - max_chars) continue;
            const size_t begin = s.rfind('\n', at), end = s.find('\n', at);
            first_report = s.substr(begin == std::string::npos ? 0 : begin + 1,
                                    (end == std::string::npos ? s.size() : end) - (begin == std::string::npos ? 0 : begin + 1));
            break;
        }
        s = "..." + s.substr(s.size() - max_chars);
        if (!first_report.empty()) s = first_report + " " + s;
    }
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    return s;
}

std::string head_and_tail(int fd, size_t bytes) {
    struct stat st {};
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) return "";
    const size_t size = static_cast<size_t>(st.st_size);
    auto read_at = [&](size_t offset, size_t n) {
        std::string s(n, '\0');
        size_t got = 0;
        for (ssize_t k; got < n && (k = pread(fd, s.data() + got, n - got, static_cast<off_t>(offset + got))) > 0;)
            got += static_cast<size_t>(k);
        s.resize(got);
        return s;
    };
    if (size <= 2 * bytes) return read_at(0, size);
    return read_at(0, bytes) + "\n...\n" + read_at(size - bytes, bytes);
}

std::string tail_of_file(const std::string& path, size_t max_chars) {
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return "";
    std::string text = head_and_tail(fd);
    close(fd);
    return stderr_summary(std::move(text), max_chars);
}

}  // namespace crossdiv::verification
