#include "crossdiv/verification/bench/valence_bench.h"

#include "crossdiv/error.h"
#include "crossdiv/mesh/halfedge_validity.h"
#include "crossdiv/mesh/halfedge_mesh.h"
#include "crossdiv/mesh/mesh_checks.h"
#include "crossdiv/verification/bench/bench.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"

namespace crossdiv::verification {
namespace {

/// What `crossdiv check` computes: the mesh checks, then the half-edge mesh and its
/// invariants where the mesh is one of triangles. Returns the number of issues.
size_t check_work(const PolyMesh& mesh) {
    size_t n = check_mesh(mesh).size();
    if (!mesh.all_triangles()) return n;
    try {
        const HalfedgeMesh he = HalfedgeMesh::from_triangles(to_tri_mesh(mesh, "a half-edge mesh"));
        n += check_halfedge_mesh(he).size();
    } catch (const InputError&) {
        ++n;
    }
    return n;
}

}  // namespace

std::vector<ValenceRow> run_valence_bench(const std::vector<int>& valences, int repeats) {
    std::vector<ValenceRow> rows;
    const WarmAllocator warm;  // as the Loop rows: repeats reuse memory instead of faulting it in again
    for (const int k : valences)
        for (const datasets::ValenceShape shape : datasets::kValenceShapes) {
            const PolyMesh mesh = datasets::valence_shape(shape, k), regular = datasets::regular_counterpart(shape, k);
            // Each work returns its size (see ValenceRow::size), which also keeps it observable.
            const auto row = [&](const std::string& command, const std::function<long long(const PolyMesh&)>& work) {
                ValenceRow r{shape, k, command};
                const std::vector<double> ms = interleaved_median_ms(
                    repeats, {[&] { r.size = work(mesh); }, [&] { r.regular_size = work(regular); }});
                r.ms = ms[0];
                r.regular_ms = ms[1];
                rows.push_back(r);
            };
            row("check", [](const PolyMesh& m) {
                check_work(m);
                return static_cast<long long>(m.face_vertices.size());
            });
            for (const Scheme s : all_schemes()) {
                if (shape == datasets::ValenceShape::Polygon && traits(s).triangles) continue;
                row(to_string(s), [s](const PolyMesh& m) {
                    const PolyMesh fine = subdivide(s, {}, m, 1);
                    return static_cast<long long>(fine.num_vertices()) + fine.num_faces();
                });
            }
        }
    return rows;
}

nlohmann::json to_json(const ValenceRow& r) {
    return {{"shape", datasets::to_string(r.shape)}, {"valence", r.valence}, {"command", r.command},
            {"size", r.size}, {"regular_size", r.regular_size}, {"ms", r.ms},
            {"regular_ms", r.regular_ms}, {"ratio", r.ratio()}};
}

}  // namespace crossdiv::verification
