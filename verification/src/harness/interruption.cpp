#include "crossdiv/verification/harness/interruption.h"

#include <dirent.h>
#include <pthread.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <mutex>
#include <new>
#include <thread>
#include <type_traits>
#include <vector>

namespace crossdiv::verification {
namespace {

struct Registry {
    std::mutex mutex;
    std::vector<std::pair<pid_t, ChildRole>> children;
    std::vector<std::string> folders;
    bool adopting = false;
};

/// Set by the watcher when it takes a signal (stop_requested).
std::atomic<bool> stopping{false};

/// The registry of this process. A forked worker starts it afresh (stop_cleanly_on_signals):
/// the copy it inherits lists its parent's children, and its mutex may be in any state. Never
/// destroyed: objects that outlive main (a registered reference's program server, stopped by
/// the registry of implementations as the process exits) still register and unregister here.
Registry& registry() {
    static Registry& r = *new Registry;
    return r;
}

/// A child of this process as /proc tells it: its id and its process group.
struct ChildProcess {
    pid_t pid;
    pid_t group;
};

/// The parent and process group of process `pid` from /proc/PID/stat (the 2nd and 3rd fields
/// after the parenthesised command name, which may itself hold spaces or parentheses); false
/// when it has ended.
bool parent_and_group(const char* pid, int& parent, int& group) {
    char path[300], text[512];  // /proc/ + a name of up to 255 bytes + /stat
    std::snprintf(path, sizeof path, "/proc/%s/stat", pid);
    FILE* f = std::fopen(path, "r");
    if (!f) return false;
    const size_t n = std::fread(text, 1, sizeof text - 1, f);
    std::fclose(f);
    text[n] = '\0';
    const char* close = std::strrchr(text, ')');
    char state = 0;
    return close && std::sscanf(close + 1, " %c %d %d", &state, &parent, &group) == 3;
}

/// Every child of this process, read from /proc/self/task/TID/children: each thread's, since an
/// orphan is re-parented to any thread of its reaper. That costs a read per thread, not per
/// process on the machine; a kernel without those files (CONFIG_PROC_CHILDREN) has /proc
/// scanned for the processes whose parent is this one instead.
std::vector<ChildProcess> children_of_this_process() {
    std::vector<ChildProcess> found;
    const pid_t self = getpid();
    const auto add = [&](const char* pid) {
        int parent = 0, group = 0;
        if (parent_and_group(pid, parent, group) && parent == self) found.push_back({static_cast<pid_t>(std::atoi(pid)), group});
    };
    bool listed = false;
    if (DIR* tasks = opendir("/proc/self/task")) {
        while (const dirent* task = readdir(tasks)) {
            if (task->d_name[0] < '0' || task->d_name[0] > '9') continue;
            char path[300];
            std::snprintf(path, sizeof path, "/proc/self/task/%s/children", task->d_name);
            FILE* f = std::fopen(path, "r");
            if (!f) continue;
            listed = true;
            char pid[32];
            while (std::fscanf(f, "%31s", pid) == 1) add(pid);
            std::fclose(f);
        }
        closedir(tasks);
    }
    if (listed) return found;
    DIR* proc = opendir("/proc");
    if (!proc) return found;
    while (const dirent* entry = readdir(proc))
        if (entry->d_name[0] >= '0' && entry->d_name[0] <= '9') add(entry->d_name);
    closedir(proc);
    return found;
}

bool registered(const Registry& r, pid_t pid) {
    return std::any_of(r.children.begin(), r.children.end(), [&](const auto& c) { return c.first == pid; });
}

/// Kills (SIGKILL, with its process group when it leads one) and reaps every child that
/// `spare` does not keep, again and again as their own orphans are re-parented here.
int kill_children(const std::function<bool(pid_t)>& spare) {
    int killed = 0;
    for (int round = 0; round < 64; ++round) {
        std::vector<pid_t> victims;
        for (const ChildProcess& c : children_of_this_process()) {
            if (spare(c.pid)) continue;
            if (c.group == c.pid) kill(-c.pid, SIGKILL);
            kill(c.pid, SIGKILL);
            victims.push_back(c.pid);
        }
        if (victims.empty()) break;
        for (const pid_t pid : victims)
            while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {}
        killed += static_cast<int>(victims.size());
    }
    return killed;
}

/// The watcher's work on a signal: stop everything this process started, remove its folders,
/// end by the signal. The registry stays locked: nothing new starts meanwhile.
[[noreturn]] void stop_everything(int sig, Registry& r) {
    r.mutex.lock();
    // Workers clean up after themselves: they get the signal and 5 s.
    std::vector<pid_t> workers;
    for (const auto& [pid, role] : r.children)
        if (role == ChildRole::Worker && kill(pid, sig) == 0) workers.push_back(pid);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (!workers.empty() && std::chrono::steady_clock::now() < deadline) {
        std::erase_if(workers, [](pid_t pid) { return waitpid(pid, nullptr, WNOHANG) == pid; });
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    // Every other child (also one started a moment ago, not yet registered), with its group.
    const int killed = kill_children([](pid_t) { return false; });
    int removed = 0;
    for (const std::string& folder : r.folders) {
        std::error_code ignored;
        if (std::filesystem::remove_all(folder, ignored) > 0) ++removed;
    }
    if (killed > 0 || removed > 0)
        std::fprintf(stderr, "crossdiv: stopped by %s: %d process(es) killed, %d temporary folder(s) removed\n",
                     sigabbrev_np(sig) ? sigabbrev_np(sig) : "a signal", killed, removed);
    std::fflush(nullptr);
    // End by the signal itself, so that a shell or a parent sees how this process ended.
    signal(sig, SIG_DFL);
    sigset_t one;
    sigemptyset(&one);
    sigaddset(&one, sig);
    pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
    raise(sig);
    _exit(128 + sig);
}

/// SIGINT, SIGTERM and SIGHUP, but not one this process was started ignoring (nohup ignores
/// SIGHUP, a shell SIGINT for a background job): that choice of the caller stands.
sigset_t stopping_signals() {
    sigset_t set;
    sigemptyset(&set);
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction current {};
        if (sigaction(sig, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
        sigaddset(&set, sig);
    }
    return set;
}

}  // namespace

void stop_cleanly_on_signals() {
    // A worker forgets its parent's registry, rebuilt in place (std::mutex is trivially
    // destructible, so one held by a parent's thread at the fork is simply replaced).
    static_assert(std::is_trivially_destructible_v<std::mutex>);
    Registry& r = registry();
    r.~Registry();
    new (&r) Registry;
    const sigset_t set = stopping_signals();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    adopt_orphans();
    stopping = false;
    std::thread([set] {
        int sig = 0;
        while (sigwait(&set, &sig) != 0) {}
        stopping = true;
        stop_everything(sig, registry());
    }).detach();
}

bool stop_requested() {
    if (stopping) return true;
    sigset_t pending;
    if (sigpending(&pending) != 0) return false;
    const sigset_t watched = stopping_signals();
    for (int sig : {SIGINT, SIGTERM, SIGHUP})
        if (sigismember(&watched, sig) == 1 && sigismember(&pending, sig) == 1) return true;
    return false;
}

void await_stop() {
    for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
}

void adopt_orphans() {
    if (prctl(PR_SET_CHILD_SUBREAPER, 1) == 0) {
        const std::lock_guard lock(registry().mutex);
        registry().adopting = true;
    }
}

void keep_adopting_orphans() {
    if (registry().adopting) prctl(PR_SET_CHILD_SUBREAPER, 1);
}

int reap_adopted_orphans() {
    Registry& r = registry();
    const std::lock_guard lock(r.mutex);
    if (!r.adopting) return 0;
    return kill_children([&](pid_t pid) { return registered(r, pid); });
}

RegisteredChild::RegisteredChild(pid_t pid, ChildRole role) : pid_(pid) {
    const std::lock_guard lock(registry().mutex);
    registry().children.emplace_back(pid, role);
}

RegisteredChild::~RegisteredChild() {
    const std::lock_guard lock(registry().mutex);
    std::erase_if(registry().children, [&](const auto& c) { return c.first == pid_; });
}

RegisteredFolder::RegisteredFolder(std::string path) : path_(std::move(path)) {
    const std::lock_guard lock(registry().mutex);
    registry().folders.push_back(path_);
}

RegisteredFolder::~RegisteredFolder() {
    const std::lock_guard lock(registry().mutex);
    const auto it = std::find(registry().folders.begin(), registry().folders.end(), path_);
    if (it != registry().folders.end()) registry().folders.erase(it);
}

}  // namespace crossdiv::verification
