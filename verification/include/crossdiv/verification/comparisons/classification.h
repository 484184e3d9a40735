#pragma once
/// @file
/// The one classification ladder: why a run diverges, decided by measurement. Every
/// comparison of refinements (Loop, the polygon schemes) hands its measured tests to
/// classify_divergence, which tries them in one fixed precedence and takes the first that
/// holds:
///
///   1. isolated-vertex-handling  same faces, and only vertices without faces differ
///   2. rounding                  same faces, within tolerances::kRoundingUlps of the coordinates;
///                                or, matched by position where vertices lie closer than the
///                                reference's rounding, every face on one of core's whose
///                                corners are as near (rounding_among_near_vertices)
///   3. the reference's rule      core re-run with the rule the reference applies agrees in faces
///                                and positions (weight-family, corner-rule, boundary-rule,
///                                border-faces-dropped, parity: rule_difference_class)
///   4. valence-limit             at level 1 exactly the vertices beyond the reference's weight
///                                table differ
///      short-boundary-loop       the Butterflies: at level 1 only the points of boundary edges
///                                on boundary loops of three edges differ, where the four-point
///                                rule's two outer points are one vertex
///   5. non-manifold-handling     core took OpenSubdiv's non-manifold rules, and every vertex
///                                that differs lies where the non-manifold vertices reach; or,
///                                where no vertex bijection exists, the reference agrees with
///                                core on the input with every vertex split into one per fan
///                                of faces (split_fans_handling)
///      fan-walk                  against OpenSubdiv itself, whose rules core takes: every
///                                vertex that differs lies where the vertices Far's walk takes
///                                for manifold ones reach (opensubdiv_walk_accepted_vertices)
///   6. topology                  a measured difference of the refined connectivity: the
///                                counts differ, or the face sets differ under a correspondence
///                                derived from provenance (measured_topology_difference). Face
///                                sets that differ only under a match by position are not one: a
///                                wrong weight that moves vertices far breaks such a match.
///   7. unexplained               none of the above: a failure
///
/// A test a comparison cannot run (no weight table, no vertex correspondence) is left empty.
/// Cheap tests come first; a test is run only when every one before it failed, so core is
/// re-run with another rule only when rounding does not already explain the difference.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "crossdiv/verification/harness/verdict.h"
#include "crossdiv/verification/implementations/scheme.h"

namespace crossdiv::verification {

/// A class with the sentence (measured figures included) that shows it.
struct Classification {
    DivergenceClass cls = DivergenceClass::Unexplained;
    std::string explanation;
};

/// One test of the ladder: its classification when it holds, nothing otherwise.
using DivergenceTest = std::function<std::optional<Classification>()>;

/// The tests one comparison can run on one divergence (empty: not applicable).
struct DivergenceTests {
    DivergenceTest isolated_vertices;
    DivergenceTest rounding;
    DivergenceTest reference_rule;
    DivergenceTest valence_table;
    DivergenceTest short_boundary_loops;
    DivergenceTest nonmanifold;  ///< core took OpenSubdiv's non-manifold rules; the reference differs only where they apply
    DivergenceTest topology;
    /// The sentence for an unexplained divergence (its class is always Unexplained).
    std::function<std::string()> unexplained;
};

/// The first test of the ladder that holds, else Unexplained with `tests.unexplained()`.
Classification classify_divergence(const DivergenceTests& tests);

/// The class of a divergence that the reference's rule `applied` explains, against the rule
/// `requested`: Loop weight-family, corner-rule or both; Catmull-Clark weight-family for another
/// interior vertex rule, corner-rule between edge-only and edge-and-corner, else boundary-rule;
/// crease-rules where only the crease transition differs (Loop, Catmull-Clark);
/// Doo-Sabin weight-family for other corner weights on the same border, else
/// border-faces-dropped; sqrt3 parity.
DivergenceClass rule_difference_class(Scheme scheme, const SchemeRule& applied, const SchemeRule& requested);

/// The vertices of the last of `levels` (0..N of a primal refinement that keeps old vertices
/// first, as core's Loop and Catmull-Clark do) that the non-manifold vertices of level 0 can
/// reach: at each level a vertex is near when it shares a face with a reached one; a child
/// of a vertex is reached when its parent is near, a new vertex when an old one sharing a
/// child face with it is (an edge point's ends, a face point's corners): a superset of the
/// stencils' support. Empty when level 0 is a manifold.
std::vector<char> nonmanifold_reach(const std::vector<const PolyMesh*>& levels);

/// The same reach from the level-0 vertices `seeds`; empty when there are none.
std::vector<char> reach_of(const std::vector<const PolyMesh*>& levels, const std::vector<int>& seeds);

/// Test 5 of the ladder: non-manifold-handling when every vertex of `ours` farther than
/// `tolerance` x its diagonal from its match in `ref` lies where `reach` marks (the sentence
/// says how many, by up to `max_rel`; `against` names core's rule when it is not the
/// requested one); nothing otherwise.
std::optional<Classification> nonmanifold_handling(const std::vector<char>& reach, const PolyMesh& ours,
                                                   const PolyMesh& ref, const std::vector<int>& ref_to_ours,
                                                   double tolerance, const std::string& reference, double max_rel,
                                                   const std::string& against = "");

/// Test 5 against OpenSubdiv: fan-walk when every vertex of `ours` that differs from its match
/// in `ref` (as nonmanifold_handling counts them) lies where `reach` marks, the reach of the
/// `accepted` vertices (opensubdiv_walk_accepted_vertices of the input); nothing otherwise.
std::optional<Classification> fan_walk_handling(const std::vector<char>& reach, const std::vector<int>& accepted,
                                                const PolyMesh& ours, const PolyMesh& ref,
                                                const std::vector<int>& ref_to_ours, double tolerance,
                                                const std::string& reference, double max_rel);

/// Test 5 where no vertex bijection exists: non-manifold-handling when the input has a vertex
/// whose faces form more than one fan, and the reference's last level `ref` agrees in faces
/// and within `tolerance` with `core_refine` of the input split into one vertex per fan
/// (split_vertex_fans): the reference split those vertices, as a half-edge structure must,
/// and refined a manifold. `core_refine` returns core's last level under the reference's
/// rule, or nothing when core refuses. Nothing otherwise.
std::optional<Classification> split_fans_handling(const PolyMesh& input, const PolyMesh& ref,
                                                  const std::function<std::optional<PolyMesh>(const PolyMesh&)>& core_refine,
                                                  double tolerance, const std::string& reference);

/// Test 2 where a match by position found other faces: rounding when `ref` is `ours` up to
/// the reference's rounding `tolerance` (x ours' diagonal: the float tier of a float
/// reference), where some of ours' vertices lie closer together than that, which a match by
/// position cannot tell apart: the same counts, every vertex of each within the distance of
/// one of the other's, and every face of `ref` on its own face of ours whose corners, in the same
/// cycle, each lie within the distance of its corners. So a float result of tiny faces far from
/// the origin (vertices 1e-4 apart at coordinates near 100, a few float ulps) that joins its
/// faces to the other of two such vertices is named; a vertex moved farther, a face whose
/// corners are not a face of core's, is not. Nothing when it does not hold (also when a face's
/// partner is not among the faces of the NearestPoints::kMaxNeighbours vertices of ours nearest
/// its first corner: too crowded to tell).
std::optional<Classification> rounding_among_near_vertices(const PolyMesh& ours, const PolyMesh& ref, double tolerance);

/// Whether a comparison measured a difference of topology (test 6): the counts differ, or
/// the face sets differ under a correspondence found by `method` Order or Topology (from
/// provenance, independent of positions).
bool measured_topology_difference(const TopologyCounts& ours, const TopologyCounts& ref, bool face_sets_equal,
                                  MatchMethod method);

/// The input handling a reference shows on an input core refuses, from the first error of
/// core's mesh checks: non-manifold-handling, orientation-handling, degenerate-face-handling,
/// else invalid-input-handling.
DivergenceClass input_handling_class(const PolyMesh& input);

}  // namespace crossdiv::verification
