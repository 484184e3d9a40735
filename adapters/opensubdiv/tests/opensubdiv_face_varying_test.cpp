// Core's face-varying refinement against Far's (PrimvarRefiner::InterpolateFaceVarying), every
// rule, on every catalog mesh in every UV layout, and the identity OpenSubdiv documents.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "crossdiv/adapters/opensubdiv.h"
#include "crossdiv/datasets/bundled.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/datasets/uv_layouts.h"
#include "crossdiv/error.h"
#include "crossdiv/subdiv/bilinear.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/face_varying_limit.h"
#include "crossdiv/subdiv/face_varying_refinement.h"
#include "crossdiv/subdiv/loop.h"

namespace crossdiv::adapters {
namespace {

/// Core and Far agree on a refined value to this fraction of the UV box: both sum a handful of
/// terms per level in double; 1e-12 leaves three orders of magnitude above the rounding of two
/// levels and is what the face-varying issue asks of `crossdiv subdivide`.
constexpr double kUvAgreement = 1e-12;
/// Vertices of the two refinements are matched by position: they are the same points up to
/// rounding, and no two vertices of a catalog mesh at two levels are closer than this.
constexpr double kSamePoint = 1e-9;

double uv_box(const FaceVaryingChannel& ch) {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (int i = 0; i < ch.num_values(); ++i)
        for (int k = 0; k < 2; ++k) {
            lo[k] = std::min(lo[k], ch.value(i)[k]);
            hi[k] = std::max(hi[k], ch.value(i)[k]);
        }
    return std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
}

/// The largest difference of the per-corner values, faces matched by their vertex sets and
/// corners by their vertex; a face or vertex without a partner fails the test.
double worst_corner_difference(const PolyMesh& ours, const PolyMesh& far, const std::string& what) {
    const double diag = bounding_box_diagonal(ours.positions);
    std::vector<int> partner(static_cast<size_t>(ours.num_vertices()), -1);
    for (int v = 0; v < ours.num_vertices(); ++v)
        for (int w = 0; w < far.num_vertices(); ++w)
            if ((ours.positions[v] - far.positions[w]).norm() <= kSamePoint * diag) {
                partner[static_cast<size_t>(v)] = w;
                break;
            }
    std::map<std::vector<int>, int> far_face;
    for (int f = 0; f < far.num_faces(); ++f) {
        std::vector<int> key(far.face(f), far.face(f) + far.face_size(f));
        std::sort(key.begin(), key.end());
        far_face[key] = f;
    }
    const FaceVaryingChannel &a = ours.face_varying.at(0), &b = far.face_varying.at(0);
    double worst = 0;
    for (int f = 0; f < ours.num_faces(); ++f) {
        std::vector<int> key;
        for (int k = 0; k < ours.face_size(f); ++k) key.push_back(partner[static_cast<size_t>(ours.face(f)[k])]);
        std::vector<int> sorted = key;
        std::sort(sorted.begin(), sorted.end());
        const auto it = far_face.find(sorted);
        if (it == far_face.end()) {
            ADD_FAILURE() << what << ": core's face " << f << " has no partner in Far's level";
            return 1e300;
        }
        const int g = it->second;
        for (int k = 0; k < ours.face_size(f); ++k) {
            const int j = static_cast<int>(std::find(far.face(g), far.face(g) + far.face_size(g), key[k]) - far.face(g));
            const double* x = a.value(a.corner_values[static_cast<size_t>(ours.face_start[f] + k)]);
            const double* y = b.value(b.corner_values[static_cast<size_t>(far.face_start[g] + j)]);
            for (int d = 0; d < a.dimension; ++d) worst = std::max(worst, std::abs(x[d] - y[d]));
        }
    }
    return worst;
}

struct Scheme {
    const char* name;
    bool triangles_only;
    FaceVaryingScheme fvar;
};

/// Core's refinement of `mesh` under `scheme` and the rule, and Far's.
std::pair<PolyMesh, PolyMesh> both(const PolyMesh& mesh, FaceVaryingScheme scheme, bool edge_and_corner,
                                   FaceVaryingRule rule, int levels) {
    const FaceVaryingOptions fo{rule, edge_and_corner};
    switch (scheme) {
        case FaceVaryingScheme::CatmullClark: {
            const CatmullClarkOptions o{edge_and_corner ? CatmullClarkBoundary::EdgeAndCorner : CatmullClarkBoundary::EdgeOnly};
            return {subdivide_with_face_varying(mesh, scheme, fo, levels,
                                                [&](const PolyMesh& m, const PolyConnectivity& c) { return catmull_clark_step(m, c, o); }),
                    opensubdiv::catmull_clark_face_varying(mesh, o, rule, levels).back()};
        }
        case FaceVaryingScheme::Loop: {
            const LoopOptions o{LoopWeights::Loop, edge_and_corner ? LoopBoundary::EdgeAndCorner : LoopBoundary::EdgeOnly};
            return {subdivide_with_face_varying(mesh, scheme, fo, levels,
                                                [&](const PolyMesh& m, const PolyConnectivity& c) { return loop_step(m, c, o); }),
                    opensubdiv::loop_face_varying(mesh, o, rule, levels).back()};
        }
        case FaceVaryingScheme::Bilinear:
            return {subdivide_with_face_varying(mesh, scheme, fo, levels,
                                                [&](const PolyMesh& m, const PolyConnectivity&) { return bilinear_step(m); }),
                    opensubdiv::bilinear_face_varying(mesh, rule, levels).back()};
    }
    throw std::logic_error("scheme");
}

// Under the sanitizers, which slow each refinement about twentyfold (these two sweeps took 536 s
// and 342 s of CI's sanitizer run), each mesh is checked under every eighth combination of
// scheme, layout, boundary rule and face-varying rule, a different eighth for each mesh, so that
// every combination still runs on several meshes and every code path under the sanitizers; the
// release build's run of the same test, which CI runs too, checks every combination on every mesh.
#ifdef CROSSDIV_SANITIZED
constexpr int kCombinationStride = 8;
#else
constexpr int kCombinationStride = 1;
#endif

/// Whether combination `k` of the mesh numbered `mesh` is checked in this build.
bool checked_here(int mesh, int k) { return (mesh + k) % kCombinationStride == 0; }

TEST(OpenSubdivFaceVarying, CoreAgreesWithFarOnEveryRuleLayoutAndCatalogMesh) {
    std::vector<datasets::BundledMesh> meshes = datasets::catalog_meshes();
    for (const datasets::BundledMesh& c : datasets::crease_meshes()) meshes.push_back(c);
    const Scheme schemes[] = {{"catmull-clark", false, FaceVaryingScheme::CatmullClark},
                              {"loop", true, FaceVaryingScheme::Loop},
                              {"bilinear", false, FaceVaryingScheme::Bilinear}};
    int compared = 0;
    std::vector<std::string> refused;
    for (size_t m = 0; m < meshes.size(); ++m) {
        const datasets::BundledMesh& bm = meshes[m];
        int combination = 0;
        for (const Scheme& s : schemes) {
            if (s.triangles_only && !bm.mesh.all_triangles()) continue;
            if (s.fvar == FaceVaryingScheme::Bilinear && !bm.mesh.creases.empty()) continue;  // bilinear has no tags here
            for (datasets::UvLayout layout : datasets::kUvLayouts) {
                const PolyMesh mesh = datasets::with_uv_layout(bm.mesh, layout);
                for (bool corners : {false, true})
                    for (FaceVaryingRule rule : kFaceVaryingRules) {
                        if (!checked_here(static_cast<int>(m), combination++)) continue;
                        const std::string what = bm.name + " " + s.name + " " + std::string(to_string(layout)) + " " +
                                                 std::string(to_string(rule)) + (corners ? " edge-and-corner" : " edge-only");
                        std::pair<PolyMesh, PolyMesh> r;
                        try {
                            r = both(mesh, s.fvar, corners, rule, 2);
                        } catch (const InputError& e) {
                            refused.push_back(what + ": " + e.what());
                            continue;
                        }
                        const double worst = worst_corner_difference(r.first, r.second, what);
                        ++compared;
                        EXPECT_LE(worst, kUvAgreement * uv_box(r.second.face_varying[0])) << what;
                    }
            }
        }
    }
    // Core refines every one of them (semi-sharp creases next to seams included).
    EXPECT_EQ(refused, std::vector<std::string>{});
    EXPECT_GT(compared, 1000 / kCombinationStride);
    std::printf("compared %d refinements\n", compared);
}

/// Core's limit values of `levels` levels of `mesh` (face_varying_limit on its last level), and
/// Far's (LimitFaceVarying).
std::pair<PolyMesh, PolyMesh> both_limits(const PolyMesh& mesh, FaceVaryingScheme scheme, bool edge_and_corner,
                                          FaceVaryingRule rule, int levels) {
    const FaceVaryingOptions fo{rule, edge_and_corner};
    std::vector<PolyMesh> ours;
    std::vector<FaceVaryingSemiSharp> semi;
    PolyMesh far;
    if (scheme == FaceVaryingScheme::CatmullClark) {
        const CatmullClarkOptions o{edge_and_corner ? CatmullClarkBoundary::EdgeAndCorner : CatmullClarkBoundary::EdgeOnly};
        ours = subdivide_levels_with_face_varying(
            mesh, scheme, fo, levels, [&](const PolyMesh& m, const PolyConnectivity& c) { return catmull_clark_step(m, c, o); },
            &semi);
        far = opensubdiv::catmull_clark_face_varying_limit(mesh, o, rule, levels);
    } else {
        const LoopOptions o{LoopWeights::Loop, edge_and_corner ? LoopBoundary::EdgeAndCorner : LoopBoundary::EdgeOnly};
        ours = subdivide_levels_with_face_varying(
            mesh, scheme, fo, levels, [&](const PolyMesh& m, const PolyConnectivity& c) { return loop_step(m, c, o); }, &semi);
        far = opensubdiv::loop_face_varying_limit(mesh, o, rule, levels);
    }
    PolyMesh limit = ours.back();
    limit.face_varying[0] = face_varying_limit(limit, limit.face_varying[0], scheme, fo, semi.empty() ? nullptr : &semi[0]);
    return {limit, far};
}

TEST(OpenSubdivFaceVarying, CoreLimitValuesAgreeWithFarsOnEveryRuleLayoutAndCatalogMesh) {
    std::vector<datasets::BundledMesh> meshes = datasets::catalog_meshes();
    for (const datasets::BundledMesh& c : datasets::crease_meshes()) meshes.push_back(c);
    for (const datasets::UvEdgeCase& e : datasets::uv_edge_cases()) meshes.push_back({e.name, e.description, e.mesh});
    int compared = 0;
    double worst_rel = 0;
    std::vector<std::string> refused;
    for (size_t m = 0; m < meshes.size(); ++m) {
        const datasets::BundledMesh& bm = meshes[m];
        int combination = 0;
        for (FaceVaryingScheme scheme : {FaceVaryingScheme::CatmullClark, FaceVaryingScheme::Loop}) {
            if (scheme == FaceVaryingScheme::Loop && !bm.mesh.all_triangles()) continue;
            std::vector<PolyMesh> inputs;
            if (bm.mesh.face_varying.empty())
                for (datasets::UvLayout layout : datasets::kUvLayouts) inputs.push_back(datasets::with_uv_layout(bm.mesh, layout));
            else
                inputs.push_back(bm.mesh);
            for (const PolyMesh& mesh : inputs)
                for (int levels : {1, 2})
                    for (bool corners : {false, true})
                        for (FaceVaryingRule rule : kFaceVaryingRules) {
                            if (!checked_here(static_cast<int>(m), combination++)) continue;
                            const std::string what = bm.name + (scheme == FaceVaryingScheme::Loop ? " loop " : " catmull-clark ") +
                                                     std::to_string(levels) + " " + std::string(to_string(rule)) +
                                                     (corners ? " edge-and-corner" : " edge-only");
                            // The UV bowtie under none: Far's refined values already depend on
                            // the order of the faces (FarSplitsABowtieValueByFaceOrder), and
                            // its limits with them; that difference is measured there.
                            if (bm.name.starts_with("uv-bowtie") && rule == FaceVaryingRule::None) continue;
                            std::pair<PolyMesh, PolyMesh> r;
                            try {
                                r = both_limits(mesh, scheme, corners, rule, levels);
                            } catch (const InputError& e) {
                                refused.push_back(what + ": " + e.what());
                                continue;
                            }
                            ++compared;
                            // Far weighs a crease value's limit with float constants (1.0f/6.0f,
                            // 2.0f/3.0f in limitFVar): off by up to 2^-25 of the largest |value|
                            // summed; twice that, or kUvAgreement of the box.
                            double largest = 0;
                            for (double x : r.first.face_varying[0].values) largest = std::max(largest, std::abs(x));
                            const double worst = worst_corner_difference(r.first, r.second, what);
                            EXPECT_LE(worst, std::max(kUvAgreement * uv_box(r.second.face_varying[0]), 0x1p-24 * largest))
                                << what;
                            worst_rel = std::max(worst_rel, worst / std::max(largest, 1e-300));
                        }
        }
    }
    EXPECT_EQ(refused, std::vector<std::string>{});
    EXPECT_GT(compared, 1000 / kCombinationStride);
    std::printf("compared %d limits; largest difference %.3g of the largest |value|\n", compared, worst_rel);
}

TEST(OpenSubdivFaceVarying, TheComparisonTellsEveryRuleApart) {
    // Three UV regions on a quad grid: seams from the boundary to a junction inside, UV
    // corners on the boundary. Far's six rules give six different results there (by 0.3% to
    // 2% of the UV box, measured), and core under one rule matches Far under that rule only,
    // so agreement above is earned rule by rule.
    const PolyMesh mesh = datasets::with_uv_layout(datasets::bundled_mesh("quad-grid"), datasets::UvLayout::ThreeRegions);
    for (FaceVaryingRule a : kFaceVaryingRules) {
        const PolyMesh ours = both(mesh, FaceVaryingScheme::CatmullClark, false, a, 2).first;
        for (FaceVaryingRule b : kFaceVaryingRules) {
            const PolyMesh far = opensubdiv::catmull_clark_face_varying(mesh, {CatmullClarkBoundary::EdgeOnly}, b, 2).back();
            const double d = worst_corner_difference(ours, far, "grid") / uv_box(far.face_varying[0]);
            if (a == b) EXPECT_LE(d, kUvAgreement) << to_string(a);
            else EXPECT_GT(d, 1e-3) << to_string(a) << " against " << to_string(b);
        }
    }
}

TEST(OpenSubdivFaceVarying, WithoutSeamsOrBoundaryEveryRuleButAllIsTheVertexRule) {
    // A closed cube with one value per vertex: no value differs from the vertex topology, so
    // every rule but `all` refines the values with the vertex masks; `all` is bilinear.
    const PolyMesh mesh = datasets::with_uv_layout(datasets::bundled_mesh("quad-cube"), datasets::UvLayout::Welded);
    const PolyMesh none = opensubdiv::catmull_clark_face_varying(mesh, {CatmullClarkBoundary::EdgeOnly}, FaceVaryingRule::None, 2).back();
    for (FaceVaryingRule r : kFaceVaryingRules) {
        const PolyMesh ours = both(mesh, FaceVaryingScheme::CatmullClark, false, r, 2).first;
        const double d = worst_corner_difference(ours, none, "cube") / uv_box(none.face_varying[0]);
        if (r == FaceVaryingRule::All) EXPECT_GT(d, 0.1);
        else EXPECT_LE(d, kUvAgreement) << to_string(r);
    }
}

/// `m` with face `first` moved to the front (its channel corners with it).
PolyMesh with_face_first(const PolyMesh& m, int first) {
    PolyMesh out = m;
    out.face_vertices.clear();
    out.face_start = {0};
    out.face_varying[0].corner_values.clear();
    std::vector<int> order{first};
    for (int f = 0; f < m.num_faces(); ++f)
        if (f != first) order.push_back(f);
    for (int f : order) {
        for (int c = m.face_start[f]; c < m.face_start[f + 1]; ++c) {
            out.face_vertices.push_back(m.face_vertices[c]);
            out.face_varying[0].corner_values.push_back(m.face_varying[0].corner_values[c]);
        }
        out.face_start.push_back(static_cast<int>(out.face_vertices.size()));
    }
    return out;
}

/// The values vertex `v` has in the faces around it, sorted.
std::vector<std::array<double, 2>> values_at(const PolyMesh& m, int v) {
    std::vector<std::array<double, 2>> out;
    for (int f = 0; f < m.num_faces(); ++f)
        for (int k = 0; k < m.face_size(f); ++k)
            if (m.face(f)[k] == v) {
                const double* x = m.face_varying[0].value(m.face_varying[0].corner_values[static_cast<size_t>(m.face_start[f] + k)]);
                out.push_back({x[0], x[1]});
            }
    std::sort(out.begin(), out.end());
    return out;
}

TEST(OpenSubdivFaceVarying, FarSplitsABowtieValueByFaceOrder) {
    // uv-bowtie: at vertex 12 = (2, 2) the faces around alternate between two UV regions
    // (1, 0, 1, 0), so each region's value has two disjoint one-face spans. OpenSubdiv's
    // FVarLevel::completeTopologyFromFaceValues sharpens a disjoint value (a corner, kept), but
    // its search for the vertex's distinct values takes a value that recurs while two are
    // known for a new one: whichever region's value comes second in the vertex's face order is
    // split into two one-face values, which `none` smooths each with the crease mask in its
    // face. So Far's result depends on the order of the faces. Core keeps both values (corners)
    // in any order. Hand values (uv_of_position, region r offset by (r/2, 3r/10)):
    //   region 0 at (2, 2): (3.458, 2.108); region 1: (3.958, 2.408);
    //   crease in face (2,1): 3/4 (3.458, 2.108) + 1/8 (uv(3,2) + uv(2,1)) = (3.448375, 2.028625);
    //   crease in face (1,2): (3.565625, 2.22575); region 1 in face (1,1): (3.697, 2.2815);
    //   region 1 in face (2,2): (4.317, 2.572875).
    const PolyMesh mesh = datasets::edge_case("uv-bowtie").mesh;
    const PolyMesh sixth_first = with_face_first(mesh, 6);  // face (2, 1), region 0
    using V = std::vector<std::array<double, 2>>;
    auto near = [](const V& a, const V& b) {
        if (a.size() != b.size()) return false;
        for (size_t i = 0; i < a.size(); ++i)
            if (std::abs(a[i][0] - b[i][0]) > 1e-12 || std::abs(a[i][1] - b[i][1]) > 1e-12) return false;
        return true;
    };
    const V region0_split{{3.448375, 2.028625}, {3.565625, 2.22575}, {3.958, 2.408}, {3.958, 2.408}};
    const V region1_split{{3.458, 2.108}, {3.458, 2.108}, {3.697, 2.2815}, {4.317, 2.572875}};
    const V both_kept{{3.458, 2.108}, {3.458, 2.108}, {3.958, 2.408}, {3.958, 2.408}};
    const CatmullClarkOptions o{CatmullClarkBoundary::EdgeOnly};
    EXPECT_TRUE(near(values_at(opensubdiv::catmull_clark_face_varying(mesh, o, FaceVaryingRule::None, 1).back(), 12), region0_split));
    EXPECT_TRUE(near(values_at(opensubdiv::catmull_clark_face_varying(sixth_first, o, FaceVaryingRule::None, 1).back(), 12),
                     region1_split));
    for (const PolyMesh* m : {&mesh, &sixth_first})
        EXPECT_TRUE(near(values_at(both(*m, FaceVaryingScheme::CatmullClark, false, FaceVaryingRule::None, 1).first, 12), both_kept));
}

}  // namespace
}  // namespace crossdiv::adapters
