#include "crossdiv/io/input_file.h"

#include <filesystem>

#include "crossdiv/error.h"

namespace crossdiv {

std::ifstream open_input_file(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);  // a symbolic link is followed
    if (ec || !fs::exists(st)) throw InputError(path + ": cannot open file: no such file");
    if (!fs::is_regular_file(st))
        throw InputError(path + ": " + (fs::is_directory(st) ? "a folder" : fs::is_fifo(st) ? "a FIFO" : "a device or socket") +
                         ", not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open file");
    return in;
}

}  // namespace crossdiv
