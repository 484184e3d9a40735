// The second of the two translation units that include CGAL: everything on a Surface_mesh
// apart from Loop subdivision: closed-mesh checks (orientation, volume), vertex normals,
// jet-fitted curvatures, the Hausdorff distance, edge-collapse simplification, and the Euler
// operations the half-edge differential tests compare with.
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include "cgal_surface_mesh.h"
#include "crossdiv/adapters/cgal.h"

namespace crossdiv::adapters::cgal {

using detail::Kernel;
using detail::Mesh;

ClosedMeshReport closed_mesh_report(const TriMesh& mesh) {
    ClosedMeshReport r;
    const detail::Mesh sm = detail::to_surface_mesh(mesh, r.error);
    if (!r.error.empty()) return r;
    r.built = true;
    r.valid = CGAL::is_valid_polygon_mesh(sm);
    r.closed = CGAL::is_closed(sm);
    if (r.closed && r.valid) {
        namespace PMP = CGAL::Polygon_mesh_processing;
        r.outward = PMP::is_outward_oriented(sm);
        r.volume = PMP::volume(sm);
    }
    return r;
}

namespace {

Mesh build(const TriMesh& mesh) {
    std::string refused;
    Mesh m = detail::to_surface_mesh(mesh, refused);
    if (!refused.empty()) throw Rejected(refused);
    return m;
}

/// The mesh's vertices and faces in Surface_mesh order (which is its index order when it has
/// no removed elements).
TriMesh to_tri_mesh(const Mesh& m) {
    TriMesh out;
    out.positions.reserve(m.number_of_vertices());
    for (Mesh::Vertex_index v : m.vertices()) out.positions.emplace_back(m.point(v).x(), m.point(v).y(), m.point(v).z());
    out.triangles.reserve(m.number_of_faces());
    for (Mesh::Face_index f : m.faces()) {
        Triangle t{};
        int k = 0;
        for (Mesh::Vertex_index v : m.vertices_around_face(m.halfedge(f))) t[k++ % 3] = static_cast<int>(v.idx());
        out.triangles.push_back(t);
    }
    return out;
}

}  // namespace

double hausdorff_distance(const TriMesh& a, const TriMesh& b, int face_samples, unsigned seed) {
    if (a.triangles.empty() || b.triangles.empty()) throw Rejected("the Hausdorff distance needs two meshes with triangles");
    const Mesh ma = build(a), mb = build(b);
    namespace PMP = CGAL::Polygon_mesh_processing;
    const auto sampling = CGAL::parameters::random_seed(seed).number_of_points_on_faces(static_cast<std::size_t>(face_samples));
    return PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(ma, mb, sampling, sampling);
}

TriMesh simplify(const TriMesh& mesh, int edges) {
    Mesh m = build(mesh);
    namespace SMS = CGAL::Surface_mesh_simplification;
    // Lindstrom-Turk cost and placement, the package's default policies.
    SMS::edge_collapse(m, SMS::Count_stop_predicate<Mesh>(static_cast<std::size_t>(std::max(edges, 0))));
    m.collect_garbage();
    return to_tri_mesh(m);
}

std::vector<Vec3> vertex_normals(const TriMesh& mesh) {
    Mesh m = build(mesh);
    auto normals = m.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:crossdiv_normal", CGAL::NULL_VECTOR).first;
    CGAL::Polygon_mesh_processing::compute_vertex_normals(m, normals);
    std::vector<Vec3> out;
    out.reserve(m.number_of_vertices());
    for (Mesh::Vertex_index v : m.vertices()) out.emplace_back(normals[v].x(), normals[v].y(), normals[v].z());
    return out;
}

MongeCurvatures monge_curvatures(const TriMesh& mesh, const std::vector<Vec3>& orientation, int rings, int degree) {
    if (degree < 1 || degree > 4 || rings < 1)
        throw Rejected("jet fitting takes degree 1..4 and at least one ring (got degree " + std::to_string(degree) +
                       ", " + std::to_string(rings) + " rings)");
    const Mesh m = build(mesh);
    if (orientation.size() != m.number_of_vertices())
        throw std::invalid_argument("monge_curvatures: one orientation normal per vertex");
    using Fitting = CGAL::Monge_via_jet_fitting<Kernel>;
    const size_t nv = m.number_of_vertices();
    const size_t needed = static_cast<size_t>((degree + 1) * (degree + 2) / 2);
    MongeCurvatures out;
    out.fitted.assign(nv, 0);
    out.k1.assign(nv, 0.0);
    out.k2.assign(nv, 0.0);
    out.direction1.assign(nv, Vec3::Zero());
    out.normal.assign(nv, Vec3::Zero());
    out.condition_number.assign(nv, 0.0);

    // Breadth-first rings, the vertex first (the fit is made at the first point); one stamp
    // array for all vertices, so gathering is linear in the neighbourhoods' size.
    std::vector<size_t> stamp(nv, static_cast<size_t>(-1));
    std::vector<Mesh::Vertex_index> ring;
    std::vector<Kernel::Point_3> points;
    for (Mesh::Vertex_index v : m.vertices()) {
        const size_t id = v;
        ring.assign(1, v);
        stamp[v] = id;
        size_t begin = 0;
        for (int r = 0; r < rings; ++r) {
            const size_t end = ring.size();
            for (size_t i = begin; i < end; ++i)
                if (m.halfedge(ring[i]) != Mesh::null_halfedge())
                    for (Mesh::Vertex_index w : CGAL::vertices_around_target(ring[i], m))
                        if (stamp[w] != id) {
                            stamp[w] = id;
                            ring.push_back(w);
                        }
            begin = end;
        }
        if (ring.size() < needed) continue;
        points.clear();
        for (Mesh::Vertex_index w : ring) points.push_back(m.point(w));
        Fitting fitting;
        Fitting::Monge_form form = fitting(points.begin(), points.end(), static_cast<size_t>(degree), 2);
        const Vec3& o = orientation[v];
        form.comply_wrt_given_normal(Kernel::Vector_3(o.x(), o.y(), o.z()));
        const auto n = form.normal_direction();
        const auto d2 = form.minimal_principal_direction();
        if (!std::isfinite(form.principal_curvatures(0)) || !std::isfinite(form.principal_curvatures(1)))
            continue;  // a degenerate neighbourhood (coplanar rings fitted by a flat jet still give 0, not this)
        out.fitted[v] = 1;
        // CGAL's k1 >= k2 bend towards +n; ours bend away from the outward normal.
        out.k1[v] = -form.principal_curvatures(1);
        out.k2[v] = -form.principal_curvatures(0);
        out.direction1[v] = Vec3(d2.x(), d2.y(), d2.z());
        out.normal[v] = Vec3(n.x(), n.y(), n.z());
        out.condition_number[v] = fitting.condition_number();
    }
    return out;
}

struct EditableMesh::Impl {
    Mesh mesh;
    Mesh::Halfedge_index halfedge(int a, int b) const {
        const auto h = mesh.halfedge(Mesh::Vertex_index(static_cast<Mesh::size_type>(a)), Mesh::Vertex_index(static_cast<Mesh::size_type>(b)));
        if (h == Mesh::null_halfedge()) throw Rejected("CGAL has no edge " + std::to_string(a) + "-" + std::to_string(b));
        return h;
    }
};

EditableMesh::EditableMesh(const TriMesh& mesh) : impl_(std::make_unique<Impl>(Impl{build(mesh)})) {}
EditableMesh::~EditableMesh() = default;
EditableMesh::EditableMesh(EditableMesh&&) noexcept = default;
EditableMesh& EditableMesh::operator=(EditableMesh&&) noexcept = default;

void EditableMesh::flip(int a, int b) {
    Mesh& m = impl_->mesh;
    const auto h = impl_->halfedge(a, b);
    // flip_edge only asserts this (and not at all in a release build): check it here.
    if (m.is_border(m.edge(h)))
        throw Rejected("CGAL edge " + std::to_string(a) + "-" + std::to_string(b) + " is a border edge; flip_edge needs two faces");
    CGAL::Euler::flip_edge(h, m);
}

int EditableMesh::split(int a, int b) {
    Mesh& m = impl_->mesh;
    const auto h = impl_->halfedge(a, b);
    const auto mid = CGAL::midpoint(m.point(m.source(h)), m.point(m.target(h)));
    // split_edge: hnew = a->m is followed by h = m->b; each side with a face is then a quad,
    // which split_face cuts from m to the vertex opposite the edge.
    const auto hnew = CGAL::Euler::split_edge(h, m);
    const auto v = m.target(hnew);
    m.point(v) = mid;
    if (!m.is_border(h)) CGAL::Euler::split_face(hnew, m.next(h), m);
    const auto ho = m.opposite(h);
    if (!m.is_border(ho)) CGAL::Euler::split_face(ho, m.next(m.opposite(hnew)), m);
    return static_cast<int>(v.idx());
}

std::vector<std::string> EditableMesh::check() const {
    std::vector<std::string> out;
    const Mesh& m = impl_->mesh;
    if (!m.is_valid(false)) out.push_back("Surface_mesh::is_valid fails");
    if (!CGAL::is_valid_polygon_mesh(m)) out.push_back("CGAL::is_valid_polygon_mesh fails");
    if (!CGAL::is_triangle_mesh(m)) out.push_back("CGAL::is_triangle_mesh fails");
    return out;
}

// Flips and splits remove nothing, so Surface_mesh order is index order.
std::vector<Triangle> EditableMesh::faces() const { return to_tri_mesh(impl_->mesh).triangles; }

std::vector<Vec3> EditableMesh::positions() const { return to_tri_mesh(impl_->mesh).positions; }

}  // namespace crossdiv::adapters::cgal
