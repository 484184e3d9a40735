#pragma once
/// @file
/// Which named rule an implementation under test follows, measured vertex class by vertex
/// class. A subject's refinement, renumbered into core's numbering, is compared with core's
/// refinement under every named rule of its scheme (named_rules: Loop's weights loop | warren
/// | regularity | continuity x boundary edge-only | edge-and-corner; Catmull-Clark's
/// boundary rules, OpenMesh's midpoint-average among them, with and without OpenSubdiv's
/// smooth-triangle weights, and the literature's other interior vertex rules; Doo-Sabin's
/// border rules with Doo and Sabin's or Catmull and Clark's weights; sqrt3's parities; the
/// Butterflies' wing rules; bilinear's one). At the first compared level each vertex depends only on the
/// input and on the rule for its class, so the fit of a rule can be read class by class, the
/// classes read off core's provenance (a primal scheme's: births):
///
///   interior-vertex (by valence)  a vertex point inside: the weight family
///   boundary-vertex               a vertex point on the boundary: the boundary mask
///   corner                        a boundary vertex of one face: kept, or moved by the boundary mask
///   interior-edge-point           an edge point inside
///   boundary-edge-point           an edge point on the boundary
///   face-point (by face size)     a face point (Catmull-Clark, bilinear)
///   isolated-vertex               a vertex without faces (kept by every named rule)
///   crease-vertex, dart,          a tagged mesh's vertices by their sharp edges (two, one,
///   sharp-corner                  three or more or a corner tag)
///   crease-edge-point             the point of an edge tagged sharp
///   corner-point (by face size)   Doo-Sabin: a corner's new point (boundary-corner-point where
///                                 the corner's vertex is on the boundary); a Chaikin point of
///                                 a boundary edge is a boundary-edge-point
///
/// sqrt3's level 1 has its old vertices and a face point per face (the boundary waits a step
/// under either parity rule, which tell themselves apart from level 2 on, in the whole-mesh fit).
///
/// A rule fits a class when every vertex of the class lies within the tolerance (relative to
/// the diagonal) of core's vertex under that rule. The whole-mesh rule is the first named rule
/// that fits every vertex at every compared level (the requested rule first).

#include <optional>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/implementations/scheme.h"

namespace crossdiv::verification {

/// The vertex classes the rules tell apart.
enum class VertexClass {
    InteriorVertex,
    BoundaryVertex,
    Corner,
    InteriorEdgePoint,
    BoundaryEdgePoint,
    FacePoint,
    IsolatedVertex,
    /// An old vertex that ends a non-manifold edge or whose faces form several fans: where
    /// OpenSubdiv's non-manifold rules (core's) apply, and most implementations do something else.
    NonManifoldVertex,
    /// The point of an edge with more than two faces, or two that traverse it alike.
    NonManifoldEdgePoint,
    /// A tagged mesh's vertices by the sharp edges at them (OpenSubdiv's vertex rules): an
    /// interior vertex with two sharp edges (the crease rule), with one (a dart: the smooth
    /// rule), and a vertex tagged a corner or with three or more sharp edges, boundary edges
    /// counted (kept in place).
    CreaseVertex,
    Dart,
    SharpCorner,
    /// The point of an interior edge tagged sharp (its midpoint while the sharpness lasts).
    CreaseEdgePoint,
    /// Doo-Sabin's new point of a corner (by the face's size): inside, and where the corner's
    /// vertex is on the boundary.
    CornerPoint,
    BoundaryCornerPoint,
};
/// "interior-vertex", "boundary-vertex", "corner", "interior-edge-point", "boundary-edge-point",
/// "face-point", "isolated-vertex", "non-manifold-vertex", "non-manifold-edge-point",
/// "crease-vertex", "dart", "sharp-corner", "crease-edge-point", "corner-point",
/// "boundary-corner-point".
const char* to_string(VertexClass cls);

/// How far the subject lies from core under one named rule, over some set of vertices.
struct RuleFit {
    SchemeRule rule;
    std::string name;    ///< rule_name of the rule
    double max_rel = 0;  ///< largest distance over the diagonal (INFINITY: not comparable)
    bool fits = false;   ///< max_rel within the tolerance
};

/// One vertex class (interior vertices: one row per valence; face points: per face size) at
/// the classified level.
struct VertexClassRow {
    VertexClass cls = VertexClass::InteriorVertex;
    int valence = 0;  ///< the parent vertex's valence (interior vertices), the face's size (face points); 0 otherwise
    int count = 0;
    std::vector<RuleFit> fits;  ///< one per named rule, in the order of named_rules()
    /// The vertex (core numbering, classified level) where the best-fitting rule is farthest.
    int worst_vertex = -1;
};

/// How far the subject's level 1 lies from a rule of another scheme that refines to the same
/// connectivity (Loop and the Butterflies split triangles alike; Catmull-Clark and bilinear
/// split faces into quads alike), or from midpoint averaging, matched vertex by vertex through
/// provenance: what a subject is when no rule of the scheme it was given as fits.
struct OtherSchemeFit {
    Scheme scheme = Scheme::Loop;
    /// The rule's name; "midpoint" for the points bilinear subdivision places (old vertices
    /// kept, edge midpoints, face centroids) on the connectivity of a triangle-splitting scheme;
    /// "<rule>, tags ignored" for the subject's own scheme on the input without its tags (a
    /// program that reads past the 't' lines it is given).
    std::string rule;
    double max_rel = 0;  ///< largest distance over the diagonal at level 1 (INFINITY: core refuses the input)
    bool fits = false;
    /// "butterfly reflected-wings", "bilinear (midpoint)"; a scheme of one rule by its name
    /// alone ("midpoint").
    std::string label() const;
    /// Whether it is its own scheme's rule on the mesh without its tags.
    bool tags_ignored() const;
    /// The rules told apart as one reading of the subject: the scheme, with the tags or
    /// without, midpoint averaging or the scheme's rules ("catmull-clark/untagged").
    std::string family() const;
};

struct RuleIdentification {
    Scheme scheme = Scheme::Loop;
    int classified_level = 0;  ///< 0: no level was classified (levels=final with more than one level, or no provenance)
    std::vector<VertexClassRow> rows;
    std::vector<RuleFit> whole;      ///< every vertex at every compared level, per named rule
    std::optional<SchemeRule> rule;  ///< the rule that fits the whole mesh, when one does
    /// When no rule fits and level 1 was classified: the scheme's rules without the input's
    /// tags (when it has some), and the rules of the schemes with the same connectivity, each
    /// measured at level 1 (empty otherwise).
    std::vector<OtherSchemeFit> other_schemes;
    /// The first of other_schemes that fits, when one does.
    const OtherSchemeFit* other_scheme() const;
};

/// The named rules of `scheme`: every rule core implements, in the order core declares them.
std::vector<SchemeRule> named_rules(Scheme scheme);

/// Classifies and measures. `subject[l-1]` and `core[r][l-1]` are level l in core's numbering
/// (an empty subject level was not compared); `births[l-1]` is core's provenance of level l
/// (empty for a scheme that is not primal); `input` is level 0. `core` has one entry per
/// named_rules(scheme) rule.
RuleIdentification identify_rule(Scheme scheme, const PolyMesh& input, const std::vector<PolyMesh>& subject,
                                 const std::vector<std::vector<PolyMesh>>& core,
                                 const std::vector<std::vector<VertexBirth>>& births, const SchemeRule& requested,
                                 double tolerance);

/// Of the named rules that fit the whole mesh, the one nearest `other`: `other` itself, else
/// (Loop) one with its weights, else one with its boundary rule, (Catmull-Clark, Doo-Sabin) the
/// one with the most options in common, else the first; nothing when none fits.
std::optional<SchemeRule> nearest_fitting_rule(const RuleIdentification& id, const SchemeRule& other);

/// The rules an implementation under test follows over many inputs, in one sentence:
/// "Loop scheme, weights=warren at interior vertices (valence 3..12), edge-only boundary, no
/// corner rule; ...". Fed one identification per input.
class RuleTally {
public:
    explicit RuleTally(Scheme scheme = Scheme::Loop) : scheme_(scheme) {}
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
    std::string loop_phrase() const;
    /// "; at level 1 it is butterfly reflected-wings on 3 of 3 inputs" when another scheme's
    /// rule fits where none of this one's does.
    std::string other_scheme_phrase() const;
    Scheme scheme_;
    struct OtherFit {
        std::string label, family;
        int inputs = 0;  ///< where it fits
    };
    std::vector<OtherFit> other_fits_;
    int other_tried_ = 0;                                  ///< inputs where other schemes were tried
    std::vector<Tally> rows_;
    std::vector<int> whole_fits_;     ///< per named rule, the inputs where it fits the whole mesh
    std::vector<double> whole_max_;   ///< per named rule, the largest whole-mesh distance where it fits
    int inputs_ = 0;
};

}  // namespace crossdiv::verification
