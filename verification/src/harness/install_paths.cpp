#include "crossdiv/verification/harness/install_paths.h"

#include <filesystem>

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;

/// PREFIX/share/crossdiv/<name> when crossdiv runs from PREFIX/bin and it exists, else `source`.
std::string installed_or(const char* name, const char* source) {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path installed = exe.parent_path().parent_path() / "share" / "crossdiv" / name;
        if (fs::is_directory(installed, ec)) return installed.string();
    }
    return source;
}

}  // namespace

std::string suites_dir() { return installed_or("suites", CROSSDIV_SUITES_DIR); }
std::string reports_dir() { return installed_or("reports", CROSSDIV_REPORTS_DIR); }
std::string adapters_dir() { return installed_or("adapters", CROSSDIV_ADAPTERS_DIR); }

}  // namespace crossdiv::verification
