#pragma once
/// @file
/// Limit positions and normals of core against OpenSubdiv's PrimvarRefiner::Limit, and the
/// convergence of refined vertices to their limit; plus the spectrum of the local subdivision
/// matrices (eigen-analysis of limit behaviour).

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/verification/harness/corner_values.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/catmull_clark_mask.h"
#include "crossdiv/subdiv/loop_mask.h"
#include "crossdiv/verification/harness/verdict.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/implementations/scheme.h"

namespace crossdiv::verification {

struct LimitComparison {
    std::string input;
    Scheme scheme = Scheme::Loop;
    std::string rule;  ///< rule_name of the request
    int levels = 0;
    int vertices = 0;             ///< of the level whose limit is taken
    std::string core_error;       ///< core refused (the message)
    RunOutcome outcome;           ///< OpenSubdiv's run
    Verdict verdict = Verdict::Agree;          ///< "agree", "diverge", "ref-rejected", "ref-crashed", "ours-rejected"
    double max_rel_position = NAN;  ///< over every vertex, relative to the diagonal
    int normals_compared = 0;       ///< interior vertices (core computes no boundary normal)
    double max_normal_angle = NAN;  ///< radians, over those
    /// The limit texture coordinates, corner by corner, when the request refines them
    /// (RefineRequest::face_varying) and the input has them.
    std::optional<CornerValueComparison> uv = std::nullopt;
    std::string explanation;
};

/// Loop or Catmull-Clark: `request.levels` levels of core then core's limit masks (through
/// core's implementation), against OpenSubdiv with the same levels and Limit(). Vertices
/// matched by nearest position (the levels agree to rounding).
LimitComparison compare_limit(const PolyMesh& input, const std::string& name, const RefineRequest& request,
                              bool isolate = true);

/// The same comparison for limit points core computed some other way (`ours`: the level's
/// mesh in core's vertex order, a position per vertex, and a normal per vertex, NaN where none
/// is compared), or for core's refusal (`core_error` not empty, `ours` empty). The fitting
/// study passes its limit sampling matrix applied to the control points here.
LimitComparison compare_limit_points(const adapters::LimitPoints& ours, const std::string& core_error, const PolyMesh& input,
                                     const std::string& name, const RefineRequest& request, bool isolate = true);

nlohmann::json to_json(const LimitComparison& c);

/// One row of the eigen table: the local subdivision matrix of an interior vertex of valence
/// n (rows: the refined 1-ring, columns: the coarse 1-ring), taken out of core's own
/// subdivision matrix of a fan, and its spectrum against the published closed form.
struct SpectrumRow {
    std::string scheme;  ///< "loop", "warren", "catmull-clark"
    int valence = 0;
    std::vector<double> eigenvalues;   ///< core's matrix, moduli sorted descending
    std::vector<double> closed_form;   ///< the published spectrum, sorted descending
    double max_difference = NAN;       ///< between the two lists
    double max_imaginary = NAN;        ///< largest |imaginary part| among core's eigenvalues
    double subdominant = NAN;          ///< lambda_1
    int subdominant_multiplicity = 0;  ///< eigenvalues within 1e-9 of lambda_1
    double next = NAN;                 ///< the largest eigenvalue below lambda_1
    /// lambda_1 real, double, and strictly above the next: the condition for a regular
    /// characteristic map (Reif 1995; Zorin's thesis ch. 4).
    bool regular_characteristic_map = false;
    /// The eigenvalue that governs how fast a vertex position converges: the largest one
    /// below 1 whose eigenvector is rotation invariant (the others vanish at the centre).
    double vertex_rate = NAN;
};

/// @throws InputError for a scheme other than loop, warren, catmull-clark or n < 3.
SpectrumRow local_spectrum(const std::string& scheme, int valence);

/// One row of the convergence table: the centre of a fan of valence n refined k = 1..levels
/// times, its distance to the limit position computed on the input.
struct ConvergenceRow {
    std::string scheme;
    int valence = 0;
    std::vector<double> distance;  ///< k = 1 .. levels, relative to the input's diagonal
    double fitted_rate = NAN;      ///< geometric mean of d_{k+1} / d_k over the levels
    double vertex_rate = NAN;      ///< from the spectrum, for comparison
    double subdominant = NAN;
};

ConvergenceRow convergence(const std::string& scheme, int valence, int levels);

nlohmann::json to_json(const SpectrumRow& r);
nlohmann::json to_json(const ConvergenceRow& r);

}  // namespace crossdiv::verification
