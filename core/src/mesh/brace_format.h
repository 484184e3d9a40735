#pragma once
// A "{}" substitution for diagnostics in core, which depends on the standard library and
// Eigen only (GCC 12 has no std::format): each "{}" takes the next argument via operator<<.

#include <sstream>
#include <string>
#include <string_view>

namespace crossdiv::detail {

template <class... Args>
std::string brace_format(std::string_view pattern, const Args&... args) {
    std::ostringstream out;
    auto put = [&](const auto& arg) {
        const size_t at = pattern.find("{}");
        out << pattern.substr(0, at);
        if (at == std::string_view::npos) {  // more arguments than "{}": a bug in the caller's pattern
            pattern = {};
            return;
        }
        out << arg;
        pattern.remove_prefix(at + 2);
    };
    (put(args), ...);
    out << pattern;
    return out.str();
}

}  // namespace crossdiv::detail
