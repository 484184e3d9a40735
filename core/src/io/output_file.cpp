#include "crossdiv/io/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <vector>

#include "crossdiv/error.h"

namespace crossdiv {

/// A stream buffer over a file descriptor that keeps the reason of its first failed write.
class OutputFile::Buffer : public std::streambuf {
public:
    explicit Buffer(int fd) : fd_(fd), data_(1 << 16) { setp(data_.data(), data_.data() + data_.size()); }
    ~Buffer() override {
        if (fd_ >= 0) ::close(fd_);
    }
    /// Writes the buffer out and closes the descriptor; 0, or the errno of the first failure.
    int finish() {
        drain();
        if (fd_ >= 0 && ::close(fd_) != 0 && error_ == 0) error_ = errno;
        fd_ = -1;
        return error_;
    }

protected:
    int_type overflow(int_type c) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    int sync() override { return drain() ? 0 : -1; }

private:
    /// Writes what is buffered; false (and the reason kept) once any write has failed.
    bool drain() {
        for (const char* p = pbase(); p < pptr() && error_ == 0;) {
            const ssize_t n = ::write(fd_, p, static_cast<size_t>(pptr() - p));
            if (n > 0) p += n;
            else if (n < 0 && errno != EINTR) error_ = errno;
            else if (n == 0) error_ = EIO;
        }
        setp(data_.data(), data_.data() + data_.size());
        return error_ == 0;
    }
    int fd_;
    int error_ = 0;
    std::vector<char> data_;
};

OutputFile::OutputFile(std::string path) : path_(std::move(path)) {
    const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw InputError(path_ + ": cannot write: " + std::strerror(errno));
    buffer_ = std::make_unique<Buffer>(fd);
    stream_ = std::make_unique<std::ostream>(buffer_.get());
}

OutputFile::~OutputFile() = default;

std::ostream& OutputFile::stream() { return *stream_; }

void OutputFile::close() {
    if (const int error = buffer_->finish(); error != 0)
        throw InputError(path_ + ": cannot write: " + std::strerror(error) + " (the file is incomplete)");
}

void write_text_file(const std::string& path, std::string_view text) {
    OutputFile out(path);
    out.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
}

void create_output_folder(const std::string& folder) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw InputError(folder + ": cannot create the folder: " + ec.message());
    if (!std::filesystem::is_directory(folder)) throw InputError(folder + ": is not a folder");
}

}  // namespace crossdiv
