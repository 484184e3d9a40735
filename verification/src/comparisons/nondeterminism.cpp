#include "crossdiv/verification/comparisons/nondeterminism.h"

#include <algorithm>
#include <bit>
#include <cstdint>

#include <fmt/format.h>

#include <cstring>

#include "harness/sci.h"

namespace crossdiv::verification {
namespace {

using detail::sci;

std::string point_text(const Vec3& p) { return fmt::format("({}, {}, {})", sci(p.x()), sci(p.y()), sci(p.z())); }

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }

}  // namespace

std::optional<std::string> first_difference(const IsolatedTrace& a, const IsolatedTrace& b) {
    if (a.outcome.status != b.outcome.status)
        return fmt::format("one run ended {}, the other {}", to_string(a.outcome.status), to_string(b.outcome.status));
    if (!a.trace || !b.trace) return std::nullopt;
    if (a.trace->size() != b.trace->size())
        return fmt::format("one run made {} levels, the other {}", a.trace->size() - 1, b.trace->size() - 1);
    for (size_t l = 0; l < a.trace->size(); ++l) {
        const PolyMesh &x = (*a.trace)[l], &y = (*b.trace)[l];
        if (x.num_vertices() != y.num_vertices() || x.num_faces() != y.num_faces())
            return fmt::format("level {} has {} vertices and {} faces in one run, {} and {} in the other", l, x.num_vertices(),
                               x.num_faces(), y.num_vertices(), y.num_faces());
        for (int v = 0; v < x.num_vertices(); ++v)
            if (!same_bits(x.positions[v], y.positions[v]))
                return fmt::format("level {} vertex {} is {} in one run and {} in the other", l, v, point_text(x.positions[v]),
                                   point_text(y.positions[v]));
        if (x.face_start != y.face_start || x.face_vertices != y.face_vertices)
            return fmt::format("level {}'s faces differ between the runs", l);
        // Face-varying values too, bit for bit, with their indexing.
        if (x.face_varying.size() != y.face_varying.size())
            return fmt::format("level {} has {} face-varying channels in one run, {} in the other", l, x.face_varying.size(),
                               y.face_varying.size());
        for (size_t k = 0; k < x.face_varying.size(); ++k) {
            const FaceVaryingChannel &p = x.face_varying[k], &q = y.face_varying[k];
            if (p.corner_values != q.corner_values || p.values.size() != q.values.size())
                return fmt::format("level {}'s face-varying channel '{}' is indexed differently in the two runs", l, p.name);
            for (size_t i = 0; i < p.values.size(); ++i)
                if (std::bit_cast<std::uint64_t>(p.values[i]) != std::bit_cast<std::uint64_t>(q.values[i]))
                    return fmt::format("level {}'s face-varying value {} of channel '{}' is {} in one run and {} in the other", l,
                                       i / static_cast<size_t>(std::max(p.dimension, 1)), p.name, p.values[i], q.values[i]);
        }
    }
    return std::nullopt;
}

bool reruns_for_determinism(RunStatus status) {
    return status != RunStatus::Timeout && status != RunStatus::Rejected && status != RunStatus::Unavailable;
}

}  // namespace crossdiv::verification
