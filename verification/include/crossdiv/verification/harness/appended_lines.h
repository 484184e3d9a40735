#pragma once
/// @file appended_lines.h
/// Reading a file another process is still appending to, one whole line at a time.

#include <string>
#include <vector>

namespace crossdiv::verification {

/// The lines of a file that a writer appends to while it is read: each call hands over the
/// lines completed since the last one. A line counts only once its newline is in the file, so
/// a line caught half written (even one that already reads as complete JSON, its newline not
/// yet flushed) waits for the next call; a writer that dies mid-line leaves it unread.
class AppendedLines {
public:
    explicit AppendedLines(std::string path) : path_(std::move(path)) {}

    /// The lines completed since the last call, without their newlines; none when the file
    /// does not exist yet.
    std::vector<std::string> take_complete();

private:
    std::string path_;
    long long read_ = 0;  ///< bytes of whole lines already handed over
};

}  // namespace crossdiv::verification
