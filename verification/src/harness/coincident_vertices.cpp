#include "crossdiv/verification/harness/coincident_vertices.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace crossdiv::verification {

bool has_vertices_within(std::span<const Vec3> positions, double distance) {
    if (!(distance > 0)) {
        std::vector<std::array<double, 3>> p;
        p.reserve(positions.size());
        for (const Vec3& x : positions) p.push_back({x.x(), x.y(), x.z()});
        std::sort(p.begin(), p.end());
        return std::adjacent_find(p.begin(), p.end()) != p.end();
    }
    // Cell numbers as doubles: far from the origin, where x / distance passes 2^53, the
    // neighbour numbers collapse onto the cell's own, which still holds the points within reach.
    using Cell = std::array<double, 3>;
    std::vector<std::pair<Cell, int>> cells;
    cells.reserve(positions.size());
    for (size_t v = 0; v < positions.size(); ++v) {
        const Vec3& x = positions[v];
        cells.push_back({{std::floor(x.x() / distance), std::floor(x.y() / distance), std::floor(x.z() / distance)}, static_cast<int>(v)});
    }
    std::sort(cells.begin(), cells.end());
    for (const auto& [cell, v] : cells)
        for (double dx = -1; dx <= 1; ++dx)
            for (double dy = -1; dy <= 1; ++dy)
                for (double dz = -1; dz <= 1; ++dz) {
                    const Cell near{cell[0] + dx, cell[1] + dy, cell[2] + dz};
                    auto it = std::lower_bound(cells.begin(), cells.end(), std::pair<Cell, int>{near, -1});
                    for (; it != cells.end() && it->first == near; ++it)
                        if (it->second != v &&
                            (positions[static_cast<size_t>(it->second)] - positions[static_cast<size_t>(v)]).norm() <= distance)
                            return true;
                }
    return false;
}

size_t vertices_float_cannot_tell_apart(std::span<const Vec3> positions) {
    std::vector<std::array<float, 3>> p;
    p.reserve(positions.size());
    for (const Vec3& x : positions) p.push_back({static_cast<float>(x.x()), static_cast<float>(x.y()), static_cast<float>(x.z())});
    std::sort(p.begin(), p.end());
    size_t shared = 0;
    for (size_t i = 0; i < p.size(); ++i)
        if ((i > 0 && p[i] == p[i - 1]) || (i + 1 < p.size() && p[i] == p[i + 1])) ++shared;
    return shared;
}

}  // namespace crossdiv::verification
