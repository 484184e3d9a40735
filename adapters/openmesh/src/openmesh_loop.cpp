#include <OpenMesh/Core/Mesh/DefaultTriMesh.hh>  // first: the Subdivider headers rely on what it brings in
#include <OpenMesh/Core/System/config.h>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <algorithm>
#include <string>

#include "crossdiv/adapters/openmesh.h"
#include "openmesh_mesh.h"

namespace crossdiv::adapters::openmesh {
namespace {

using detail::Mesh;
using detail::snapshot;

}  // namespace

bool supports(const LoopOptions& options) {
    return options.weights == LoopWeights::Loop && options.boundary == LoopBoundary::EdgeOnly;
}

std::string version() {
    // OM_GET_MAJ masks the wrong bits for 0x90000; decode OM_VERSION (0xMMmmpp) directly.
    return "OpenMesh " + std::to_string(OM_VERSION >> 16) + "." + std::to_string((OM_VERSION >> 8) & 0xff);
}

namespace {

Mesh build(const TriMesh& mesh, const LoopOptions& options) {
    if (!supports(options))
        throw Rejected("OpenMesh's LoopT has Loop weights and the edge-only boundary rule only");
    return detail::to_openmesh(mesh);
}

/// LoopT's weight table covers valences below 50 by default and is read unchecked beyond.
void size_weights(OpenMesh::Subdivider::Uniform::LoopT<Mesh>& loop, const Mesh& m) {
    size_t max_valence = 0;
    for (auto v : m.vertices()) max_valence = std::max<size_t>(max_valence, m.valence(v));
    loop.init_weights(std::max<size_t>(50, max_valence + 1));
}

}  // namespace

LevelTrace loop(const TriMesh& mesh, const LoopOptions& options, int levels) {
    Mesh m = build(mesh, options);
    LevelTrace trace{snapshot(m, 0)};
    OpenMesh::Subdivider::Uniform::LoopT<Mesh> loop;
    for (int l = 1; l <= levels; ++l) {
        size_weights(loop, m);
        loop.attach(m);
        loop(1);
        loop.detach();
        trace.push_back(snapshot(m, l));
    }
    return trace;
}

size_t loop_native(const TriMesh& mesh, const LoopOptions& options, int levels) {
    Mesh m = build(mesh, options);
    OpenMesh::Subdivider::Uniform::LoopT<Mesh> loop;
    size_weights(loop, m);  // refinement adds only valence-6 and existing valences
    loop.attach(m);
    loop(levels);
    loop.detach();
    return m.n_faces();
}

}  // namespace crossdiv::adapters::openmesh
