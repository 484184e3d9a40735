#pragma once
/// @file
/// What the harness concludes about one implementation run against another: the verdict and,
/// for a divergence or a refusal of ours, its class. Typed throughout the harness; turned
/// into the strings of results.json, results.csv and JUnit only at the output edge
/// (to_string), and parsed back from them by from_string when a results file is merged.

#include <optional>
#include <string>
#include <string_view>

namespace crossdiv::verification {

/// The verdict on one run.
enum class Verdict {
    Agree,         ///< within the tier's tolerance at every level compared
    Diverge,       ///< outside it; the DivergenceClass says why, by measurement
    RefRejected,   ///< the reference refused the input or the rule (adapters::Rejected)
    RefCrashed,    ///< the reference crashed, threw, hung or ended without a result
    RefInvalidOutput,  ///< the reference's result is not a mesh of the scheme (unreadable, NaN, wrong counts)
    RefUnavailable,    ///< the reference is not on this machine (an external program whose setup failed)
    OursRejected,  ///< core refused the input (the class names the input handling)
    /// The reference's result changed when it ran again on the same input with its heap filled
    /// otherwise (comparisons/nondeterminism.h): it reads memory it never wrote. The class is the
    /// first run's divergence, if it diverged; not a failure of core's, as no verdict on core can
    /// be read off a result that changes.
    RefNondeterministic,
    /// Nothing was compared: an invariance check whose refinement has vertices at one position,
    /// whose faces positions cannot match, and whose point sets agree (comparisons/invariance.h);
    /// or a float reference where a float cannot tell core's vertices apart (far from the
    /// origin), so none of its vertices can be matched. Neither agreement nor a divergence.
    NotCompared,
};

/// "agree", "diverge", "ref-rejected", "ref-crashed", "ref-invalid-output", "ref-unavailable",
/// "ours-rejected", "ref-nondeterministic", "not-compared".
const char* to_string(Verdict verdict);
/// @throws InputError naming the unknown verdict and the known ones.
Verdict verdict_from_string(std::string_view name);

/// Why two implementations differ, each class established by a measurement (see
/// comparisons/classification.h for the ladder that assigns them).
enum class DivergenceClass {
    None,  ///< no divergence (agreement, or a failure that is not a divergence)
    // A rule the reference applies, shown by re-running core with it:
    /// The weights inside: Loop's family (Loop's, Warren's, ...), Catmull-Clark's interior
    /// vertex rule (the literature's variants), Doo-Sabin's corner weights (Doo and Sabin's or
    /// Catmull and Clark's)
    WeightFamily,
    CornerRule,                ///< the reference lacks the corner rule (edge-only boundary)
    WeightFamilyAndCornerRule, ///< both of the above
    BoundaryRule,              ///< another boundary rule (OpenMesh's Catmull-Clark midpoint average)
    BorderFacesDropped,        ///< Doo-Sabin: the faces of border edges and vertices are dropped
    Parity,                    ///< sqrt3: the boundary generations are counted per call
    WingRule,                  ///< Butterfly: another stand-in for a wing point beyond the boundary
    TriangleRule,              ///< Catmull-Clark: OpenSubdiv's smooth-triangle edge weights, or not
    /// Loop, Catmull-Clark: other semi-sharp crease rules (Hbr's, crossdiv::CreaseRules: a
    /// sharpness of exactly 1 stays sharp a step longer; Chaikin's decay of its own)
    CreaseRules,
    /// Face-varying values (texture coordinates) refined under another of OpenSubdiv's six
    /// linear-interpolation rules than the one asked for
    FaceVaryingRule,
    /// Face-varying values refined by Hbr's rules, OpenSubdiv 2's and RenderMan's, which Far
    /// corrected (crossdiv::FaceVaryingOptions::rules: a sharp edge a face-varying boundary for
    /// good, the dart's boundary rule, no fractional sharpness)
    LegacyFaceVaryingRules,
    NormalRule,                ///< vertex normals by a rule that is none of our weightings (CGAL's most visible normal)
    /// A course task's subject follows another named convention than core's (a curve's
    /// basis, t read as 1 - t, a normal weighting, a cylinder's frames)
    Convention,
    // Something else measured:
    /// The reference's result changes when the input's faces are listed in another order
    /// (reversed, or rotated by half), the mesh unchanged: it depends on how the input is
    /// written, where core's does not (OpenSubdiv's face-varying values at a UV bowtie)
    FaceOrderDependence,
    Rounding,                  ///< same faces, within tolerances::kRoundingUlps of the coordinates
    IsolatedVertexHandling,    ///< only vertices without faces differ
    ValenceLimit,              ///< the reference's weight table ends below the input's valence
    /// The Butterflies: only boundary edges on boundary loops of three edges differ, where the
    /// four-point rule's two outer points are the loop's third vertex (VTK reads another point)
    ShortBoundaryLoop,
    /// OpenSubdiv: only vertices where the non-manifold vertices that Far's walk takes for
    /// manifold ones reach differ (opensubdiv_walk_accepted_vertices, subdiv/nonmanifold.h):
    /// a face names the vertex twice, not in a row, and Far refines it by a ring with an edge
    /// taken twice, where core keeps it
    FanWalk,
    Topology,                  ///< the refined connectivity differs
    Triangulation,             ///< the same vertices and topology, other triangles over them (isosurface polygons)
    Unexplained,               ///< none of the above: a failure
    // For OursRejected, the input handling the reference shows; NonManifoldHandling also for
    // a divergence confined to where the non-manifold vertices reach, when core refined them
    // by OpenSubdiv's rules (nonmanifold.h):
    NonManifoldHandling,
    OrientationHandling,
    DegenerateFaceHandling,
    InvalidInputHandling,
};

/// "" for None, else the class's name in results.json ("weight-family", "corner-rule",
/// "weight-family+corner-rule", "boundary-rule", "border-faces-dropped", "parity", "wing-rule", "triangle-rule",
/// "fvar-rule", "legacy-fvar-rules", "normal-rule",
/// "convention", "face-order-dependence", "rounding",
/// "isolated-vertex-handling", "valence-limit", "short-boundary-loop", "fan-walk", "topology", "triangulation",
/// "unexplained", "non-manifold-handling", "orientation-handling", "degenerate-face-handling",
/// "invalid-input-handling").
const char* to_string(DivergenceClass cls);
/// "" gives None. @throws InputError naming the unknown class and the known ones.
DivergenceClass divergence_class_from_string(std::string_view name);

/// A verdict with its class: the outcome of one run as the summary counts it.
struct Outcome {
    Verdict verdict = Verdict::Agree;
    DivergenceClass cls = DivergenceClass::None;

    /// Counted as a failure (JUnit, exit status): an unexplained divergence, and a refusal by
    /// core of an input a reference refines that its case does not declare expected.
    bool is_failure() const {
        return (verdict == Verdict::Diverge || verdict == Verdict::OursRejected) && cls == DivergenceClass::Unexplained;
    }
    friend bool operator==(const Outcome&, const Outcome&) = default;
};

/// "agree", "diverge (<class>)", "ref-rejected", "ref-crashed", "ours-rejected (<class>)",
/// "ref-nondeterministic (<class>)"; a verdict without a class is the bare verdict.
std::string to_string(const Outcome& outcome);

}  // namespace crossdiv::verification
