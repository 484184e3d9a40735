#include "crossdiv/verification/implementations/isolated_calls.h"

namespace crossdiv::verification {
namespace {

using detail::get;
using detail::get_vector;
using detail::put;
using detail::put_vector;

void write_curvatures(FILE* f, const PrincipalCurvatures& c) {
    put_vector(f, std::vector<char>(c.method.begin(), c.method.end()));
    put_vector(f, c.estimated);
    for (const std::vector<double>* v : {&c.k1, &c.k2, &c.mean, &c.gaussian}) put_vector(f, *v);
    put_vector(f, c.direction1);
}

bool read_curvatures(FILE* f, PrincipalCurvatures& c) {
    std::vector<char> method;
    if (!get_vector(f, method) || !get_vector(f, c.estimated)) return false;
    c.method.assign(method.begin(), method.end());
    for (std::vector<double>* v : {&c.k1, &c.k2, &c.mean, &c.gaussian})
        if (!get_vector(f, *v)) return false;
    return get_vector(f, c.direction1);
}

void write_number(FILE* f, const double& x) { put(f, x); }
bool read_number(FILE* f, double& x) { return get(f, x); }

void write_mesh(FILE* f, const TriMesh& m) {
    put_vector(f, m.positions);
    put_vector(f, m.triangles);
}
bool read_mesh(FILE* f, TriMesh& m) { return get_vector(f, m.positions) && get_vector(f, m.triangles); }

bool isolates(const Implementation& impl) { return impl.kind() != ImplementationKind::Core && !impl.confines_itself(); }

}  // namespace

IsolatedValue<PrincipalCurvatures> curvatures_isolated(const Implementation& impl, const TriMesh& mesh, double timeout_seconds) {
    return run_isolated_value<PrincipalCurvatures>([&] { return impl.curvatures(mesh); }, write_curvatures, read_curvatures,
                                                   timeout_seconds, isolates(impl));
}

IsolatedValue<double> hausdorff_isolated(const Implementation& impl, const TriMesh& a, const TriMesh& b, double timeout_seconds) {
    return run_isolated_value<double>([&] { return impl.hausdorff_distance(a, b); }, write_number, read_number, timeout_seconds,
                                      isolates(impl));
}

IsolatedValue<TriMesh> simplify_isolated(const Implementation& impl, const TriMesh& mesh, int edges, double timeout_seconds) {
    return run_isolated_value<TriMesh>([&] { return impl.simplify(mesh, edges); }, write_mesh, read_mesh, timeout_seconds,
                                       isolates(impl));
}

}  // namespace crossdiv::verification
