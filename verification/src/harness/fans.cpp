// The fans of the eigen-analysis and the rule oracles (fans.h).
#include "crossdiv/verification/harness/fans.h"

#include <cmath>

namespace crossdiv::verification {

TriMesh loop_fan(int n) {
    TriMesh m;
    m.positions.emplace_back(0.1, -0.2, 0.7);
    for (int k = 0; k < n; ++k)
        m.positions.emplace_back(std::cos(2 * M_PI * k / n) * (1 + 0.1 * k), std::sin(2 * M_PI * k / n), 0.05 * k);
    for (int k = 0; k < n; ++k) m.triangles.push_back({0, 1 + k, 1 + (k + 1) % n});
    return m;
}

PolyMesh quad_fan(int n) {
    PolyMesh m;
    m.positions.emplace_back(0.1, -0.2, 0.7);
    for (int k = 0; k < n; ++k) {
        const double a = 2 * M_PI * k / n, b = a + M_PI / n;
        m.positions.emplace_back(std::cos(a) * (1 + 0.1 * k), std::sin(a), 0.05 * k);
        m.positions.emplace_back(1.6 * std::cos(b), 1.5 * std::sin(b), -0.04 * k);
    }
    for (int k = 0; k < n; ++k) m.add_face({0, 1 + 2 * k, 2 + 2 * k, 1 + 2 * ((k + 1) % n)});
    return m;
}

}  // namespace crossdiv::verification
