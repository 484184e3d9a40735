#pragma once
// The factories of the library implementations. Each is compiled only when its adapter is
// built (verification/CMakeLists.txt), and called only from registry.cpp, the one place that
// asks which adapters this binary has.

#include <memory>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/adapters/reference.h"
#include "crossdiv/verification/implementations/implementation.h"

namespace crossdiv::verification::detail {

std::unique_ptr<Implementation> make_core_implementation();
std::unique_ptr<Implementation> make_opensubdiv_implementation();
std::vector<std::unique_ptr<Implementation>> make_openmesh_implementations();
std::vector<std::unique_ptr<Implementation>> make_cgal_implementations();
std::unique_ptr<Implementation> make_vtk_implementation();
std::unique_ptr<Implementation> make_hbr_implementation();
std::unique_ptr<Implementation> make_eigen_implementation();
std::unique_ptr<Implementation> make_skimage_implementation();

/// The scheme support of one rule list, for the declarations below.
inline SchemeSupport supports(Scheme scheme, std::vector<SchemeRule> rules, bool creases = false, int max_valence = 0,
                              std::string valence_table = {}) {
    return {scheme, std::move(rules), creases, max_valence, std::move(valence_table), false};
}

/// `s` with hierarchical edits (Catmull-Clark in core and Hbr).
inline SchemeSupport with_hierarchical_edits(SchemeSupport s) {
    s.hierarchical_edits = true;
    return s;
}

/// `s` with face-varying channels refined too.
inline SchemeSupport with_face_varying(SchemeSupport s) {
    s.face_varying = true;
    return s;
}

/// A rule of `scheme` given by its variant alone.
inline SchemeRule loop_rule(LoopWeights w, LoopBoundary b) {
    SchemeRule r;
    r.loop = {w, b};
    return r;
}
inline SchemeRule catmull_clark_rule(CatmullClarkBoundary b, bool smooth_triangles = false,
                                     CatmullClarkVertexRule vertex = CatmullClarkVertexRule::Standard) {
    SchemeRule r;
    r.catmull_clark.boundary = b;
    r.catmull_clark.smooth_triangles = smooth_triangles;
    r.catmull_clark.vertex = vertex;
    return r;
}
inline SchemeRule doo_sabin_rule(DooSabinBoundary b, DooSabinWeights w = DooSabinWeights::DooSabin) {
    SchemeRule r;
    r.doo_sabin = {b, w};
    return r;
}
inline SchemeRule sqrt3_rule(Sqrt3Parity p) {
    SchemeRule r;
    r.sqrt3 = {p};
    return r;
}
inline SchemeRule butterfly_rule(ButterflyWings w) {
    SchemeRule r;
    r.butterfly_wings = w;
    return r;
}

/// A library's editable mesh (the adapters' EditableMesh classes) as an edit session.
/// `AnswersFlipOk`: whether the library can say if it would flip an edge (OpenMesh's
/// is_flip_ok); where it cannot (CGAL), flipping a refused edge is a broken precondition.
template <class Editable, bool AnswersFlipOk>
class LibraryEditSession final : public EditSession {
public:
    explicit LibraryEditSession(const TriMesh& base) : mesh_(base) {}
    std::optional<bool> flip_ok([[maybe_unused]] int a, [[maybe_unused]] int b) const override {
        if constexpr (AnswersFlipOk) return mesh_.flip_ok(a, b);
        else return std::nullopt;
    }
    void flip(int a, int b) override { mesh_.flip(a, b); }
    int split(int a, int b) override { return mesh_.split(a, b); }
    std::vector<std::string> check() const override { return mesh_.check(); }
    std::vector<Triangle> faces() const override { return mesh_.faces(); }
    std::vector<Vec3> positions() const override { return mesh_.positions(); }

private:
    Editable mesh_;
};

/// The triangle schemes' adapters take a TriMesh; a polygon is the library's refusal.
inline TriMesh triangles_for(const PolyMesh& mesh, Scheme scheme) {
    try {
        return to_tri_mesh(mesh, to_string(scheme));
    } catch (const InputError& e) {
        throw adapters::Rejected(e.what());
    }
}

}  // namespace crossdiv::verification::detail
