// OpenMesh as the reference for vertex normals and for the local operations flip and split.
#include <OpenMesh/Tools/Utils/MeshCheckerT.hh>

#include <sstream>

#include "crossdiv/adapters/openmesh.h"
#include "openmesh_mesh.h"

namespace crossdiv::adapters::openmesh {

using detail::Mesh;

std::vector<Vec3> vertex_normals(const TriMesh& mesh, NormalMethod method) {
    Mesh m = detail::to_openmesh(mesh);
    std::vector<Vec3> out;
    out.reserve(m.n_vertices());
    if (method == NormalMethod::Correct) {
        for (auto v : m.vertices()) {
            Mesh::Normal n;
            m.calc_vertex_normal_correct(v, n);
            out.emplace_back(n[0], n[1], n[2]);
        }
        return out;
    }
    m.request_face_normals();
    m.request_vertex_normals();
    m.update_face_normals();
    m.update_vertex_normals();
    for (auto v : m.vertices()) {
        const auto& n = m.normal(v);
        out.emplace_back(n[0], n[1], n[2]);
    }
    return out;
}

struct EditableMesh::Impl {
    Mesh mesh;
    Mesh::EdgeHandle edge(int a, int b) const {
        const auto h = mesh.find_halfedge(mesh.vertex_handle(static_cast<unsigned>(a)), mesh.vertex_handle(static_cast<unsigned>(b)));
        if (!h.is_valid()) throw Rejected("OpenMesh has no edge " + std::to_string(a) + "-" + std::to_string(b));
        return mesh.edge_handle(h);
    }
};

EditableMesh::EditableMesh(const TriMesh& mesh) : impl_(std::make_unique<Impl>(Impl{detail::to_openmesh(mesh)})) {}
EditableMesh::~EditableMesh() = default;
EditableMesh::EditableMesh(EditableMesh&&) noexcept = default;
EditableMesh& EditableMesh::operator=(EditableMesh&&) noexcept = default;

bool EditableMesh::flip_ok(int a, int b) const { return impl_->mesh.is_flip_ok(impl_->edge(a, b)); }

void EditableMesh::flip(int a, int b) { impl_->mesh.flip(impl_->edge(a, b)); }

int EditableMesh::split(int a, int b) {
    Mesh& m = impl_->mesh;
    const auto e = impl_->edge(a, b);
    const Mesh::Point mid = 0.5 * (m.point(m.vertex_handle(static_cast<unsigned>(a))) + m.point(m.vertex_handle(static_cast<unsigned>(b))));
    return m.split(e, mid).idx();
}

std::vector<std::string> EditableMesh::check() const {
    std::ostringstream report;
    OpenMesh::Utils::MeshCheckerT<Mesh> checker(impl_->mesh);
    std::vector<std::string> lines;
    if (checker.check(OpenMesh::Utils::MeshCheckerT<Mesh>::CHECK_ALL, report)) return lines;
    std::istringstream in(report.str());
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    if (lines.empty()) lines.push_back("MeshCheckerT failed without a message");
    return lines;
}

std::vector<Triangle> EditableMesh::faces() const {
    std::vector<Triangle> out;
    out.reserve(impl_->mesh.n_faces());
    for (auto f : impl_->mesh.faces()) {
        Triangle t{};
        int k = 0;
        for (auto v : impl_->mesh.fv_range(f)) t[k++ % 3] = v.idx();
        out.push_back(t);
    }
    return out;
}

std::vector<Vec3> EditableMesh::positions() const {
    std::vector<Vec3> out;
    out.reserve(impl_->mesh.n_vertices());
    for (auto v : impl_->mesh.vertices()) {
        const auto& p = impl_->mesh.point(v);
        out.emplace_back(p[0], p[1], p[2]);
    }
    return out;
}

}  // namespace crossdiv::adapters::openmesh
