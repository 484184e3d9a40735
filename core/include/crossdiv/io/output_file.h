#pragma once
/// @file
/// Writing a file the user asked for. Every byte is checked: a full disk, a quota or an I/O
/// error while writing or at close is an InputError naming the file and the system's reason,
/// never a success line over a file cut short (a std::ofstream's buffered tail is written
/// only at close, where its destructor drops the error, and its errno is long gone by then).

#include <memory>
#include <ostream>
#include <string>
#include <string_view>

namespace crossdiv {

/// A file open for writing, closed with a check.
class OutputFile {
public:
    /// Opens `path` for writing (created, or truncated).
    /// @throws InputError naming the path and the reason when it cannot be opened.
    explicit OutputFile(std::string path);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;
    /// The stream to write to; its failures are reported by close().
    std::ostream& stream();
    /// Writes what is buffered and closes.
    /// @throws InputError "PATH: cannot write: REASON (the file is incomplete)" when any write failed.
    void close();
    const std::string& path() const { return path_; }

private:
    class Buffer;
    std::string path_;
    std::unique_ptr<Buffer> buffer_;
    std::unique_ptr<std::ostream> stream_;
};

/// Writes `text` to `path` whole, checked (OutputFile).
void write_text_file(const std::string& path, std::string_view text);

/// Creates `folder` and its missing parents.
/// @throws InputError naming the folder and the reason (a file in the way, no permission).
void create_output_folder(const std::string& folder);

}  // namespace crossdiv
