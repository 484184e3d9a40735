// The second of the two translation units that include CGAL: everything on a Surface_mesh
// apart from Loop subdivision: closed-mesh checks (orientation, volume), vertex normals, and
// the Euler operations the half-edge differential tests compare with.
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
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

}  // namespace

std::vector<Vec3> vertex_normals(const TriMesh& mesh) {
    Mesh m = build(mesh);
    auto normals = m.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:crossdiv_normal", CGAL::NULL_VECTOR).first;
    CGAL::Polygon_mesh_processing::compute_vertex_normals(m, normals);
    std::vector<Vec3> out;
    out.reserve(m.number_of_vertices());
    for (Mesh::Vertex_index v : m.vertices()) out.emplace_back(normals[v].x(), normals[v].y(), normals[v].z());
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

std::vector<Triangle> EditableMesh::faces() const {
    const Mesh& m = impl_->mesh;
    std::vector<Triangle> out;
    out.reserve(m.number_of_faces());
    for (Mesh::Face_index f : m.faces()) {
        Triangle t{};
        int k = 0;
        for (Mesh::Vertex_index v : m.vertices_around_face(m.halfedge(f))) t[k++ % 3] = static_cast<int>(v.idx());
        out.push_back(t);
    }
    return out;
}

std::vector<Vec3> EditableMesh::positions() const {
    const Mesh& m = impl_->mesh;
    std::vector<Vec3> out;
    out.reserve(m.number_of_vertices());
    for (Mesh::Vertex_index v : m.vertices()) out.emplace_back(m.point(v).x(), m.point(v).y(), m.point(v).z());
    return out;
}

}  // namespace crossdiv::adapters::cgal
