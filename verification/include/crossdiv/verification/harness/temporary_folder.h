#pragma once
/// @file
/// A temporary folder of its own for a program run, removed with whatever the program left in
/// it when the run ends, or when crossdiv is stopped by a signal meanwhile (interruption.h).

#include <stdlib.h>

#include <filesystem>
#include <optional>
#include <string>
#include <system_error>

#include "crossdiv/error.h"
#include "crossdiv/verification/harness/interruption.h"

namespace crossdiv::verification {

class TemporaryFolder {
public:
    /// @param label part of the folder's name (crossdiv-LABEL-XXXXXX), for whoever finds one.
    /// @throws InputError when the folder cannot be made.
    explicit TemporaryFolder(const std::string& label) {
        namespace fs = std::filesystem;
        std::string pattern = (fs::temp_directory_path() / ("crossdiv-" + label + "-XXXXXX")).string();
        if (!mkdtemp(pattern.data())) throw InputError("cannot create a temporary folder in " + fs::temp_directory_path().string());
        path_ = pattern;
        registration_.emplace(path_.string());
    }
    ~TemporaryFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
    std::optional<RegisteredFolder> registration_;  ///< after path_: unregistered once it is removed
};

}  // namespace crossdiv::verification
