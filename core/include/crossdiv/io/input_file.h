#pragma once
/// @file
/// Opening a file the user names as input. Only a regular file is read (a symbolic link to
/// one is): a device such as /dev/zero would be read without end, a FIFO would block, and a
/// folder reads as nothing, each taken for an empty input.

#include <fstream>
#include <string>

namespace crossdiv {

/// The file at `path`, open for reading (binary).
/// @throws InputError naming the path when it is missing, not a regular file, or unreadable.
std::ifstream open_input_file(const std::string& path);

}  // namespace crossdiv
