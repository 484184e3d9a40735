#pragma once
/// @file
/// One writer per output folder. `crossdiv suite` clears the previous run's views and minimal
/// meshes, its workers write their records (workerN.jsonl) and each job's views, and it writes
/// results.json at the end; `crossdiv merge` writes the same files. Two of them in one folder at
/// once delete and mix each other's files and end with results that are neither run's (measured: three suites started
/// into one folder wrote 2,725 cases with 4,770 runs of 37,566). The second is refused instead.

#include <string>

namespace crossdiv::verification {

/// Holds `folder` (created if absent) for this process until destroyed: an exclusive flock(2)
/// on `folder`/.crossdiv-lock, which the kernel drops however the process ends, so a crashed or
/// killed run leaves no stale lock. Forked workers share it; programs started from them do not
/// (close-on-exec).
class OutputFolderLock {
public:
    /// @throws InputError naming the folder when another process holds it, or it cannot be made.
    explicit OutputFolderLock(const std::string& folder);
    ~OutputFolderLock();
    OutputFolderLock(const OutputFolderLock&) = delete;
    OutputFolderLock& operator=(const OutputFolderLock&) = delete;

private:
    int fd_ = -1;
};

}  // namespace crossdiv::verification
