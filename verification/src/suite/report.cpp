#include "crossdiv/verification/suite/report.h"

#include <filesystem>

#include "crossdiv/verification/harness/install_paths.h"
#include "crossdiv/verification/harness/process.h"

namespace crossdiv::verification {

int render_report(const std::string& dir) {
    // Debian's interpreter has matplotlib; a python3 earlier on PATH may not.
    const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    return run_process({python, reports_dir() + "/make_report.py", dir});
}

}  // namespace crossdiv::verification
