#include "crossdiv/subdiv/level_stencils.h"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

#include "crossdiv/error.h"
#include "loop_level_matrices.h"

namespace crossdiv {
namespace {

using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// FNV-1a over a row's weights, bit for bit: rows with equal weights hash alike.
uint64_t hash_weights(const double* w, int n) {
    uint64_t h = 1469598103934665603ull;
    const auto* bytes = reinterpret_cast<const unsigned char*>(w);
    for (size_t i = 0; i < static_cast<size_t>(n) * sizeof(double); ++i) h = (h ^ bytes[i]) * 1099511628211ull;
    return h;
}

}  // namespace

LevelStencils LevelStencils::loop(const TriMesh& base, const LoopOptions& options, int levels) {
    detail::LoopLevelMatrices levels_of = detail::loop_level_matrices(base, options, levels);
    LevelStencils out;
    out.num_base_ = base.num_vertices();
    for (const RowMajor& S : levels_of.matrices) {
        Level level;
        const int rows = static_cast<int>(S.rows());
        const int* outer = S.outerIndexPtr();
        const double* value = S.valuePtr();
        level.row_start.assign(outer, outer + rows + 1);
        level.source.assign(S.innerIndexPtr(), S.innerIndexPtr() + S.nonZeros());
        // Patterns: rows sorted by the hash of their weights; equal weights (checked bit for
        // bit, not trusted to the hash) share one pattern.
        std::vector<std::pair<uint64_t, int>> keyed(static_cast<size_t>(rows));
        for (int r = 0; r < rows; ++r) keyed[static_cast<size_t>(r)] = {hash_weights(value + outer[r], outer[r + 1] - outer[r]), r};
        std::sort(keyed.begin(), keyed.end());
        level.row_pattern.assign(static_cast<size_t>(rows), -1);
        for (size_t i = 0; i < keyed.size();) {
            size_t j = i;
            while (j < keyed.size() && keyed[j].first == keyed[i].first) ++j;
            // Rows [i, j) share a hash: each takes the first earlier pattern of the group with
            // its very weights, or a new one.
            const size_t first_pattern = level.pattern_start.size() - 1;
            for (size_t k = i; k < j; ++k) {
                const int r = keyed[k].second, n = outer[r + 1] - outer[r];
                int found = -1;
                for (size_t p = first_pattern; p + 1 < level.pattern_start.size() && found < 0; ++p) {
                    const int begin = level.pattern_start[p], size = level.pattern_start[p + 1] - begin;
                    if (size == n && std::memcmp(level.pattern_weight.data() + begin, value + outer[r], sizeof(double) * static_cast<size_t>(n)) == 0)
                        found = static_cast<int>(p);
                }
                if (found < 0) {
                    found = static_cast<int>(level.pattern_start.size()) - 1;
                    level.pattern_weight.insert(level.pattern_weight.end(), value + outer[r], value + outer[r + 1]);
                    level.pattern_start.push_back(static_cast<int>(level.pattern_weight.size()));
                }
                level.row_pattern[static_cast<size_t>(r)] = found;
            }
            i = j;
        }
        out.levels_.push_back(std::move(level));
    }
    out.triangles_ = std::move(levels_of.triangles);
    return out;
}

size_t LevelStencils::num_terms() const {
    size_t n = 0;
    for (const Level& l : levels_) n += l.source.size();
    return n;
}

size_t LevelStencils::num_patterns() const {
    size_t n = 0;
    for (const Level& l : levels_) n += l.pattern_start.size() - 1;
    return n;
}

void LevelStencils::apply_level(const Level& level, const Vec3* in, Vec3* out) {
    static_assert(sizeof(Vec3) == 3 * sizeof(double), "positions are packed triples");
    const double* p = reinterpret_cast<const double*>(in);
    const int* start = level.row_start.data();
    const int* source = level.source.data();
    const int* pattern = level.row_pattern.data();
    const int* pattern_start = level.pattern_start.data();
    const double* pattern_weight = level.pattern_weight.data();
    const int rows = level.rows();
    for (int r = 0; r < rows; ++r) {
        const double* w = pattern_weight + pattern_start[pattern[r]];
        const int* s = source + start[r];
        const int n = start[r + 1] - start[r];
        double x = 0, y = 0, z = 0;
        for (int k = 0; k < n; ++k) {
            const double* q = p + 3 * static_cast<size_t>(s[k]);
            x += w[k] * q[0];
            y += w[k] * q[1];
            z += w[k] * q[2];
        }
        out[r] = Vec3(x, y, z);
    }
}

void LevelStencils::apply(const std::vector<Vec3>& base, std::vector<Vec3>& out, std::vector<Vec3>& scratch) const {
    if (static_cast<int>(base.size()) != num_base_)
        throw InputError("the stencils read " + std::to_string(num_base_) + " base vertices, given " +
                         std::to_string(base.size()));
    if (levels_.empty()) {
        out = base;
        return;
    }
    out.resize(static_cast<size_t>(num_rows()));
    size_t largest_between = 0;
    for (size_t l = 0; l + 1 < levels_.size(); ++l) largest_between = std::max(largest_between, static_cast<size_t>(levels_[l].rows()));
    if (scratch.size() < largest_between) scratch.resize(largest_between);
    // The levels alternate between the two buffers, the last one writing into `out`: level l
    // writes `out` when an even number of levels follow it.
    const Vec3* in = base.data();
    const int last = num_levels() - 1;
    for (int l = 0; l <= last; ++l) {
        Vec3* target = (last - l) % 2 == 0 ? out.data() : scratch.data();
        apply_level(levels_[static_cast<size_t>(l)], in, target);
        in = target;
    }
}

}  // namespace crossdiv
