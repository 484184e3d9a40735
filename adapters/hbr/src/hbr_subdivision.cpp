// The Hbr adapter's conversions: crossdiv's meshes and rules to Hbr's input, Hbr's levels back
// to a LevelTrace. Hbr itself is in hbr_refiner.cpp (C++17).
#include "crossdiv/adapters/hbr.h"

#include <algorithm>
#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hbr_refiner.h"

namespace crossdiv::adapters::hbr {
namespace {

constexpr const char* kOwnCreaseRules =
    "Hbr changes crease rules its own way where semi-sharp features decay (creases=hbr); it has no other";

/// Hbr asserts (or corrupts its half-edges) on a face it cannot link; refuse such a mesh first,
/// as OpenSubdiv's regression reader does before it calls NewFace: a face naming a vertex twice,
/// a directed edge used twice (a flipped face, or more than two faces on an edge), a vertex
/// without faces (Hbr never refines it).
void check_topology(const PolyMesh& mesh) {
    struct DirectedEdge {
        int a, b, face;
    };
    std::vector<DirectedEdge> edges;
    edges.reserve(mesh.face_vertices.size());
    std::vector<int> last_face(static_cast<size_t>(mesh.num_vertices()), -1);
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const int* c = mesh.face(f);
        const int n = mesh.face_size(f);
        for (int k = 0; k < n; ++k) {
            int& seen = last_face[static_cast<size_t>(c[k])];
            if (seen == f) throw Rejected("Hbr cannot hold face " + std::to_string(f) + ": it names vertex " + std::to_string(c[k]) + " twice");
            seen = f;
            edges.push_back({c[k], c[(k + 1) % n], f});
        }
    }
    std::sort(edges.begin(), edges.end(), [](const DirectedEdge& x, const DirectedEdge& y) {
        return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.face < y.face;
    });
    for (size_t i = 1; i < edges.size(); ++i)
        if (edges[i].a == edges[i - 1].a && edges[i].b == edges[i - 1].b)
            throw Rejected("Hbr cannot hold face " + std::to_string(edges[i].face) + ": its edge " + std::to_string(edges[i].a) + "-" +
                           std::to_string(edges[i].b) + " runs the same way in face " + std::to_string(edges[i - 1].face) +
                           " (a flipped face, or more than two faces on the edge)");
    for (int v = 0; v < mesh.num_vertices(); ++v)
        if (last_face[static_cast<size_t>(v)] < 0)
            throw Rejected("Hbr does not refine vertex " + std::to_string(v) + ", which has no faces");
}

/// Refuses, for `levels` >= 2 of Loop, two triangles on the same three vertices (back to back:
/// with check_topology passed they share all three edges, a closed component of their own).
/// Hbr's Loop refines them once, then loops without end in HbrVertex::AddIncidentEdge on the
/// second level (measured: any such pair, beside other components or alone, at levels 2 and
/// 3; its Catmull-Clark and bilinear refine them). Refused here so the run is not a minute of a
/// core spent waiting for the timeout; the reason keeps the finding.
void check_loop_back_to_back(const PolyMesh& mesh, int levels) {
    if (levels < 2) return;
    struct Triple {
        std::array<int, 3> v;
        int face;
    };
    std::vector<Triple> triples;
    triples.reserve(static_cast<size_t>(mesh.num_faces()));
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const int* c = mesh.face(f);
        std::array<int, 3> v{c[0], c[1], c[2]};
        std::sort(v.begin(), v.end());
        triples.push_back({v, f});
    }
    std::sort(triples.begin(), triples.end(), [](const Triple& x, const Triple& y) { return x.v != y.v ? x.v < y.v : x.face < y.face; });
    for (size_t i = 1; i < triples.size(); ++i)
        if (triples[i].v == triples[i - 1].v)
            throw Rejected("faces " + std::to_string(triples[i - 1].face) + " and " + std::to_string(triples[i].face) +
                           " are two triangles back to back, a closed component of their own: Hbr's Loop loops without "
                           "end on its second level there (HbrVertex::AddIncidentEdge), so it is not run");
}

/// Hbr's face-varying settings for `rule` in `in`: OpenSubdiv's table of the Hbr method and
/// propagate-corners flag each of its rules re-expresses (documentation/compatibility.rst,
/// "Face-varying Interpolation Options"), with the mesh's first channel.
/// @throws Rejected for corners-only, which OpenSubdiv 3.0 added and Hbr does not have, and for
///         a mesh without a channel.
void set_face_varying(const PolyMesh& mesh, FaceVaryingRule rule, detail::HbrInput& in) {
    if (mesh.face_varying.empty()) throw Rejected("the mesh has no face-varying channel for Hbr to refine");
    using B = detail::HbrFVarBoundary;
    switch (rule) {
        case FaceVaryingRule::None: in.fvar_boundary = B::EdgeOnly; break;
        case FaceVaryingRule::CornersOnly:
            throw Rejected("Hbr has no corners-only face-varying rule (OpenSubdiv 3.0 added it; Hbr's five rules are the others)");
        case FaceVaryingRule::CornersPlus1: in.fvar_boundary = B::EdgeAndCorner; break;
        case FaceVaryingRule::CornersPlus2:
            in.fvar_boundary = B::EdgeAndCorner;
            in.fvar_propagate_corners = true;
            break;
        case FaceVaryingRule::Boundaries: in.fvar_boundary = B::AlwaysSharp; break;
        case FaceVaryingRule::All: in.fvar_boundary = B::None; break;
    }
    const FaceVaryingChannel& channel = mesh.face_varying.front();
    in.fvar_width = channel.dimension;
    in.fvar_values.assign(channel.values.begin(), channel.values.end());  // Hbr's data are floats
    in.fvar_corners = channel.corner_values;
}

/// Hbr's input for `mesh` under `scheme`, with its first face-varying channel under `fvar`.
detail::HbrInput input_of(const PolyMesh& mesh, detail::HbrScheme scheme, int levels,
                          std::optional<FaceVaryingRule> fvar = std::nullopt) {
    check_topology(mesh);
    detail::HbrInput in;
    in.scheme = scheme;
    in.levels = levels;
    for (const Vec3& p : mesh.positions) in.positions.insert(in.positions.end(), {p.x(), p.y(), p.z()});
    for (int f = 0; f < mesh.num_faces(); ++f) in.face_sizes.push_back(mesh.face_size(f));
    in.corners = mesh.face_vertices;
    for (const SharpEdge& e : mesh.creases.edges) {
        in.crease_ends.insert(in.crease_ends.end(), {e.a, e.b});
        in.crease_sharpness.push_back(e.sharpness);
    }
    for (const SharpVertex& v : mesh.creases.vertices) {
        in.corner_vertices.push_back(v.v);
        in.corner_sharpness.push_back(v.sharpness);
    }
    in.holes = mesh.creases.holes;
    for (const HierarchicalEdit& e : mesh.creases.edits) {
        // Hbr takes a path as given and walks off the mesh (or its child array) on a bad one.
        const bool in_range = e.face >= 0 && e.face < mesh.num_faces();
        if (const std::string problem = hierarchical_edit_problem(e, mesh.num_faces(), in_range ? mesh.face_size(e.face) : 0);
            !problem.empty())
            throw Rejected("hierarchical edit " + describe(e) + ": " + problem);
        detail::HbrEdit h;
        h.target = static_cast<int>(e.target);
        h.op = static_cast<int>(e.op);
        h.face = e.face;
        h.children = e.children;
        h.element = e.element;
        for (int i = 0; i < 3; ++i) h.value[i] = static_cast<float>(e.value[static_cast<size_t>(i)]);
        in.edits.push_back(std::move(h));
    }
    if (fvar) set_face_varying(mesh, *fvar, in);
    return in;
}

/// @throws Rejected for a mesh with hierarchical edits, under a scheme whose paths Hbr's
///         regression reader does not define (its Loop and bilinear schemes).
void reject_hierarchical_edits(const PolyMesh& mesh, const char* scheme) {
    if (!mesh.creases.edits.empty())
        throw Rejected(std::string(scheme) + " is not compared with hierarchical edits (" +
                       std::to_string(mesh.creases.edits.size()) + " here): crossdiv applies them under Catmull-Clark only");
}

/// Hbr's levels as a LevelTrace (level 0 the input), each vertex's parent in `births`.
LevelTrace run(const PolyMesh& mesh, const detail::HbrInput& in, LevelBirths* births) {
    detail::HbrOutput out = detail::refine(in);
    if (!out.error.empty()) throw Rejected(out.error);
    LevelTrace trace;
    trace.push_back(mesh);
    trace.back().source = {};
    for (const detail::HbrLevel& lv : out.levels) {
        PolyMesh level;
        for (size_t i = 0; i < lv.positions.size(); i += 3) level.positions.emplace_back(lv.positions[i], lv.positions[i + 1], lv.positions[i + 2]);
        for (size_t f = 0, c = 0; f < lv.face_sizes.size(); c += static_cast<size_t>(lv.face_sizes[f]), ++f)
            level.add_face(std::span<const int>(lv.corners.data() + c, static_cast<size_t>(lv.face_sizes[f])));
        level.creases.holes = lv.holes;
        if (in.fvar_width > 0) {
            FaceVaryingChannel channel;
            channel.name = mesh.face_varying.front().name;
            channel.dimension = in.fvar_width;
            channel.values.assign(lv.fvar_values.begin(), lv.fvar_values.end());
            channel.corner_values = lv.fvar_corners;
            level.face_varying.push_back(std::move(channel));
        }
        if (births) {
            std::vector<VertexBirth> born(lv.parent_kind.size());
            for (size_t v = 0; v < born.size(); ++v) {
                const VertexBirth::Kind kind = lv.parent_kind[v] == 0   ? VertexBirth::Kind::Vertex
                                               : lv.parent_kind[v] == 1 ? VertexBirth::Kind::Edge
                                                                        : VertexBirth::Kind::Face;
                born[v] = {kind, lv.parent_a[v], lv.parent_b[v]};
            }
            births->push_back(std::move(born));
        }
        trace.push_back(std::move(level));
    }
    return trace;
}

/// The schemes with their first face-varying channel refined under `fvar`, or without.
LevelTrace catmull_clark_with(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels, LevelBirths* births,
                              std::optional<FaceVaryingRule> fvar) {
    if (options.boundary == CatmullClarkBoundary::MidpointAverage)
        throw Rejected("Hbr's Catmull-Clark has no midpoint-average boundary rule (OpenMesh's)");
    if (options.vertex != CatmullClarkVertexRule::Standard) throw Rejected("Hbr's Catmull-Clark has the standard vertex rule only");
    if (options.crease_rules != CreaseRules::Hbr) throw Rejected(kOwnCreaseRules);
    detail::HbrInput in = input_of(mesh, detail::HbrScheme::CatmullClark, levels, fvar);
    in.edge_and_corner = options.boundary == CatmullClarkBoundary::EdgeAndCorner;
    in.chaikin = options.creasing == CreaseMethod::Chaikin;
    in.smooth_triangles = options.smooth_triangles;
    return run(mesh, in, births);
}

LevelTrace loop_with(const PolyMesh& mesh, const LoopOptions& options, int levels, LevelBirths* births,
                     std::optional<FaceVaryingRule> fvar) {
    if (options.weights != LoopWeights::Loop)
        throw Rejected("Hbr's Loop scheme has Loop's 1987 weights only (not " + std::string(to_string(options.weights)) + ")");
    if (options.crease_rules != CreaseRules::Hbr) throw Rejected(kOwnCreaseRules);
    for (int f = 0; f < mesh.num_faces(); ++f)
        if (mesh.face_size(f) != 3)
            throw Rejected("Hbr's Loop scheme takes triangles; face " + std::to_string(f) + " has " + std::to_string(mesh.face_size(f)) + " corners");
    reject_hierarchical_edits(mesh, "Hbr's Loop scheme");
    detail::HbrInput in = input_of(mesh, detail::HbrScheme::Loop, levels, fvar);
    check_loop_back_to_back(mesh, levels);
    in.edge_and_corner = options.boundary == LoopBoundary::EdgeAndCorner;
    in.chaikin = options.creasing == CreaseMethod::Chaikin;
    return run(mesh, in, births);
}

LevelTrace bilinear_with(const PolyMesh& mesh, int levels, LevelBirths* births, std::optional<FaceVaryingRule> fvar) {
    // Bilinear has no crease rules; Hbr would refine the holes and drop the creases.
    reject_crease_tags(mesh, "Hbr's bilinear scheme");
    return run(mesh, input_of(mesh, detail::HbrScheme::Bilinear, levels, fvar), births);
}

}  // namespace

LevelTrace catmull_clark(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels, LevelBirths* births) {
    return catmull_clark_with(mesh, options, levels, births, std::nullopt);
}

LevelTrace loop(const PolyMesh& mesh, const LoopOptions& options, int levels, LevelBirths* births) {
    return loop_with(mesh, options, levels, births, std::nullopt);
}

LevelTrace bilinear(const PolyMesh& mesh, int levels, LevelBirths* births) { return bilinear_with(mesh, levels, births, std::nullopt); }

LevelTrace catmull_clark_face_varying(const PolyMesh& mesh, const CatmullClarkOptions& options, FaceVaryingRule rule,
                                      int levels, LevelBirths* births) {
    return catmull_clark_with(mesh, options, levels, births, rule);
}

LevelTrace loop_face_varying(const PolyMesh& mesh, const LoopOptions& options, FaceVaryingRule rule, int levels,
                             LevelBirths* births) {
    return loop_with(mesh, options, levels, births, rule);
}

LevelTrace bilinear_face_varying(const PolyMesh& mesh, FaceVaryingRule rule, int levels, LevelBirths* births) {
    return bilinear_with(mesh, levels, births, rule);
}

std::string version() { return "OpenSubdiv Hbr " + detail::version(); }

}  // namespace crossdiv::adapters::hbr
