#include "crossdiv/subdiv/vertex_age.h"

#include <algorithm>
#include <array>
#include <string>

#include "crossdiv/error.h"

namespace crossdiv {

std::vector<int> vertex_birth_levels(std::span<const size_t> counts, bool dual) {
    if (counts.empty()) throw InputError("vertex ages need the vertex count of at least one level");
    for (size_t l = 1; l < counts.size(); ++l)
        if (!dual && counts[l] < counts[l - 1])
            throw InputError("level " + std::to_string(l) + " has fewer vertices (" + std::to_string(counts[l]) +
                             ") than level " + std::to_string(l - 1) + " (" + std::to_string(counts[l - 1]) +
                             "): not a refinement that keeps its old vertices");
    const int last = static_cast<int>(counts.size()) - 1;
    std::vector<int> born(counts.back(), last);
    if (dual) return born;
    size_t start = 0;
    for (int l = 0; l <= last; ++l) {
        std::fill(born.begin() + static_cast<std::ptrdiff_t>(start), born.begin() + static_cast<std::ptrdiff_t>(counts[l]), l);
        start = counts[l];
    }
    return born;
}

Vec3 age_color(int level, int levels) {
    // viridis at 0, 1/8, ..., 1 (matplotlib's table), linearly interpolated.
    static constexpr std::array<std::array<double, 3>, 9> kViridis{{{0.267, 0.005, 0.329},
                                                                      {0.279, 0.175, 0.483},
                                                                      {0.230, 0.322, 0.546},
                                                                      {0.173, 0.449, 0.558},
                                                                      {0.128, 0.567, 0.551},
                                                                      {0.158, 0.684, 0.502},
                                                                      {0.369, 0.789, 0.383},
                                                                      {0.678, 0.864, 0.190},
                                                                      {0.993, 0.906, 0.144}}};
    const double s = levels > 0 ? std::clamp(static_cast<double>(level) / levels, 0.0, 1.0) * 8.0 : 0.0;
    const int i = std::min(static_cast<int>(s), 7);
    const double f = s - i;
    Vec3 c;
    for (int k = 0; k < 3; ++k) c[k] = (1 - f) * kViridis[i][k] + f * kViridis[i + 1][k];
    return c;
}

}  // namespace crossdiv
