#include "crossdiv/verification/harness/process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/syscall.h>
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
#include "spawn_setup.h"

extern char** environ;

namespace crossdiv::verification {
namespace {

std::vector<char*> c_argv(const std::vector<std::string>& argv) {
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    return args;
}


}  // namespace

bool wait_for_child(pid_t pid, int& status, double seconds) {
    using Clock = std::chrono::steady_clock;
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    // The system call itself: glibc 2.36's <sys/pidfd.h> declares pidfd_open without C linkage.
    const int fd = static_cast<int>(syscall(SYS_pidfd_open, pid, 0));
    for (auto pause = std::chrono::microseconds(200);;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) break;  // not our child (any more): nothing to wait for
        const auto now = Clock::now();
        if (now >= deadline) {
            if (fd >= 0) close(fd);
            return false;
        }
        if (fd >= 0) {
            // Readable when the child ends; a signal or the deadline ends the poll too.
            const long long ms = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count() + 1;
            pollfd p{fd, POLLIN, 0};
            poll(&p, 1, static_cast<int>(std::min<long long>(ms, 1 << 30)));
        } else {
            // No pidfd (a kernel before 5.3): short sleeps, growing.
            std::this_thread::sleep_for(std::min<Clock::duration>(pause, deadline - Clock::now()));
            pause = std::min(pause * 2, std::chrono::microseconds(20000));
        }
    }
    if (fd >= 0) close(fd);
    return true;
}

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
    setup.own_process_group();

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
    if (!wait_for_child(pid, status, limits.timeout_seconds - elapsed())) {
        kill(-pid, SIGKILL);
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
        r.timed_out = true;
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

std::string head_and_tail(int fd, size_t bytes, off_t from) {
    struct stat st {};
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size <= from) return "";
    const size_t size = static_cast<size_t>(st.st_size - from);
    auto read_at = [&](size_t offset, size_t n) {
        std::string s(n, '\0');
        size_t got = 0;
        for (ssize_t k; got < n && (k = pread(fd, s.data() + got, n - got, from + static_cast<off_t>(offset + got))) > 0;)
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
