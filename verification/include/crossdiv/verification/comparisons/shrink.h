#pragma once
/// @file
/// Shrinking a disagreement to a small mesh that still shows it, for every scheme: the
/// neighbourhood of the worst vertex (the smallest k-ring of its coarse ancestors that still shows the symptom),
/// then delta debugging over faces (Zeller and Hildebrandt, "Simplifying and Isolating
/// Failure-Inducing Input", IEEE TSE 2002: ddmin, removing complements) while the symptom
/// persists unchanged.
///
/// The symptom is read off the comparison of the whole input: a reference that diverges from
/// the implementation under test (core, or a subject in core's place) keeps its divergence
/// class; a reference or subject that fails keeps its way of failing (crash, wrong count,
/// invalid mesh, ...; a subject's timeout too); a subject compared with no reference keeps
/// following no named rule.

#include <string>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/comparisons/loop_comparison.h"
#include "crossdiv/verification/comparisons/scheme_comparison.h"

namespace crossdiv::verification {

/// What must persist while faces are removed.
struct ShrinkSymptom {
    enum class Kind {
        ReferenceDiverges,     ///< the one reference diverges with `divergence_class`
        ReferenceFails,        ///< the one reference's run ends with `status` (not a refusal or a timeout)
        SubjectFails,          ///< the subject's run ends with `status`
        SubjectUnmatched,      ///< the subject's vertices match none of core's
        SubjectFollowsNoRule,  ///< no named rule fits the subject's refinement
    };
    Kind kind = Kind::ReferenceDiverges;
    DivergenceClass divergence_class = DivergenceClass::None;
    RunStatus status = RunStatus::Ok;  ///< how the run fails, for the *Fails kinds
    bool operator==(const ShrinkSymptom&) const = default;
};
/// "opensubdiv diverges from core (corner-rule)", "openmesh fails (unreadable-output)",
/// "the subject fails (crashed)", "no named rule fits the subject".
std::string describe(const ShrinkSymptom& symptom, const std::string& subject, const std::string& reference);

/// The symptom of a comparison, when it has one.
std::optional<ShrinkSymptom> symptom_of(const LoopComparison& comparison);
/// The symptom of a polygon scheme's comparison with one reference, when it has one (core
/// refines the input, and the reference diverges or fails).
std::optional<ShrinkSymptom> symptom_of(const SchemeComparison& comparison);

struct ShrinkResult {
    LoopComparison original;  ///< the comparison on the whole input
    ShrinkSymptom symptom;    ///< what must persist
    int k = 0;                ///< ring size of the neighbourhood (0: the whole mesh was needed)
    TriMesh neighbourhood;    ///< faces within k rings of the worst vertex's coarse ancestors
    TriMesh minimal;          ///< after delta debugging
    LoopComparison minimal_comparison;
    int tests = 0;  ///< comparisons run while shrinking
};

/// @param request at most one reference; none only with a subject (whose failure or lack of a
///        named rule is then shrunk). @throws InputError if the comparison of the input shows
///        no symptom (nothing to shrink), or for bad input.
ShrinkResult shrink_divergence(const TriMesh& mesh, const std::string& name, const LoopComparisonRequest& request);

/// A divergence or failure of one reference under a polygon scheme (Catmull-Clark, Doo-Sabin,
/// sqrt3, the Butterflies), shrunk as a Loop divergence is: the smallest k-ring that still
/// shows it around the coarse vertex nearest the worst refined vertex, then ddmin over its
/// polygons, while the reference keeps diverging with the same class or failing the same way.
struct SchemeShrinkResult {
    SchemeComparison original;  ///< the comparison on the whole input
    ShrinkSymptom symptom;      ///< what must persist
    int k = 0;                  ///< ring size of the neighbourhood (0: the whole mesh was needed)
    PolyMesh neighbourhood;     ///< faces within k rings of the seed
    PolyMesh minimal;           ///< after delta debugging
    SchemeComparison minimal_comparison;
    int tests = 0;  ///< comparisons run while shrinking
};

/// @param request exactly one reference. @throws InputError if that reference neither
///        diverges nor fails on the input (nothing to shrink), or for bad input.
SchemeShrinkResult shrink_scheme_divergence(const PolyMesh& mesh, const std::string& name, const SchemeRequest& request);

/// The faces of `mesh` listed in `faces`, with unused vertices dropped (order kept).
TriMesh submesh(const TriMesh& mesh, const std::vector<int>& faces);

/// The polygons of `mesh` listed in `faces`, with unused vertices dropped (order kept); the
/// crease and corner tags of the kept vertices, the holes among the kept faces and the
/// file's scheme options come along.
PolyMesh submesh(const PolyMesh& mesh, const std::vector<int>& faces);

}  // namespace crossdiv::verification
