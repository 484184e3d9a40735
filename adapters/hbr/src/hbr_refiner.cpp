// OpenSubdiv's Hbr (hierarchical boundary representation): the one translation unit that
// includes its headers, compiled as C++17 (hbr_refiner.h). Hbr is header-only templates over
// the vertex data type, here a double-precision point; Hbr's own weights are floats.
//
// HBR_ADAPTIVE declares the split-vertex list (a vertex whose faces form more than one fan is
// split by Finish()). Hbr's headers are not self-contained: mesh.h first, as OpenSubdiv's own
// regression code includes them.
#define HBR_ADAPTIVE
// clang-format off
#include <cassert>
#include <opensubdiv/hbr/mesh.h>
#include <opensubdiv/hbr/bilinear.h>
#include <opensubdiv/hbr/loop.h>
#include <opensubdiv/hbr/catmark.h>
#include <opensubdiv/hbr/cornerEdit.h>
#include <opensubdiv/hbr/creaseEdit.h>
#include <opensubdiv/hbr/holeEdit.h>
#include <opensubdiv/hbr/vertexEdit.h>
#include <opensubdiv/version.h>
// clang-format on

#include <algorithm>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "hbr_refiner.h"

namespace crossdiv::adapters::hbr::detail {
namespace {

/// Hbr's vertex data: a position, combined with Hbr's (float) weights in double.
class Point {
public:
    Point() = default;
    explicit Point(int) {}  // HbrMesh::NewVertex(id) makes its data from the ID
    Point(double x, double y, double z) : p_{x, y, z} {}

    void Clear(void* = nullptr) { p_[0] = p_[1] = p_[2] = 0.0; }
    void AddWithWeight(const Point& src, float weight, void* = nullptr) {
        for (int i = 0; i < 3; ++i) p_[i] += static_cast<double>(weight) * src.p_[i];
    }
    /// Varying data (linearly interpolated primvars): a position has none.
    void AddVaryingWithWeight(const Point&, float, void* = nullptr) {}
    /// A hierarchical edit of the position ("P"): set, add or subtract three values.
    void ApplyVertexEdit(const OpenSubdiv::HbrVertexEdit<Point>& edit) {
        const float* value = edit.GetEdit();
        for (int i = 0; i < 3; ++i) {
            switch (edit.GetOperation()) {
                case OpenSubdiv::HbrHierarchicalEdit<Point>::Set: p_[i] = value[i]; break;
                case OpenSubdiv::HbrHierarchicalEdit<Point>::Add: p_[i] += value[i]; break;
                case OpenSubdiv::HbrHierarchicalEdit<Point>::Subtract: p_[i] -= value[i]; break;
            }
        }
    }
    void ApplyMovingVertexEdit(const OpenSubdiv::HbrMovingVertexEdit<Point>&) {}

    const double* data() const { return p_; }

private:
    double p_[3] = {0.0, 0.0, 0.0};
};

using Mesh = OpenSubdiv::HbrMesh<Point>;
using Vertex = OpenSubdiv::HbrVertex<Point>;
using Face = OpenSubdiv::HbrFace<Point>;
using Halfedge = OpenSubdiv::HbrHalfedge<Point>;
using Subdivision = OpenSubdiv::HbrSubdivision<Point>;

/// The number of floats Hbr is given for a channel of `width`: Hbr's allocator lays its vertices
/// back to back, each followed by its face-varying datum (HbrMesh's m_vertexSize), so a datum
/// whose size is not a multiple of a vertex's alignment leaves the next vertex misaligned
/// (undefined behaviour; UBSan stops at the constructor call with two floats). The width is
/// rounded up until the datum keeps the alignment; the extra floats are zeros, refined with
/// the others and dropped.
int padded_fvar_width(int width) {
    int w = width;
    while ((sizeof(OpenSubdiv::HbrFVarData<Point>) + static_cast<size_t>(w - 1) * sizeof(float)) % alignof(Vertex) != 0) ++w;
    return w;
}

/// How Hbr lays out a face-varying channel of `width` numbers (padded_fvar_width of the
/// channel's): `width` items of one float each, as OpenSubdiv's regression code gives it UVs.
/// HbrMesh keeps pointers to both arrays.
struct FVarLayout {
    int width = 0;
    std::vector<int> indices, widths;
    explicit FVarLayout(int w) : width(w), indices(static_cast<size_t>(w)), widths(static_cast<size_t>(w), 1) {
        std::iota(indices.begin(), indices.end(), 0);
    }
};

/// Hbr's face-varying data of `in`: each corner's value on its vertex's datum for that face, a
/// second datum (NewFVarData) where a vertex's faces disagree, as OpenSubdiv's regression code
/// sets them. Called after Finish(), when every face knows its vertices.
void set_face_varying(Mesh& mesh, const HbrInput& in, int w) {
    std::vector<float> value(static_cast<size_t>(w), 0.0f);  // the channel's numbers, then the padding's zeros
    for (int f = 0, c = 0; f < static_cast<int>(in.face_sizes.size()); ++f) {
        Face* face = mesh.GetFace(f);
        for (int k = 0; k < in.face_sizes[static_cast<size_t>(f)]; ++k, ++c) {
            const float* given = in.fvar_values.data() + static_cast<size_t>(in.fvar_corners[static_cast<size_t>(c)]) * in.fvar_width;
            std::copy(given, given + in.fvar_width, value.begin());
            Vertex* v = face->GetVertex(k);
            OpenSubdiv::HbrFVarData<Point>& data = v->GetFVarData(face);
            if (!data.IsInitialized())
                data.SetAllData(w, value.data());
            else if (!data.CompareAll(w, value.data()))
                v->NewFVarData(face).SetAllData(w, value.data());
        }
    }
}

/// The Hbr mesh of `in` with its tags, finished; empty with `error` set when a tag names
/// something the mesh does not have.
std::unique_ptr<Mesh> build(const HbrInput& in, Subdivision* scheme, const FVarLayout& fvar, std::string& error) {
    auto out = in.fvar_width > 0 ? std::make_unique<Mesh>(scheme, fvar.width, fvar.indices.data(), fvar.widths.data(), fvar.width)
                                 : std::make_unique<Mesh>(scheme);
    const int nv = static_cast<int>(in.positions.size() / 3);
    for (int v = 0; v < nv; ++v) out->NewVertex(v, Point(in.positions[3 * v], in.positions[3 * v + 1], in.positions[3 * v + 2]));
    for (size_t f = 0, c = 0; f < in.face_sizes.size(); c += static_cast<size_t>(in.face_sizes[f]), ++f)
        out->NewFace(in.face_sizes[f], const_cast<int*>(in.corners.data() + c), 0);
    for (size_t e = 0; e < in.crease_sharpness.size(); ++e) {
        Vertex* a = out->GetVertex(in.crease_ends[2 * e]);
        Vertex* b = out->GetVertex(in.crease_ends[2 * e + 1]);
        Halfedge* h = a && b ? (a->GetEdge(b) ? a->GetEdge(b) : b->GetEdge(a)) : nullptr;
        if (!h) {
            error = "a crease tag names edge " + std::to_string(in.crease_ends[2 * e]) + "-" +
                    std::to_string(in.crease_ends[2 * e + 1]) + ", which the mesh does not have";
            return nullptr;
        }
        h->SetSharpness(in.crease_sharpness[e]);
    }
    for (size_t c = 0; c < in.corner_sharpness.size(); ++c) {
        Vertex* v = out->GetVertex(in.corner_vertices[c]);
        if (!v) {
            error = "a corner tag names vertex " + std::to_string(in.corner_vertices[c]) + ", which the mesh does not have";
            return nullptr;
        }
        v->SetSharpness(in.corner_sharpness[c]);
    }
    for (int f : in.holes) out->GetFace(f)->SetHole();
    using Edit = OpenSubdiv::HbrHierarchicalEdit<Point>;
    for (const HbrEdit& e : in.edits) {
        const typename Edit::Operation op = e.op == 0 ? Edit::Set : e.op == 1 ? Edit::Add : Edit::Subtract;
        // Hbr's edits copy their path (HbrHierarchicalEdit's constructor) through a pointer that
        // is not const.
        int* path = const_cast<int*>(e.children.data());
        const int depth = static_cast<int>(e.children.size());
        float value[3] = {e.value[0], e.value[1], e.value[2]};
        if (e.target == 0)
            out->AddHierarchicalEdit(new OpenSubdiv::HbrVertexEdit<Point>(e.face, depth, path, e.element, 0, 3, true, op, value));
        else if (e.target == 1)
            out->AddHierarchicalEdit(new OpenSubdiv::HbrCornerEdit<Point>(e.face, depth, path, e.element, op, value[0]));
        else if (e.target == 2)
            out->AddHierarchicalEdit(new OpenSubdiv::HbrCreaseEdit<Point>(e.face, depth, path, e.element, op, value[0]));
        else
            out->AddHierarchicalEdit(new OpenSubdiv::HbrHoleEdit<Point>(e.face, depth, path));
    }
    out->SetInterpolateBoundaryMethod(in.edge_and_corner ? Mesh::k_InterpolateBoundaryEdgeAndCorner : Mesh::k_InterpolateBoundaryEdgeOnly);
    scheme->SetCreaseSubdivisionMethod(in.chaikin ? Subdivision::k_CreaseChaikin : Subdivision::k_CreaseNormal);
    if (in.fvar_width > 0) {
        static constexpr Mesh::InterpolateBoundaryMethod kMethods[] = {
            Mesh::k_InterpolateBoundaryNone, Mesh::k_InterpolateBoundaryEdgeOnly, Mesh::k_InterpolateBoundaryEdgeAndCorner,
            Mesh::k_InterpolateBoundaryAlwaysSharp};
        out->SetFVarInterpolateBoundaryMethod(kMethods[static_cast<int>(in.fvar_boundary)]);
        out->SetFVarPropagateCorners(in.fvar_propagate_corners);
    }
    out->Finish();
    if (in.fvar_width > 0) set_face_varying(*out, in, fvar.width);
    return out;
}

/// The face-varying channel of `faces` (one level's, in order) into `lv`: one value per Hbr
/// datum, told apart by address and numbered in order of first use.
void read_face_varying(const std::vector<Face*>& faces, int width, HbrLevel& lv) {
    using Datum = OpenSubdiv::HbrFVarData<Point>;
    std::vector<Datum*> data;
    for (Face* f : faces)
        for (int k = 0; k < f->GetNumVertices(); ++k) data.push_back(&f->GetFVarData(k));
    // The corners sorted by datum, then by corner: each run is one datum, its first corner first.
    std::vector<size_t> order(data.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return data[a] != data[b] ? std::less<Datum*>()(data[a], data[b]) : a < b;
    });
    std::vector<size_t> first(data.size());  // each corner's first corner with the same datum
    for (size_t i = 0, run = 0; i < order.size(); ++i) {
        if (data[order[i]] != data[order[run]]) run = i;
        first[order[i]] = order[run];
    }
    std::vector<int> number(data.size(), -1);
    lv.fvar_corners.resize(data.size());
    for (size_t c = 0; c < data.size(); ++c) {
        int& n = number[first[c]];
        if (n < 0) {
            n = static_cast<int>(lv.fvar_values.size()) / width;
            lv.fvar_values.insert(lv.fvar_values.end(), data[c]->GetData(0), data[c]->GetData(0) + width);
        }
        lv.fvar_corners[c] = n;
    }
}

/// The parent of `v` (a vertex of the level after `index`'s), in the numbering of its level:
/// `index` maps Hbr's vertex IDs, `face_index` its face IDs. False when Hbr names none.
bool record_parent(Vertex* v, const std::vector<int>& index, const std::vector<int>& face_index, HbrLevel& lv) {
    int kind = 0, a = -1, b = -1;
    if (Face* pf = v->GetParentFace()) {
        kind = 2;
        a = face_index[static_cast<size_t>(pf->GetID())];
    } else if (Halfedge* pe = v->GetParentEdge()) {
        kind = 1;
        a = index[static_cast<size_t>(pe->GetOrgVertex()->GetID())];
        b = index[static_cast<size_t>(pe->GetDestVertex()->GetID())];
    } else if (Vertex* pv = v->GetParentVertex()) {
        a = index[static_cast<size_t>(pv->GetID())];
    } else {
        return false;
    }
    lv.parent_kind.push_back(kind);
    lv.parent_a.push_back(a);
    lv.parent_b.push_back(b);
    return true;
}

/// Refines every face of every level (hole faces too: Hbr hands their holes down to their
/// children, as Far does) and reads each level back. Each level's vertices are numbered as
/// Far and core number them where they can be: first the children of the level before's
/// vertices, in its order, so that a vertex keeps its number; then the others (edge and face
/// points) in order of first use by the child faces.
void refine_levels(Mesh& mesh, int num_vertices, int num_faces, int levels, int fvar_width, HbrOutput& out) {
    std::vector<Face*> faces;
    for (int f = 0; f < num_faces; ++f) faces.push_back(mesh.GetFace(f));
    // The vertices of the current level in its numbering; a split vertex (Hbr's copy of a
    // vertex whose faces form more than one fan, made by Finish()) after the input's, and
    // named as its original.
    std::vector<Vertex*> vertices;
    std::vector<int> index(static_cast<size_t>(mesh.GetNumVertices()), -1);
    for (int v = 0; v < num_vertices; ++v) {
        vertices.push_back(mesh.GetVertex(v));
        index[static_cast<size_t>(v)] = v;
    }
    for (const std::pair<int, int>& split : mesh.GetSplitVertices()) {
        vertices.push_back(mesh.GetVertex(split.first));
        index[static_cast<size_t>(split.first)] = split.second;
    }
    std::vector<int> face_index;  // Hbr face ID -> position in `faces`
    Subdivision* scheme = mesh.GetSubdivision();
    for (int level = 1; level <= levels; ++level) {
        face_index.assign(static_cast<size_t>(mesh.GetNumFaces()), -1);
        for (size_t f = 0; f < faces.size(); ++f) face_index[static_cast<size_t>(faces[f]->GetID())] = static_cast<int>(f);
        for (Face* f : faces) f->Refine();
        std::vector<Face*> children;
        for (Face* f : faces) {
            const int n = scheme->GetFaceChildrenCount(f->GetNumVertices());
            for (int c = 0; c < n; ++c)
                if (Face* child = f->GetChild(c)) children.push_back(child);
        }
        HbrLevel lv;
        std::vector<Vertex*> next_vertices;
        std::vector<int> next(static_cast<size_t>(mesh.GetNumVertices()), -1);
        const auto number = [&](Vertex* v) {
            int& id = next[static_cast<size_t>(v->GetID())];
            if (id >= 0) return true;
            id = static_cast<int>(next_vertices.size());
            next_vertices.push_back(v);
            const double* p = v->GetData().data();
            lv.positions.insert(lv.positions.end(), p, p + 3);
            if (record_parent(v, index, face_index, lv)) return true;
            out.error = "Hbr made vertex " + std::to_string(v->GetID()) + " of level " + std::to_string(level) + " without a parent";
            return false;
        };
        // Hbr applies a vertex edit when a vertex's neighbourhood is first complete
        // (HbrVertex::GuaranteeNeighbors, which the next level's refinement calls): so that
        // each level is read as edited, as the next level sees it, that is done here.
        if (mesh.HasVertexEdits())
            for (Face* f : children)
                for (int k = 0; k < f->GetNumVertices(); ++k) f->GetVertex(k)->GuaranteeNeighbors();
        for (Vertex* v : vertices)
            if (v->HasChild() && !number(v->Subdivide())) return;
        for (Face* f : children) {
            if (f->IsHole()) lv.holes.push_back(static_cast<int>(lv.face_sizes.size()));
            lv.face_sizes.push_back(f->GetNumVertices());
            for (int k = 0; k < f->GetNumVertices(); ++k) {
                if (!number(f->GetVertex(k))) return;
                lv.corners.push_back(next[static_cast<size_t>(f->GetVertex(k)->GetID())]);
            }
        }
        if (fvar_width > 0) read_face_varying(children, fvar_width, lv);
        out.levels.push_back(std::move(lv));
        index = std::move(next);
        vertices = std::move(next_vertices);
        faces = std::move(children);
    }
}

}  // namespace

HbrOutput refine(const HbrInput& in) {
    OpenSubdiv::HbrCatmarkSubdivision<Point> catmark;
    OpenSubdiv::HbrLoopSubdivision<Point> loop;
    OpenSubdiv::HbrBilinearSubdivision<Point> bilinear;
    catmark.SetTriangleSubdivisionMethod(in.smooth_triangles ? OpenSubdiv::HbrCatmarkSubdivision<Point>::k_New
                                                             : OpenSubdiv::HbrCatmarkSubdivision<Point>::k_Normal);
    Subdivision* scheme = in.scheme == HbrScheme::CatmullClark ? static_cast<Subdivision*>(&catmark)
                          : in.scheme == HbrScheme::Loop       ? static_cast<Subdivision*>(&loop)
                                                               : static_cast<Subdivision*>(&bilinear);
    HbrOutput out;
    const FVarLayout fvar(in.fvar_width > 0 ? padded_fvar_width(in.fvar_width) : 0);  // outlives the mesh, which points into it
    std::unique_ptr<Mesh> mesh = build(in, scheme, fvar, out.error);
    if (mesh)
        refine_levels(*mesh, static_cast<int>(in.positions.size() / 3), static_cast<int>(in.face_sizes.size()), in.levels,
                      in.fvar_width, out);
    return out;
}

std::string version() {
    return std::to_string(OPENSUBDIV_VERSION_MAJOR) + "." + std::to_string(OPENSUBDIV_VERSION_MINOR) + "." +
           std::to_string(OPENSUBDIV_VERSION_PATCH);
}

}  // namespace crossdiv::adapters::hbr::detail
