#include "crossdiv/io/curve_io.h"

#include <filesystem>

#include "crossdiv/error.h"

namespace crossdiv {

CurveFile read_curve_file(const std::string& path) {
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext == ".swp" || ext == ".SWP") return read_swp(path);
    if (ext == ".bzc" || ext == ".BZC") return read_bzc(path);
    throw InputError(path + ": not a curve file (expected .swp or .bzc)");
}

}  // namespace crossdiv
