// The valence rows of `crossdiv bench`: the shapes are what they claim, and each row measures
// the work it names (sizes by hand). Times are reported, never asserted.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "crossdiv/verification/bench/valence_bench.h"
#include "crossdiv/verification/harness/mesh_topology.h"

namespace crossdiv::verification {
namespace {

using datasets::ValenceShape;

int largest_valence(const PolyMesh& m) {
    int n = 0;
    for (int v : mesh_topology(m).valence) n = std::max(n, v);
    return n;
}

TEST(ValenceBench, TheShapesHaveTheValenceAndTheRegularMeshesTheSize) {
    const int k = 40;
    EXPECT_EQ(largest_valence(datasets::valence_shape(ValenceShape::Bicone, k)), k);
    EXPECT_EQ(largest_valence(datasets::valence_shape(ValenceShape::DiscFan, k)), k);
    const PolyMesh polygon = datasets::valence_shape(ValenceShape::Polygon, k);
    ASSERT_EQ(polygon.num_faces(), 1);
    EXPECT_EQ(polygon.face_size(0), k);
    for (const ValenceShape s : datasets::kValenceShapes) {
        const PolyMesh shape = datasets::valence_shape(s, 1000), regular = datasets::regular_counterpart(s, 1000);
        EXPECT_LE(largest_valence(regular), 6) << datasets::to_string(s);
        // About as many corners: within the rounding of an n x n grid to k.
        const double ratio = static_cast<double>(regular.face_vertices.size()) / shape.face_vertices.size();
        EXPECT_NEAR(ratio, 1.0, 0.1) << datasets::to_string(s);
    }
}

TEST(ValenceBench, EachRowMeasuresTheWorkItNames) {
    const int k = 40;
    std::map<std::pair<std::string, std::string>, long long> size;
    for (const ValenceRow& r : run_valence_bench({k}, 1)) {
        EXPECT_EQ(r.valence, k);
        EXPECT_GT(r.ms, 0);
        EXPECT_GT(r.regular_ms, 0);
        EXPECT_TRUE(std::isfinite(r.ratio()));
        size[{std::string(datasets::to_string(r.shape)), r.command}] = r.size;
    }
    // Every scheme on the triangle shapes; Catmull-Clark, Doo-Sabin and bilinear on the polygon: 9 + 9 + 4.
    EXPECT_EQ(size.size(), 22u);
    // check: the input's corners.
    EXPECT_EQ((size[{"bicone", "check"}]), 6 * k);
    // Loop on the bicone (k + 2 vertices, 3k edges, 2k faces): (4k + 2) vertices + 8k faces.
    EXPECT_EQ((size[{"bicone", "loop"}]), 12 * k + 2);
    // Midpoint has Loop's topology.
    EXPECT_EQ((size[{"bicone", "midpoint"}]), 12 * k + 2);
    // sqrt3 on the closed bicone: a point per face, three faces per old face.
    EXPECT_EQ((size[{"bicone", "sqrt3"}]), (k + 2 + 2 * k) + 6 * k);
    // Catmull-Clark on the polygon: 1 face point, k edge points, k vertex points; k quads.
    EXPECT_EQ((size[{"polygon", "catmull-clark"}]), 3 * k + 1);
    // Bilinear has Catmull-Clark's topology.
    EXPECT_EQ((size[{"polygon", "bilinear"}]), 3 * k + 1);
    // Doo-Sabin on the polygon: k corner points and two Chaikin points per boundary edge;
    // the F-face, k E-faces and k V-faces.
    EXPECT_EQ((size[{"polygon", "doo-sabin"}]), 5 * k + 1);
}

}  // namespace
}  // namespace crossdiv::verification
