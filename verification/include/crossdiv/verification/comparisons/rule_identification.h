#pragma once
/// @file
/// Which named rule an implementation under test follows, measured vertex class by vertex
/// class. A subject's refinement, renumbered into core's numbering, is compared with core's
/// refinement under every named Loop rule (weights loop | warren | regularity | continuity, boundary edge-only |
/// edge-and-corner). At the first compared level each vertex depends only on the input and
/// on the rule for its class, so the fit of a rule can be read class by class:
///
///   interior-vertex (by valence)  the weight family (Loop's beta, or Warren's 3/(8n))
///   boundary-vertex               the boundary mask 1/8, 3/4, 1/8 (every named rule)
///   corner                        a boundary vertex of one face: kept (edge-and-corner) or
///                                 moved by the boundary mask (edge-only)
///   interior-edge-point           3/8, 3/8, 1/8, 1/8 (every named rule)
///   boundary-edge-point           the midpoint (every named rule)
///   isolated-vertex               a vertex without faces (kept by every named rule)
///
/// A rule fits a class when every vertex of the class lies within the tolerance (relative to
/// the diagonal) of core's vertex under that rule. The whole-mesh rule is the first named rule
/// that fits every vertex at every compared level (the requested rule first).

#include <optional>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/harness/correspondence.h"

namespace crossdiv::verification {

/// The vertex classes the Loop rules tell apart.
enum class VertexClass { InteriorVertex, BoundaryVertex, Corner, InteriorEdgePoint, BoundaryEdgePoint, IsolatedVertex };
/// "interior-vertex", "boundary-vertex", "corner", "interior-edge-point", "boundary-edge-point", "isolated-vertex".
const char* to_string(VertexClass cls);

/// How far the subject lies from core under one named rule, over some set of vertices.
struct RuleFit {
    LoopOptions rule{LoopWeights::Loop, LoopBoundary::EdgeOnly};
    double max_rel = 0;  ///< largest distance over the diagonal (INFINITY: not comparable)
    bool fits = false;   ///< max_rel within the tolerance
};

/// One vertex class (interior vertices: one row per valence) at the classified level.
struct VertexClassRow {
    VertexClass cls = VertexClass::InteriorVertex;
    int valence = 0;  ///< the parent vertex's valence (interior vertices); 0 otherwise
    int count = 0;
    std::vector<RuleFit> fits;  ///< one per named rule, in the order of loop_named_rules()
    /// The vertex (core numbering, classified level) where the best-fitting rule is farthest.
    int worst_vertex = -1;
};

struct RuleIdentification {
    int classified_level = 0;  ///< 0: no level was classified (levels=final with more than one level)
    std::vector<VertexClassRow> rows;
    std::vector<RuleFit> whole;      ///< every vertex at every compared level, per named rule
    std::optional<LoopOptions> rule; ///< the rule that fits the whole mesh, when one does
};

/// Loop's named rules: weights loop, warren, regularity, continuity x boundary edge-only, edge-and-corner.
std::vector<LoopOptions> loop_named_rules();

/// Classifies and measures. `subject[l-1]` and `core[r][l-1]` are level l in core's numbering
/// (an empty subject level was not compared); `births[l-1]` is core's provenance of level l;
/// `input` is level 0. `core` has one entry per loop_named_rules() rule.
RuleIdentification identify_loop_rule(const PolyMesh& input, const std::vector<PolyMesh>& subject,
                                      const std::vector<std::vector<PolyMesh>>& core,
                                      const std::vector<std::vector<VertexBirth>>& births, const LoopOptions& requested,
                                      double tolerance);

/// Of the named rules that fit the whole mesh, the one nearest `other`: `other` itself, else
/// one with its weights, else one with its boundary rule, else the first; nothing when none fits.
std::optional<LoopOptions> nearest_fitting_rule(const RuleIdentification& id, const LoopOptions& other);

/// The rules an implementation under test follows over many inputs, in one sentence:
/// "Loop scheme, weights=warren at interior vertices (valence 3..12), edge-only boundary, no
/// corner rule; ...". Fed one identification per input.
class RuleTally {
public:
    void add(const RuleIdentification& id);
    /// The rule phrases: weights at interior vertices, boundary, corners, edge points.
    std::string rule_phrase() const;
    /// "agrees with core weights=warren boundary=edge-only to 2.1e-16 on 18 of 18 meshes", or
    /// the best whole-mesh fit when no rule fits every mesh.
    std::string core_phrase() const;

private:
    struct Key {
        VertexClass cls;
        int valence;
        bool operator==(const Key&) const = default;
    };
    struct Tally {
        Key key;
        int inputs = 0, count = 0;
        std::vector<double> max_rel;  ///< per named rule, the largest over the inputs
        std::vector<char> fits;       ///< per named rule, fits on every input
    };
    std::vector<Tally> rows_;
    std::vector<int> whole_fits_;     ///< per named rule, the inputs where it fits the whole mesh
    std::vector<double> whole_max_;   ///< per named rule, the largest whole-mesh distance where it fits
    int inputs_ = 0;
};

}  // namespace crossdiv::verification
