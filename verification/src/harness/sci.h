#pragma once
// The one number format of every explanation sentence the harness writes ("%.3g").
#include <cstdio>
#include <string>

namespace crossdiv::verification::detail {

inline std::string sci(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
}

}  // namespace crossdiv::verification::detail
