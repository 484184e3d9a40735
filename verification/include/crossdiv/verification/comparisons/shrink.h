#pragma once
/// @file
/// Shrinking a disagreement to a small mesh that still shows it, for every scheme: the
/// neighbourhood of the worst vertex (the smallest k-ring of its coarse ancestors that still shows the symptom),
/// then delta debugging over faces (Zeller and Hildebrandt, "Simplifying and Isolating
/// Failure-Inducing Input", IEEE TSE 2002: ddmin, removing complements), then over the
/// vertices no face uses, while the symptom persists unchanged.
///
/// The symptom is read off the comparison of the whole input: a reference that diverges from
/// the implementation under test (core, or a subject in core's place) keeps its divergence
/// class; a reference or subject that fails keeps its way of failing (crash, wrong count,
/// invalid mesh, ...; a subject's timeout too); a subject compared with no reference keeps
/// following no named rule.

#include <limits>
#include <string>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"

namespace crossdiv::verification {

/// What must persist while faces are removed.
struct ShrinkSymptom {
    enum class Kind {
        ReferenceDiverges,     ///< the one reference diverges with `divergence_class`
        ReferenceFails,        ///< the one reference's run ends with `status` (not a refusal or a timeout)
        SubjectFails,          ///< the subject's run ends with `status`
        SubjectUnmatched,      ///< the subject's vertices match none of core's
        SubjectTopology,       ///< the subject's vertices match core's, its faces do not
        SubjectFollowsNoRule,  ///< no named rule fits the subject's refinement
        /// the one reference agrees in positions and its texture coordinates diverge with
        /// `divergence_class` (RefinementRun::uv)
        ReferenceUvDiverges,
    };
    Kind kind = Kind::ReferenceDiverges;
    DivergenceClass divergence_class = DivergenceClass::None;
    RunStatus status = RunStatus::Ok;  ///< how the run fails, for the *Fails kinds
    bool operator==(const ShrinkSymptom&) const = default;
};
/// "opensubdiv diverges from core (corner-rule)", "openmesh fails (unreadable-output)",
/// "the subject fails (crashed)", "no named rule fits the subject", "opensubdiv's texture
/// coordinates diverge from core's (face-order-dependence)".
std::string describe(const ShrinkSymptom& symptom, const std::string& subject, const std::string& reference);

/// The one-line explanation of a comparison's first run: its texture coordinates' when they
/// are what diverges, else its positions'; "" without a run.
std::string symptom_explanation(const RefinementComparison& comparison);

/// The symptom of a comparison, when it has one: core refines the input, and the subject
/// fails or follows no named rule, or the one reference diverges or fails.
std::optional<ShrinkSymptom> symptom_of(const RefinementComparison& comparison);

struct ShrinkResult {
    RefinementComparison original;  ///< the comparison on the whole input
    ShrinkSymptom symptom;          ///< what must persist
    int k = 0;                      ///< ring size of the neighbourhood (0: the whole mesh was needed)
    PolyMesh neighbourhood;         ///< faces within k rings of the symptom's coarse vertices
    PolyMesh minimal;               ///< after delta debugging
    /// The levels the shrinking refined at: the fewest at which the whole input shows the
    /// symptom (at most the request's); `minimal_comparison` and the reproduce line use them.
    int levels = 0;
    RefinementComparison minimal_comparison;
    int tests = 0;  ///< comparisons run while shrinking
    /// The time limit ended the shrinking before every face was tried: `minimal` still shows
    /// the symptom, but removing one more face might not make it go away.
    bool cut_short = false;
};

/// How long shrinking may take: past it no further candidate is tried (a candidate running
/// then finishes, under the request's own time limit) and the smallest mesh found so far that
/// shows the symptom is the result.
struct ShrinkLimits {
    double seconds = std::numeric_limits<double>::infinity();
};

/// Shrinks the symptom of the comparison of `mesh` under any scheme, at the fewest levels (up
/// to the request's) at which the whole input shows it (ShrinkResult::levels). The neighbourhood's
/// seeds are the coarse ancestors of the vertex where the symptom shows, where core's
/// refinement carries provenance (Loop), else the coarse vertex nearest it.
/// @param request at most one reference; none only with a subject (whose failure or lack of a
///        named rule is then shrunk). @throws InputError if the comparison of the input shows
///        no symptom (nothing to shrink), core refuses it, or for bad input.
ShrinkResult shrink_divergence(const PolyMesh& mesh, const std::string& name, const RefinementRequest& request,
                               const ShrinkLimits& limits = {});

/// The polygons of `mesh` listed in `faces`, with unused vertices dropped (order kept) but for
/// `also_vertices`, kept though no kept face uses them; the crease and corner tags of the kept
/// vertices, the holes among the kept faces, the hierarchical edits of the kept faces
/// (renumbered), the face-varying values their corners use (renumbered, order kept) and the
/// file's scheme options come along.
PolyMesh submesh(const PolyMesh& mesh, const std::vector<int>& faces, const std::vector<int>& also_vertices = {});

}  // namespace crossdiv::verification
