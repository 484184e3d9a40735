#pragma once
// For tests that compare with a reference library. A build may be configured without a
// library (its CROSSDIV_WITH_* option OFF); the comparison with it does not exist there, and
// such a test is skipped, naming the option. A library the build was configured with must be
// in the registry: a lost registration fails instead of passing as a skip. The default
// configuration turns every option ON (configure stops when a library is missing), so on
// run.sh and in CI these tests always run.
#include <gtest/gtest.h>

#include <cctype>
#include <initializer_list>
#include <string>
#include <string_view>

#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification::test {

/// The CMake option that builds `library`'s implementation.
inline std::string option_of(std::string_view library) {
    if (library == "eigen") return "CROSSDIV_WITH_EIGEN_SPLINES";
    if (library == "hbr") return "CROSSDIV_WITH_OPENSUBDIV";  // Hbr's headers come with OpenSubdiv
    std::string s = "CROSSDIV_WITH_";
    for (char c : library.substr(0, library.find('-'))) s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

/// Whether the build was configured with `library` (CROSSDIV_CONFIGURED_LIBRARIES, set by CMake).
inline bool configured_with(std::string_view library) {
    const std::string list = std::string(",").append(CROSSDIV_CONFIGURED_LIBRARIES);
    const std::string item = std::string(",").append(library.substr(0, library.find('-'))).append(",");
    return list.find(item) != std::string::npos;
}

/// Why the test cannot run in this build ("" when it can); adds a failure for a library that
/// was configured but is not in the registry.
inline std::string missing_libraries(std::initializer_list<std::string_view> libraries) {
    std::string why;
    for (std::string_view l : libraries) {
        if (configured_with(l)) {
            EXPECT_TRUE(is_built(l)) << l << " was configured (" << option_of(l) << "=ON) but is not in the registry";
            continue;
        }
        why.append(why.empty() ? "" : ", ").append(option_of(l)).append("=OFF");
    }
    return why.empty() ? why : std::string("configured without the library this test compares with (").append(why).append(")");
}

}  // namespace crossdiv::verification::test

/// Skips the test in a build configured without one of the named libraries (see above).
#define CROSSDIV_REQUIRE_LIBRARIES(...)                                                                  \
    do {                                                                                                 \
        const std::string crossdiv_why = ::crossdiv::verification::test::missing_libraries({__VA_ARGS__}); \
        if (!crossdiv_why.empty()) GTEST_SKIP() << crossdiv_why;                                         \
    } while (0)
