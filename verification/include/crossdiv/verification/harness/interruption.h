#pragma once
/// @file
/// What crossdiv leaves behind when it is stopped (Ctrl-C, SIGTERM, a closed terminal) or when a
/// program it runs tries to outlive its run: nothing. The programs under test run in process
/// groups of their own, where a terminal's Ctrl-C does not reach them; their temporary folders
/// are removed by destructors that a signal would skip. So the process keeps a registry of the
/// children it started and the folders it uses, and one thread that waits for the signals and
/// clears the registry before the process ends by the same signal.

#include <sys/types.h>

#include <string>

namespace crossdiv::verification {

/// From now on SIGINT, SIGTERM and SIGHUP end this process cleanly: they are blocked in every
/// thread and a watcher thread waits for them; on one it kills every registered child (a running
/// program's whole process group, an isolated library run), asks registered workers to stop
/// (the same signal, then SIGKILL after 5 s), removes every registered folder, says what it
/// stopped on stderr, and ends the process by the signal (exit status 128 + its number in a
/// shell). Call it in main() before any other thread starts, and again in a forked worker
/// (suite and shrink workers), which starts its own watcher and forgets the parent's registry.
/// It also makes this process the reaper of its orphaned descendants (adopt_orphans), so that
/// a program's child that left its process group (setsid) is still found and killed.
void stop_cleanly_on_signals();

/// Whether this process is being stopped (after stop_cleanly_on_signals): its watcher has taken
/// one of the signals, or one waits for it. A terminal's Ctrl-C reaches the workers together with
/// this process, so a worker may have ended by it before the watcher wakes.
bool stop_requested();

/// Waits, without end, for the watcher to end this process. Called once stop_requested(), where
/// the caller would otherwise go on with what the stop cut short (a suite recording every job
/// its stopped workers left as a failure, a line each, before the process ends).
[[noreturn]] void await_stop();

/// Makes this process the subreaper of its descendants (PR_SET_CHILD_SUBREAPER): a process
/// whose parent ends is re-parented here instead of to init, so reap_adopted_orphans finds it.
void adopt_orphans();

/// Makes this process a subreaper again when the process it was forked from is one: fork does
/// not pass the attribute on, so a forked library run that starts a program calls this first.
void keep_adopting_orphans();

/// Kills and reaps every child of this process that it did not start itself (not registered
/// as a RegisteredChild): what a finished program left behind outside its process group, now
/// re-parented here. Does nothing unless adopt_orphans was called, since a host process (the
/// Python interpreter) has children of its own. Returns how many it killed.
int reap_adopted_orphans();

/// How an interruption stops a registered child.
enum class ChildRole {
    ProgramGroup,  ///< a program under test, leader of its own process group: SIGKILL to the group
    Isolated,      ///< a forked library run: SIGKILL
    Worker,        ///< a forked worker that cleans up after itself: the signal, then SIGKILL after 5 s
};

/// While alive, `pid` is a child this process started (so reap_adopted_orphans leaves it alone)
/// and an interruption stops it as its role says.
class RegisteredChild {
public:
    RegisteredChild(pid_t pid, ChildRole role);
    ~RegisteredChild();
    RegisteredChild(const RegisteredChild&) = delete;
    RegisteredChild& operator=(const RegisteredChild&) = delete;

private:
    pid_t pid_;
};

/// While alive, an interruption removes `path` and everything in it.
class RegisteredFolder {
public:
    explicit RegisteredFolder(std::string path);
    ~RegisteredFolder();
    RegisteredFolder(const RegisteredFolder&) = delete;
    RegisteredFolder& operator=(const RegisteredFolder&) = delete;

private:
    std::string path_;
};

}  // namespace crossdiv::verification
