#include "crossdiv/verification/comparisons/multiresolution_checks.h"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/mesh/vertex_normals.h"

namespace crossdiv::verification {
namespace {

double largest_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double d = 0;
    for (size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
    return d;
}

}  // namespace

std::vector<Vec3> detailed_surface(const LoopMultiresolution& m, const std::vector<Vec3>& base_positions, double amplitude,
                                   double waves) {
    TriMesh smooth;
    smooth.positions = m.subdivide(base_positions);
    smooth.triangles = m.triangles(m.num_levels());
    const std::vector<Vec3> normals = vertex_normals(smooth, NormalWeighting::Angle);
    const double diagonal = bounding_box_diagonal(smooth.positions), k = waves / diagonal;
    std::vector<Vec3> out = smooth.positions;
    for (size_t v = 0; v < out.size(); ++v) {
        const Vec3& p = smooth.positions[v];
        out[v] += amplitude * diagonal * std::sin(k * p.x()) * std::sin(k * p.y()) * std::sin(k * p.z()) * normals[v];
    }
    return out;
}

MultiresolutionMeasures measure_multiresolution(const LoopMultiresolution& m, const std::vector<Vec3>& finest, int vertex,
                                                const Vec3& edit) {
    if (vertex < 0 || vertex >= m.num_vertices(0))
        throw InputError("multiresolution: base vertex " + std::to_string(vertex) + " of " + std::to_string(m.num_vertices(0)));
    MultiresolutionMeasures out;
    out.diagonal = bounding_box_diagonal(finest);
    const MultiresolutionDecomposition d = m.decompose(finest);
    const std::vector<Vec3> before = m.recompose(d);  // the round trip, and the edit's reference
    out.round_trip = largest_difference(before, finest) / out.diagonal;
    for (const std::vector<Vec3>& level : d.details) {
        double sum = 0;
        for (const Vec3& x : level) sum += x.squaredNorm();
        out.detail_rms.push_back(std::sqrt(sum / static_cast<double>(level.size())) / out.diagonal);
    }

    // A rotation about a skew axis and a shift of the diagonal's size.
    const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
    const Vec3 shift = out.diagonal * Vec3(1.5, -0.5, 1.0);
    std::vector<Vec3> moved = finest;
    for (Vec3& x : moved) x = r * x + shift;
    const MultiresolutionDecomposition dm = m.decompose(moved);
    out.rigid_motion = largest_difference(m.recompose(dm), moved);
    for (size_t l = 0; l < d.details.size(); ++l) out.rigid_motion = std::max(out.rigid_motion, largest_difference(d.details[l], dm.details[l]));
    out.rigid_motion /= out.diagonal;

    const std::vector<char> reach = m.edit_reach({vertex}, true), support = m.edit_reach({vertex}, false);
    MultiresolutionDecomposition e = d;
    e.base[vertex] += edit;
    out.edited = m.recompose(e);
    // With zero details a subdivision surface: the frames multiply zeros.
    MultiresolutionDecomposition z = d;
    for (std::vector<Vec3>& level : z.details) std::fill(level.begin(), level.end(), Vec3::Zero());
    const std::vector<Vec3> smooth_before = m.recompose(z);
    z.base[vertex] += edit;
    const std::vector<Vec3> smooth_after = m.recompose(z);
    const bool moves = edit != Vec3::Zero();  // no edit moves nothing, support or not
    for (size_t v = 0; v < finest.size(); ++v) {
        const bool changed = out.edited[v] != before[v], smooth_changed = smooth_after[v] != smooth_before[v];
        out.moved += changed;
        out.reach += reach[v];
        out.support += support[v];
        out.outside_reach += changed && !reach[v];
        out.smooth_moved += smooth_changed;
        out.smooth_mismatch += smooth_changed != (moves && support[v]);
    }
    return out;
}

}  // namespace crossdiv::verification
