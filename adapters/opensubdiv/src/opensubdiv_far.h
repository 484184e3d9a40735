#pragma once
// What every OpenSubdiv translation unit of the adapter shares (internal header): the primvar
// type, Far's error callback, the refiner factory call, and reading a level back.
#include <opensubdiv/far/error.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <memory>
#include <string>
#include <vector>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/catmull_clark_mask.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv::adapters::opensubdiv::detail {

using namespace OpenSubdiv;

/// Sdc options for our boundary rule (edge-only, or edge-and-corner) and crease decay; the
/// library default VTX_BOUNDARY_NONE (boundary faces become holes) is never used.
inline Sdc::Options sdc_options(bool edge_and_corner, CreaseMethod creasing) {
    Sdc::Options sdc;
    sdc.SetVtxBoundaryInterpolation(edge_and_corner ? Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER
                                                    : Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    sdc.SetCreasingMethod(creasing == CreaseMethod::Uniform ? Sdc::Options::CREASE_UNIFORM
                                                            : Sdc::Options::CREASE_CHAIKIN);
    return sdc;
}

/// Sdc options of core's Catmull-Clark options. @throws Rejected for the midpoint-average rule.
inline Sdc::Options catmark_options(const CatmullClarkOptions& options) {
    if (options.boundary == CatmullClarkBoundary::MidpointAverage)
        throw Rejected("OpenSubdiv's Catmull-Clark has no midpoint-average boundary rule (OpenMesh's)");
    Sdc::Options sdc = sdc_options(options.boundary == CatmullClarkBoundary::EdgeAndCorner, options.creasing);
    if (options.smooth_triangles) sdc.SetTriangleSubdivision(Sdc::Options::TRI_SUB_SMOOTH);
    return sdc;
}

/// Sdc options of core's Loop options. @throws Rejected for Warren's weights.
inline Sdc::Options loop_options(const LoopOptions& options) {
    if (options.weights != LoopWeights::Loop)
        throw Rejected("OpenSubdiv's Loop scheme has Loop's 1987 weights only (not " + std::string(to_string(options.weights)) + ")");
    return sdc_options(options.boundary == LoopBoundary::EdgeAndCorner, options.creasing);
}

/// Primvar with the Clear/AddWithWeight interface PrimvarRefiner expects.
struct Point3 {
    double p[3];
    void Clear() { p[0] = p[1] = p[2] = 0.0; }
    void AddWithWeight(const Point3& src, double w) {
        p[0] += w * src.p[0];
        p[1] += w * src.p[1];
        p[2] += w * src.p[2];
    }
    Vec3 vec() const { return {p[0], p[1], p[2]}; }
};

// Far reports topology errors through a global C callback; collect them for Rejected.
inline std::string g_far_errors;
inline void collect_far_error(Far::ErrorType, const char* message) {
    g_far_errors += message;
    g_far_errors += "; ";
}

/// Far's refiner for a polygon mesh given as face sizes and corner indices (not refined yet).
/// @throws Rejected with Far's own words when the factory refuses the mesh.
/// Crease and corner tags go to the descriptor's sharpness arrays, as given (Far sharpens the
/// boundary itself).
inline std::unique_ptr<Far::TopologyRefiner> make_refiner(int num_vertices, const std::vector<int>& face_sizes,
                                                          const std::vector<int>& corners, Sdc::SchemeType scheme,
                                                          const Sdc::Options& sdc, const CreaseTags& tags = {},
                                                          const FaceVaryingChannel* fvar = nullptr) {
    Far::TopologyDescriptor desc;
    desc.numVertices = num_vertices;
    desc.numFaces = static_cast<int>(face_sizes.size());
    desc.numVertsPerFace = face_sizes.data();
    desc.vertIndicesPerFace = corners.data();
    std::vector<int> crease_pairs, corner_vertices;
    std::vector<float> crease_weights, corner_weights;
    for (const SharpEdge& e : tags.edges) {
        crease_pairs.insert(crease_pairs.end(), {e.a, e.b});
        crease_weights.push_back(e.sharpness);
    }
    for (const SharpVertex& v : tags.vertices) {
        corner_vertices.push_back(v.v);
        corner_weights.push_back(v.sharpness);
    }
    desc.numCreases = static_cast<int>(crease_weights.size());
    desc.creaseVertexIndexPairs = crease_pairs.data();
    desc.creaseWeights = crease_weights.data();
    desc.numCorners = static_cast<int>(corner_weights.size());
    desc.cornerVertexIndices = corner_vertices.data();
    desc.cornerWeights = corner_weights.data();
    desc.numHoles = static_cast<int>(tags.holes.size());
    desc.holeIndices = tags.holes.data();
    Far::TopologyDescriptor::FVarChannel channel;
    if (fvar) {
        channel.numValues = fvar->num_values();
        channel.valueIndices = fvar->corner_values.data();
        desc.numFVarChannels = 1;
        desc.fvarChannels = &channel;
    }
    g_far_errors.clear();
    Far::SetErrorCallback(collect_far_error);
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, Factory::Options(scheme, sdc)));
    if (!refiner) throw Rejected("Far::TopologyRefinerFactory failed: " + g_far_errors);
    return refiner;
}

/// The refiner of a polygon mesh with its tags, and with face-varying channel `fvar` (channel 0) when given.
inline std::unique_ptr<Far::TopologyRefiner> make_refiner(const PolyMesh& mesh, Sdc::SchemeType scheme,
                                                          const Sdc::Options& sdc,
                                                          const FaceVaryingChannel* fvar = nullptr) {
    std::vector<int> sizes(static_cast<size_t>(mesh.num_faces()));
    for (int f = 0; f < mesh.num_faces(); ++f) sizes[f] = mesh.face_size(f);
    return make_refiner(mesh.num_vertices(), sizes, mesh.face_vertices, scheme, sdc, mesh.creases, fvar);
}

/// Uniform refinement; full topology in the last level when asked (edges, for Limit()).
/// @throws Rejected when Far reports an error while refining.
inline void refine_uniform(Far::TopologyRefiner& refiner, int levels, bool full_topology_in_last_level) {
    Far::TopologyRefiner::UniformOptions uniform(levels);
    uniform.fullTopologyInLastLevel = full_topology_in_last_level;
    refiner.RefineUniform(uniform);
    if (!g_far_errors.empty()) throw Rejected("Far reported: " + g_far_errors);
}

/// The positions of the input, with room for every refined level after them.
inline std::vector<Point3> base_points(const Far::TopologyRefiner& refiner, const std::vector<Vec3>& positions) {
    std::vector<Point3> points(static_cast<size_t>(refiner.GetNumVerticesTotal()));
    for (size_t v = 0; v < positions.size(); ++v) points[v] = {{positions[v].x(), positions[v].y(), positions[v].z()}};
    return points;
}

/// One level as a PolyMesh (Far's vertex and face order), its hole faces as hole tags.
inline PolyMesh level_mesh(const Far::TopologyLevel& level, const Point3* points) {
    PolyMesh m;
    m.positions.reserve(static_cast<size_t>(level.GetNumVertices()));
    for (int v = 0; v < level.GetNumVertices(); ++v) m.positions.push_back(points[v].vec());
    for (int f = 0; f < level.GetNumFaces(); ++f) {
        Far::ConstIndexArray fv = level.GetFaceVertices(f);
        for (int k = 0; k < fv.size(); ++k) m.face_vertices.push_back(fv[k]);
        m.face_start.push_back(static_cast<int>(m.face_vertices.size()));
        if (level.IsFaceHole(f)) m.creases.holes.push_back(f);
    }
    return m;
}

/// The refiner's last level, positions interpolated level by level in double into one buffer
/// and kept there (the native refinements `crossdiv bench` times); its face count.
inline size_t interpolate_native(const Far::TopologyRefiner& refiner, const std::vector<Vec3>& positions) {
    std::vector<Point3> points = base_points(refiner, positions);
    Far::PrimvarRefinerReal<double> primvar(refiner);
    Point3* src = points.data();
    for (int level = 1; level <= refiner.GetMaxLevel(); ++level) {
        Point3* dst = src + refiner.GetLevel(level - 1).GetNumVertices();
        primvar.Interpolate(level, src, dst);
        src = dst;
    }
    return static_cast<size_t>(refiner.GetLevel(refiner.GetMaxLevel()).GetNumFaces());
}

/// Every level of a refined refiner, positions interpolated level by level in double.
/// Where each vertex of each refined level was born, from Far's child queries on the level
/// before (GetVertexChildVertex, GetEdgeChildVertex, GetFaceChildVertex): Far's own
/// provenance, not inferred. Needs the full topology of every level but the last.
inline LevelBirths child_births(const Far::TopologyRefiner& refiner) {
    LevelBirths births;
    for (int level = 1; level <= refiner.GetMaxLevel(); ++level) {
        const Far::TopologyLevel& parent = refiner.GetLevel(level - 1);
        std::vector<VertexBirth>& out = births.emplace_back(static_cast<size_t>(refiner.GetLevel(level).GetNumVertices()));
        const auto set = [&](Far::Index child, VertexBirth birth) {
            if (child >= 0) out[static_cast<size_t>(child)] = birth;  // INDEX_INVALID: no child (a hole)
        };
        for (int v = 0; v < parent.GetNumVertices(); ++v) set(parent.GetVertexChildVertex(v), {VertexBirth::Kind::Vertex, v, -1});
        for (int e = 0; e < parent.GetNumEdges(); ++e) {
            const Far::ConstIndexArray ends = parent.GetEdgeVertices(e);
            set(parent.GetEdgeChildVertex(e), {VertexBirth::Kind::Edge, ends[0], ends[1]});
        }
        // Loop's triangle split has no face points (and Far no face-vertex table to ask).
        if (refiner.GetSchemeType() != Sdc::SCHEME_LOOP)
            for (int f = 0; f < parent.GetNumFaces(); ++f) set(parent.GetFaceChildVertex(f), {VertexBirth::Kind::Face, f, -1});
    }
    return births;
}

inline LevelTrace interpolate_trace(const Far::TopologyRefiner& refiner, const std::vector<Vec3>& positions,
                                    std::vector<Point3>* all_points = nullptr) {
    std::vector<Point3> points = base_points(refiner, positions);
    LevelTrace trace;
    trace.push_back(level_mesh(refiner.GetLevel(0), points.data()));
    Far::PrimvarRefinerReal<double> primvar(refiner);
    Point3* src = points.data();
    for (int level = 1; level <= refiner.GetMaxLevel(); ++level) {
        Point3* dst = src + refiner.GetLevel(level - 1).GetNumVertices();
        primvar.Interpolate(level, src, dst);
        trace.push_back(level_mesh(refiner.GetLevel(level), dst));
        src = dst;
    }
    if (all_points) *all_points = std::move(points);
    return trace;
}

}  // namespace crossdiv::adapters::opensubdiv::detail
