// The half-edge work over the whole catalog: Loop by split and flip against index-based Loop
// on every bundled, edge-case, course and meshedit mesh; normals against OpenMesh and CGAL;
// the meshedit flip and split results; the meshedit COLLADA files loaded and subdivided.
#include <gtest/gtest.h>

#include <filesystem>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/error.h"
#include "crossdiv/mesh/halfedge_mesh.h"
#include "crossdiv/mesh/halfedge_validity.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/loop_split_flip.h"
#include "crossdiv/verification/comparisons/edit_differential.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/comparisons/normals_comparison.h"
#include "crossdiv/datasets/data_paths.h"

namespace crossdiv::verification {
namespace {

const bool kMeshedit = std::filesystem::is_directory(datasets::shared_data_dir() / "meshedit/dae");

// Every input, both weight families, both boundary rules: the same vertices bit for bit and
// the same faces, or both refuse. The only input the split-and-flip method refuses on its own
// is a doubled triangle (two faces on the same three vertices), which it names.
TEST(HalfedgeCatalog, LoopBySplitAndFlipEqualsIndexBasedLoopEverywhere) {
    int compared = 0, both_refused = 0, doubled = 0;
    for (const std::string& spec : expand_inputs({"bundled:all", "edgecases:all", "course:all", "meshedit:all"})) {
        TriMesh mesh;
        try {
            mesh = to_tri_mesh(load_input(spec), "Loop");
        } catch (const InputError&) {
            continue;  // quads, malformed: Loop refuses them before either method runs
        }
        for (LoopWeights w : {LoopWeights::Loop, LoopWeights::Warren})
            for (LoopBoundary b : {LoopBoundary::EdgeOnly, LoopBoundary::EdgeAndCorner}) {
                const LoopOptions opt{w, b};
                TriMesh index, local;
                std::string index_error, local_error;
                try {
                    index = loop_subdivide(mesh, opt, 1);
                } catch (const InputError& e) {
                    index_error = e.what();
                }
                try {
                    local = loop_by_split_and_flip(mesh, opt);
                } catch (const InputError& e) {
                    local_error = e.what();
                }
                if (!index_error.empty()) {
                    EXPECT_EQ(local_error, index_error) << spec;  // the same check, the same message
                    ++both_refused;
                    continue;
                }
                if (local_error.find("two faces on the same three vertices") != std::string::npos) {
                    ++doubled;
                    continue;
                }
                ASSERT_EQ(local_error, "") << spec;
                EXPECT_EQ(local.positions, index.positions) << spec;
                EXPECT_EQ(canonical_faces(local.triangles), canonical_faces(index.triangles)) << spec;
                ++compared;
            }
    }
    EXPECT_GE(compared, 4 * 40);  // bundled and valid edge cases, every variant
    EXPECT_GT(both_refused, 0);   // the invalid edge cases were offered to both
    std::cout << compared << " comparisons equal, " << both_refused << " refused by both, " << doubled
              << " doubled-triangle refusals\n";
    if (kMeshedit) {
        EXPECT_GE(compared, 4 * 40 + 4 * 8);
    }
}

TEST(HalfedgeCatalog, OpenMeshNormalsAreAreaAndUniformCgalIsClassified) {
    for (const std::string& spec : expand_inputs({"bundled:all"})) {
        const TriMesh mesh = to_tri_mesh(load_input(spec));
        const NormalsComparison c = compare_normals(mesh, NormalWeighting::Area, {"openmesh", "cgal"});
        ASSERT_EQ(c.references.size(), 3u);
        // On symmetric meshes several weightings coincide; the one each method is must match.
        EXPECT_LE(c.references[0].max_angle[0], tolerances::kNormalMatchRad) << spec << ": " << c.references[0].classification;
        EXPECT_LE(c.references[1].max_angle[2], tolerances::kNormalMatchRad) << spec << ": " << c.references[1].classification;
        EXPECT_EQ(c.references[2].error, "") << spec;
    }
    // Where a vertex's faces are not symmetric the weightings part; CGAL follows none of them.
    const NormalsComparison patch = compare_normals(to_tri_mesh(load_input("bundled:open-patch")), NormalWeighting::Area, {"cgal"});
    const ReferenceNormals& cgal = patch.references[0];
    EXPECT_EQ(cgal.matches, "");
    EXPECT_GT(cgal.max_angle[0], 1e-2);
    // Measured: every one of its 25 normals is the most visible one, and the two one-face
    // corners (where every rule gives the face normal) are also the sine-weighted sum.
    EXPECT_EQ(cgal.most_visible, 25);
    EXPECT_EQ(cgal.sine_weighted, 2);
    EXPECT_EQ(cgal.unexplained, 0);
    // On the icosahedron every weighting is the same direction, and CGAL agrees with all.
    const NormalsComparison ico = compare_normals(to_tri_mesh(load_input("bundled:icosahedron")), NormalWeighting::Area, {"cgal"});
    EXPECT_LT(ico.references[0].max_angle[0], tolerances::kNormalMatchRad);
}

// The meshedit reference results: the input, and the mesh after one flip and after one split.
// The edge they operated on is not recorded, so every edge is tried: our result must equal
// theirs (same faces under the correspondence of identical positions; the split's new vertex
// at their midpoint within float precision) for at least one edge.
TEST(HalfedgeCatalog, MeshEditFlipAndSplitResultsAreReproduced) {
    if (!kMeshedit) {
        EXPECT_TRUE(expand_inputs({"meshedit:all"}).empty());
        return;
    }
    for (const std::string name : {"cube", "icosahedron", "torus"}) {
        const std::string dir = (datasets::shared_data_dir() / "meshedit/dae" / name).string() + "/";
        const TriMesh input = to_tri_mesh(load_input(dir + "input.dae"));
        for (const std::string op : {"edgeFlip", "edgeSplit"}) {
            const TriMesh theirs = to_tri_mesh(load_input(dir + op + ".dae"));
            // The DAE stores 6 significant digits; 1e-5 of the model size separates vertices.
            const double tol = 1e-5 * bounding_box_diagonal(input.positions);
            int reproduced = 0;
            const HalfedgeMesh base = HalfedgeMesh::from_triangles(input);
            for (int e = 0; e < base.num_edges(); ++e) {
                HalfedgeMesh he = base;
                std::vector<Vec3> pos = input.positions;
                if (op == "edgeFlip" && he.flip(EdgeId(e)) != FlipRefusal::None) continue;
                if (op == "edgeSplit") split_at_midpoint(he, pos, EdgeId(e));
                if (static_cast<int>(pos.size()) != theirs.num_vertices()) continue;
                // Their vertex i is our vertex map[i]: the one at the same position.
                std::vector<int> map(pos.size(), -1);
                bool all = true;
                for (size_t i = 0; i < pos.size() && all; ++i) {
                    for (size_t j = 0; j < pos.size(); ++j)
                        if ((theirs.positions[i] - pos[j]).norm() <= tol) map[i] = static_cast<int>(j);
                    all = map[i] >= 0;
                }
                if (!all) continue;
                std::vector<Triangle> mapped = theirs.triangles;
                for (Triangle& t : mapped)
                    for (int& v : t) v = map[static_cast<size_t>(v)];
                if (canonical_faces(mapped) == canonical_faces(he.triangles())) ++reproduced;
            }
            EXPECT_GE(reproduced, 1) << name << "/" << op;
            std::cout << name << "/" << op << ": reproduced by " << reproduced << " edge(s)\n";
        }
    }
}

// Every meshedit file loads (all are triangle meshes), is a valid half-edge mesh, and Loop runs
// on the four the issue names; beetle has a boundary.
TEST(HalfedgeCatalog, MeshEditColladaFilesLoadAndSubdivide) {
    const auto files = expand_inputs({"meshedit:all"});
    if (!kMeshedit) {
        EXPECT_TRUE(files.empty());
        return;
    }
    EXPECT_EQ(files.size(), 8u);
    for (const std::string& f : files) {
        const TriMesh mesh = to_tri_mesh(load_input(f));
        const HalfedgeMesh he = HalfedgeMesh::from_triangles(mesh);
        EXPECT_TRUE(check_halfedge_mesh(he).empty()) << f;
        const std::string stem = std::filesystem::path(f).stem().string();
        if (stem == "beetle") {
            EXPECT_GT(he.num_boundary_loops(), 0);
        }
        if (stem == "teapot" || stem == "cube" || stem == "beetle" || stem == "cow") {
            const TriMesh fine = loop_subdivide(mesh, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1);
            EXPECT_EQ(fine.num_faces(), 4 * mesh.num_faces()) << f;
        }
    }
}

}  // namespace
}  // namespace crossdiv::verification
