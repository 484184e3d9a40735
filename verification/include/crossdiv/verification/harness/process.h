#pragma once
/// @file
/// Running an external program from an argument vector, never through a shell: no quoting,
/// no word splitting, no injection through a file name.

#include <string>
#include <vector>

namespace crossdiv::verification {

/// Runs argv[0] (looked up on PATH when it has no slash) with the arguments argv[1..],
/// inheriting standard output and error, and waits for it. Returns its exit status, or
/// 128 + the signal number when a signal ended it.
/// @throws InputError when the program cannot be started (naming it and the reason).
int run_process(const std::vector<std::string>& argv);

}  // namespace crossdiv::verification
