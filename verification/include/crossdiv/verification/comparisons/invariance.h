#pragma once
/// @file
/// Invariance (metamorphic) testing: an implementation refines an input and the same input
/// written otherwise (input_transformation.h); mapped back, the two refinements must be the
/// same surface. No reference is needed: what is checked is that the implementation's answer
/// depends on the mesh and not on how it was written -- where every reference shares a blind
/// spot (a bug that shows only when an extraordinary vertex is a face's third corner), or in a
/// reference itself.
///
/// The refinement of the input is mapped as the input was (positions through the
/// transformation's affine map, faces reversed for reverse-orientation) and matched to the
/// refinement of the transformed input vertex by vertex through positions and faces
/// (correspondence.h). It is `invariant` when the faces are the same and the positions agree
/// bit for bit where floating point makes the transformation exact (scale, swap-axes, mirror,
/// repeat), within the tolerance elsewhere (summation order, rounding); `nondeterministic` when
/// the same input run again differs; else `not-invariant`, with the worst vertex. An input the
/// implementation refuses is `not-compared` (a refusal of the input written otherwise, when the
/// input itself is taken, is `not-invariant`), as is a refinement with vertices at one position
/// whose positions all agree but whose faces positions cannot match.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/verification/comparisons/divergence_view.h"
#include "crossdiv/verification/comparisons/input_transformation.h"
#include "crossdiv/verification/comparisons/shrink.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/harness/verdict.h"
#include "crossdiv/verification/implementations/implementation.h"

namespace crossdiv::verification {

enum class InvarianceResult {
    Invariant,
    NotInvariant,
    Nondeterministic,  ///< the same input, run again, refined otherwise
    /// The implementation refused (or failed on) the input itself, or the refinement has
    /// vertices at one position, whose faces positions cannot match: nothing is said either way.
    NotCompared,
};
/// "invariant", "not-invariant", "nondeterministic", "not-compared".
const char* to_string(InvarianceResult r);

/// One implementation under one transformation of one input.
struct InvarianceCheck {
    InputTransformation transformation = InputTransformation::Repeat;
    InvarianceResult result = InvarianceResult::NotCompared;
    bool exact = false;          ///< bit-identical results expected (TransformedInput::exact)
    bool faces_equal = false;    ///< the same faces, as oriented faces up to rotation
    bool bit_identical = false;  ///< faces equal and every matched position equal bit for bit
    /// Compared as point sets (Hausdorff distance): the refinement has vertices at one position,
    /// which positions cannot tell apart, so its faces were not compared.
    bool point_sets = false;
    /// The positions (and faces) invariant, the texture coordinates not.
    bool uv_only = false;
    double max_rel = NAN;        ///< largest matched distance over the diagonal
    /// With texture coordinates on both sides: the largest corner difference over the UV box
    /// (bit for bit expected where the transformation is exact; no map moves them).
    double uv_max_rel = NAN;
    /// The worst vertex, in the numbering of the refinement of the untransformed input.
    int worst_vertex = -1;
    int worst_valence = 0;
    bool worst_boundary = false;
    std::string explanation;  ///< one sentence with the figures

    /// Not invariant, or nondeterministic: what is reported, shrunk and explained.
    bool finding() const { return result == InvarianceResult::NotInvariant || result == InvarianceResult::Nondeterministic; }
};

/// The check's fields as the CLI's --json, the suite's runs and the Python module write them:
/// transformation, result, exact, bit_identical, faces_equal, max_rel, uv_max_rel (null when not
/// measured), the worst vertex, the explanation.
nlohmann::json to_json(const InvarianceCheck& check);

/// Compares `refined` (the last level of the input's refinement) with `refined_transformed`
/// (of `transformed.mesh`'s) as the transformation says they relate. `float_ulps`: for an
/// implementation that computes in float, the float tier's bound B on each run's rounding
/// (tolerances::kFloatAgreementUlps + (n + 2) / 2 * L float ulps of the largest coordinate);
/// two runs then part by up to 2B, the bar where the transformation is not exact.
InvarianceCheck measure_invariance(const PolyMesh& refined, const PolyMesh& refined_transformed,
                                   const TransformedInput& transformed, double tolerance, double float_ulps = 0);

/// What an implementation did under every transformation asked for.
struct InvarianceReport {
    std::string implementation;
    RunOutcome outcome;  ///< its run on the untransformed input
    std::vector<InvarianceCheck> checks;
    /// No check not-invariant or nondeterministic (a check not compared says nothing).
    bool invariant() const;
};

/// Runs `impl` on `input` and on each transformation of it (drawn from `seed`), `request.levels`
/// levels, each run isolated as refinements are (refine_isolated: a crash or a hang is an
/// outcome), and measures each.
InvarianceReport check_invariance(const Implementation& impl, const PolyMesh& input, const RefineRequest& request,
                                  const std::vector<InputTransformation>& transformations, std::uint64_t seed,
                                  double tolerance, double timeout_seconds, bool isolate = true);

/// Why an implementation is not invariant (or not deterministic) on an input, by measurement:
/// the check is run again on the input without what one input handling concerns, each removal
/// kept for the next (a model may have vertices no face uses and a bowtie, both mishandled), and
/// the class is the removal that makes it invariant; the why names the removals before it.
/// A finding made on point sets (InvarianceCheck::point_sets) is gone when a removal leaves
/// the same points, compared as it was.
///   isolated-vertex-handling   invariant once the vertices no face uses are removed
///   non-manifold-handling      invariant once each non-manifold vertex is split into its fans
///   face-order-dependence      invariant once each texture coordinate that is a bowtie at a
///                              vertex (its faces alternating with another value's) is split,
///                              one per fan: which fan keeps the value is read off the face order; or, where only the
///                              texture coordinates differ, invariant once the mesh is cut along
///                              its UV seams (a vertex copied per value its corners hold): the
///                              values along a seam are read off the face order
///   valence-limit              the input has a vertex past the weight table the implementation
///                              declares (SchemeSupport::max_valence): what it reads there is undefined
///   degenerate-face-handling   its refinement of the input has a face with fewer than 3 distinct
///                              corners, whose orientation and position no rule fixes
///   unexplained                none of these
/// The class is what a reference's finding is recorded as; a finding of core's or a subject's is
/// a failure whatever it measures (the caller records it unexplained, the cause in its words).
struct InvarianceCause {
    DivergenceClass cls = DivergenceClass::Unexplained;
    std::string why;  ///< the measurement, one clause
};

/// The cause of `finding` (a not-invariant or nondeterministic check of check_invariance's
/// arguments): at most four more checks under the same transformation and one run.
InvarianceCause explain_not_invariant(const Implementation& impl, const PolyMesh& input, const RefineRequest& request,
                                      const InvarianceCheck& finding, std::uint64_t seed, double tolerance,
                                      double timeout_seconds, bool isolate = true);

/// The causes of several findings of one implementation on one input (check_invariance's
/// checks), in their order, as explain_not_invariant gives each: every removal is checked once
/// for all the findings it has not explained yet (one run of the input without it, one per
/// transformation), and the closing run once, rather than each once per finding.
std::vector<InvarianceCause> explain_findings(const Implementation& impl, const PolyMesh& input, const RefineRequest& request,
                                              const std::vector<InvarianceCheck>& findings, std::uint64_t seed,
                                              double tolerance, double timeout_seconds, bool isolate = true);

/// Each check of `report` (check_invariance's on `input`) with its cause where it is a finding,
/// by explain_findings over all of them.
std::vector<std::optional<InvarianceCause>> causes_of(const Implementation& impl, const PolyMesh& input,
                                                      const RefineRequest& request, const InvarianceReport& report,
                                                      std::uint64_t seed, double tolerance, double timeout_seconds,
                                                      bool isolate = true);

/// A finding drawn for the report's 3D viewer: the implementation's levels on the input, and as
/// its one "reference", named invariance_view_label, its last level on the input written
/// otherwise, mapped back into the first run's numbering (positions through the inverse of the
/// transformation's map, vertices matched as measure_invariance matches them). Nothing when
/// either run fails or the two last levels do not match vertex for vertex.
std::optional<DivergenceView> invariance_view(const Implementation& impl, const PolyMesh& input, const RefineRequest& request,
                                            InputTransformation t, std::uint64_t seed, double timeout_seconds,
                                            bool isolate = true);
/// "cgal under reverse-faces": the reference name of an invariance view.
std::string invariance_view_label(const std::string& implementation, InputTransformation t);

/// A non-invariant input shrunk: the fewest faces found by delta debugging over faces (ddmin:
/// Zeller and Hildebrandt 2002, as comparisons/shrink.h) on which the implementation is still
/// not invariant (nondeterministic, for repeat) under the same transformation.
struct InvarianceShrink {
    PolyMesh minimal;
    int tests = 0;  ///< invariance checks run while shrinking
    InvarianceCheck check;  ///< the check on the minimal input
    /// The time limit ended the shrinking before every face was tried: `minimal` still shows
    /// the finding, but removing one more face might not make it go away.
    bool cut_short = false;
};

/// Shrinks `input`, on which `impl` is not invariant under `t` (check_invariance's arguments),
/// within `limits` (as shrink_divergence: past it the smallest input found so far).
/// @throws InputError when the check on `input` itself shows nothing to shrink.
InvarianceShrink shrink_not_invariant(const Implementation& impl, const PolyMesh& input, const RefineRequest& request,
                                      InputTransformation t, std::uint64_t seed, double tolerance, double timeout_seconds,
                                      bool isolate = true, const ShrinkLimits& limits = {});

}  // namespace crossdiv::verification
