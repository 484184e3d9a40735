// Core as an implementation: every scheme (bilinear and midpoint too) under every named rule, with crease tags for Loop
// and Catmull-Clark, limit positions for both, discrete curvature.
#include "crossdiv/mesh/discrete_curvature.h"
#include "crossdiv/subdiv/bilinear.h"
#include "crossdiv/subdiv/butterfly.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/catmull_clark_streaming.h"
#include "crossdiv/subdiv/doo_sabin.h"
#include "crossdiv/subdiv/face_varying_limit.h"
#include "crossdiv/subdiv/face_varying_refinement.h"
#include "crossdiv/subdiv/limit.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/loop_streaming.h"
#include "crossdiv/subdiv/midpoint.h"
#include "crossdiv/subdiv/nonmanifold.h"
#include "crossdiv/subdiv/sqrt3.h"
#include "library_implementations.h"

namespace crossdiv::verification::detail {
namespace {

/// Every rule of every scheme, as core declares them.
Capabilities core_capabilities() {
    Capabilities c;
    std::vector<SchemeRule> loop;
    for (LoopWeights w : kAllLoopWeights)
        for (LoopBoundary b : {LoopBoundary::EdgeOnly, LoopBoundary::EdgeAndCorner}) loop.push_back(loop_rule(w, b));
    // Catmull-Clark: every boundary rule, with and without OpenSubdiv's smooth triangles,
    // then the literature's other vertex rules (for naming a subject's) under each boundary rule.
    std::vector<SchemeRule> catmull_clark;
    for (bool smooth_triangles : {false, true})
        for (CatmullClarkBoundary b : kAllCatmullClarkBoundaries) catmull_clark.push_back(catmull_clark_rule(b, smooth_triangles));
    for (CatmullClarkVertexRule v : {CatmullClarkVertexRule::RegularWeights, CatmullClarkVertexRule::EdgePointAverage})
        for (CatmullClarkBoundary b : kAllCatmullClarkBoundaries) catmull_clark.push_back(catmull_clark_rule(b, false, v));
    std::vector<SchemeRule> doo_sabin;
    for (DooSabinWeights w : {DooSabinWeights::DooSabin, DooSabinWeights::CatmullClark})
        for (DooSabinBoundary b : {DooSabinBoundary::ChaikinBoundary, DooSabinBoundary::DropBorderFaces})
            doo_sabin.push_back(doo_sabin_rule(b, w));
    c.schemes = {with_face_varying(supports(Scheme::Loop, loop, true)),
                 with_hierarchical_edits(with_face_varying(supports(Scheme::CatmullClark, catmull_clark, true))),
                 supports(Scheme::DooSabin, doo_sabin),
                 supports(Scheme::Sqrt3, {sqrt3_rule(Sqrt3Parity::CountFromInput), sqrt3_rule(Sqrt3Parity::RestartEachLevel)}),
                 supports(Scheme::Butterfly, {butterfly_rule(ButterflyWings::Reflected), butterfly_rule(ButterflyWings::OppositeVertex)}),
                 supports(Scheme::ModifiedButterfly,
                          {butterfly_rule(ButterflyWings::Reflected), butterfly_rule(ButterflyWings::OppositeVertex)}),
                 with_face_varying(supports(Scheme::Bilinear, {SchemeRule{}})),
                 supports(Scheme::Midpoint, {SchemeRule{}})};
    c.limit_positions = true;
    c.curvatures = true;
    return c;
}

/// `levels` levels of a polygon scheme in one call (the sqrt3 parity counts from this call's input).
PolyMesh subdivide(const PolyMesh& mesh, const RefineRequest& r, int levels) {
    switch (r.scheme) {
        case Scheme::Loop: return loop_subdivide(mesh, r.rule.loop, levels);
        case Scheme::CatmullClark: return catmull_clark_subdivide_streaming(mesh, r.rule.catmull_clark, levels);
        case Scheme::DooSabin: return doo_sabin_subdivide(mesh, r.rule.doo_sabin, levels);
        case Scheme::Sqrt3: return sqrt3_subdivide(mesh, r.rule.sqrt3, levels);
        case Scheme::Butterfly: return butterfly_subdivide(mesh, ButterflyVariant::Classic, levels, r.rule.butterfly_wings);
        case Scheme::ModifiedButterfly:
            return butterfly_subdivide(mesh, ButterflyVariant::Modified, levels, r.rule.butterfly_wings);
        case Scheme::Bilinear: return bilinear_subdivide(mesh, levels);
        case Scheme::Midpoint: return midpoint_subdivide(mesh, levels);
    }
    throw InputError("unknown scheme");
}

/// Levels 0..N with the face-varying channels refined (face_varying_refinement.h), for Loop,
/// Catmull-Clark and bilinear on a manifold; nothing for a mesh that is not one (its
/// positions are then refined without the channels, and the comparison says so), or for a
/// tagged mesh under bilinear (refused there, as without channels).
/// The face-varying scheme of a request's scheme (bilinear for any other).
FaceVaryingScheme face_varying_scheme(Scheme s) {
    return s == Scheme::Loop ? FaceVaryingScheme::Loop : s == Scheme::CatmullClark ? FaceVaryingScheme::CatmullClark
                                                                                   : FaceVaryingScheme::Bilinear;
}

/// The face-varying options of a request: its rule, and what of the geometry's rule decides
/// a value's sharpness (Hbr's crease rules bring Hbr's face-varying rules with them).
FaceVaryingOptions face_varying_options(const RefineRequest& r) {
    const bool corners_sharp = r.scheme == Scheme::Loop ? r.rule.loop.boundary == LoopBoundary::EdgeAndCorner
                                                        : r.rule.catmull_clark.boundary == CatmullClarkBoundary::EdgeAndCorner;
    return {*r.face_varying, corners_sharp && r.scheme != Scheme::Bilinear,
            r.scheme == Scheme::Loop ? r.rule.loop.creasing : r.rule.catmull_clark.creasing,
            r.scheme == Scheme::Loop ? r.rule.loop.crease_rules : r.rule.catmull_clark.crease_rules};
}

std::optional<adapters::LevelTrace> face_varying_levels(const PolyMesh& mesh, const RefineRequest& r,
                                                        std::vector<FaceVaryingSemiSharp>* semi_tags = nullptr) {
    if (r.scheme == Scheme::Bilinear && !mesh.creases.empty()) return std::nullopt;  // refused as without channels
    // Hierarchical edits are applied to the positions alone (catmull_clark_levels); the
    // channels of an edited mesh are not refined.
    if (!mesh.creases.edits.empty()) return std::nullopt;
    const FaceVaryingScheme scheme = face_varying_scheme(r.scheme);
    const FaceVaryingOptions options = face_varying_options(r);
    try {
        return subdivide_levels_with_face_varying(mesh, scheme, options, r.levels,
                                                  [&](const PolyMesh& m, const PolyConnectivity& conn) {
                                                      switch (r.scheme) {
                                                          case Scheme::Loop: return loop_step(m, conn, r.rule.loop);
                                                          case Scheme::CatmullClark: return catmull_clark_step(m, conn, r.rule.catmull_clark);
                                                          default: return bilinear_step(m);
                                                      }
                                                  },
                                                  semi_tags);
    } catch (const NonManifoldInput&) {
        return std::nullopt;
    }
}

/// Levels 0..N, with Loop's provenance when `births` is asked for.
Refinement refinement(const PolyMesh& mesh, const RefineRequest& r, bool births) {
    if (r.face_varying && !mesh.face_varying.empty() &&
        (r.scheme == Scheme::Loop || r.scheme == Scheme::CatmullClark || r.scheme == Scheme::Bilinear))
        if (std::optional<adapters::LevelTrace> levels = face_varying_levels(mesh, r)) return {std::move(*levels), {}};
    Refinement out{{mesh}, {}};
    adapters::LevelTrace& trace = out.levels;
    using Kind = VertexBirth::Kind;
    const bool loop = r.scheme == Scheme::Loop && mesh.creases.empty();
    if (loop) {
        try {
            LoopRefiner refiner(to_tri_mesh(mesh, "Loop subdivision"), r.rule.loop);
            refiner.refine(r.levels);
            for (int l = 1; l <= r.levels; ++l) {
                trace.push_back(to_poly_mesh(refiner.mesh(l)));
                if (!births) continue;
                std::vector<VertexBirth>& level = out.births.emplace_back();
                for (const VertexOrigin& o : refiner.origins(l))
                    level.push_back(o.is_edge_point() ? VertexBirth{Kind::Edge, o.a, o.b} : VertexBirth{Kind::Vertex, o.a, -1});
            }
            return out;
        } catch (const NonManifoldInput&) {
            // Not a manifold: loop_subdivide takes OpenSubdiv's rules level by level below
            // (or refuses, under NonManifoldRule::Refuse).
        }
    }
    // Loop's non-manifold levels and the midpoint scheme's: edge points in the order Far
    // numbers the edges (nonmanifold.h).
    if (loop || r.scheme == Scheme::Midpoint) {
        for (int l = 1; l <= r.levels; ++l) {
            const PolyMesh& coarse = trace.back();
            PolyMesh fine = subdivide(coarse, r, 1);  // refuses first, under NonManifoldRule::Refuse
            if (births) {
                std::vector<VertexBirth>& level = out.births.emplace_back();
                for (int v = 0; v < coarse.num_vertices(); ++v) level.push_back({Kind::Vertex, v, -1});
                for (const auto& [a, b] : nonmanifold_edges(coarse)) level.push_back({Kind::Edge, a, b});
            }
            trace.push_back(std::move(fine));
        }
        return out;
    }
    // Hierarchical edits follow their paths from the input's faces: all levels in one call.
    if (r.scheme == Scheme::CatmullClark && !mesh.creases.edits.empty()) {
        out.levels = catmull_clark_levels(mesh, r.rule.catmull_clark, r.levels);
        return out;
    }
    // sqrt3 counts its boundary generations from the input: each level is its own call
    // from the input. The other schemes' levels are the same one step at a time.
    for (int l = 1; l <= r.levels; ++l)
        trace.push_back(r.scheme == Scheme::Sqrt3 ? subdivide(mesh, r, l) : subdivide(trace.back(), r, 1));
    return out;
}

class Core final : public Implementation {
public:
    Core() : Implementation("core", "crossdiv", ImplementationKind::Core, core_capabilities()) {}

    /// Core refuses bad input with InputError (naming the element), which callers record as
    /// core's refusal; it is never turned into adapters::Rejected.
    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& r) const override {
        return refinement(mesh, r, false).levels;
    }

    /// Loop's levels carry the refiner's provenance (on a mesh that is not a manifold, the
    /// edges in the order the non-manifold steps number their edge points); the other primal
    /// schemes' are read off the faces of each level, whose numbering keeps the old vertices
    /// first (primal_births). Doo-Sabin's and sqrt3's levels have none.
    Refinement refine_with_provenance(const PolyMesh& mesh, const RefineRequest& r) const override {
        Refinement out = refinement(mesh, r, true);
        if (out.births.empty() && traits(r.scheme).primal)
            for (size_t l = 1; l < out.levels.size(); ++l) out.births.push_back(primal_births(out.levels[l - 1], out.levels[l]));
        return out;
    }

    PolyMesh refine_last(const PolyMesh& mesh, const RefineRequest& r) const override {
        if (r.face_varying && !mesh.face_varying.empty()) return refinement(mesh, r, false).levels.back();
        return subdivide(mesh, r, r.levels);
    }


    size_t refine_native(const TriMesh& mesh, const RefineRequest& r) const override {
        if (r.scheme != Scheme::Loop) return Implementation::refine_native(mesh, r);
        // The fastest way core makes the last level: the streaming driver (loop_streaming.h).
        return loop_subdivide_streaming(mesh, r.rule.loop, r.levels).triangles.size();
    }

    size_t refine_polygons_native(const PolyMesh& mesh, const RefineRequest& r) const override {
        if (r.scheme != Scheme::CatmullClark) return Implementation::refine_polygons_native(mesh, r);
        // The streaming driver (catmull_clark_streaming.h).
        return catmull_clark_subdivide_streaming(mesh, r.rule.catmull_clark, r.levels).num_faces();
    }

    adapters::LimitPoints limit_points(const PolyMesh& mesh, const RefineRequest& r) const override {
        if (r.scheme != Scheme::Loop && r.scheme != Scheme::CatmullClark) lacks(std::string(to_string(r.scheme)) + " limit positions");
        adapters::LimitPoints out;
        // With texture coordinates, the level is refined with its channel, whose limit values
        // are taken on it too (face_varying_limit.h).
        const bool uv = r.face_varying && !mesh.face_varying.empty();
        if (uv) {
            std::vector<FaceVaryingSemiSharp> semi;
            std::optional<adapters::LevelTrace> levels = face_varying_levels(mesh, r, &semi);
            if (!levels)
                throw InputError("the limit of texture coordinates needs a manifold mesh (core refines a non-manifold "
                                 "mesh's positions without them)");
            out.level = std::move(levels->back());
            out.uv = face_varying_limit(out.level, out.level.face_varying.front(), face_varying_scheme(r.scheme),
                                        face_varying_options(r), semi.empty() ? nullptr : &semi.front());
        } else if (r.scheme == Scheme::Loop) {
            out.level = to_poly_mesh(loop_subdivide(to_tri_mesh(mesh, "Loop subdivision"), r.rule.loop, r.levels));
        } else {
            out.level = catmull_clark_subdivide(mesh, r.rule.catmull_clark, r.levels);
        }
        LimitResult limit = r.scheme == Scheme::Loop ? loop_limit(to_tri_mesh(out.level, "Loop subdivision"), r.rule.loop)
                                                     : catmull_clark_limit(out.level, r.rule.catmull_clark);
        out.position = std::move(limit.position);
        out.normal = std::move(limit.normal);
        return out;
    }

    PrincipalCurvatures curvatures(const TriMesh& mesh) const override {
        DiscreteCurvature c = discrete_curvature(mesh);
        PrincipalCurvatures out{"cotangent Laplacian and angle defect (Meyer et al. 2002)", {}, std::move(c.k1),
                                std::move(c.k2), std::move(c.mean), std::move(c.gaussian), std::move(c.direction1)};
        out.estimated.reserve(c.status.size());
        for (CurvatureStatus s : c.status) out.estimated.push_back(s == CurvatureStatus::Estimated);
        return out;
    }
};

}  // namespace

std::unique_ptr<Implementation> make_core_implementation() { return std::make_unique<Core>(); }

}  // namespace crossdiv::verification::detail
