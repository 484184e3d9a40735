#include "crossdiv/verification/comparisons/refinement_comparison.h"

#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/nonmanifold.h"
#include "crossdiv/verification/comparisons/input_transformation.h"
#include "crossdiv/verification/comparisons/nondeterminism.h"
#include "crossdiv/verification/comparisons/shared_topology.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <cstring>
#include <deque>
#include <functional>

#include "crossdiv/error.h"
#include "harness/sci.h"
#include "crossdiv/verification/comparisons/classification.h"
#include "crossdiv/verification/harness/coincident_vertices.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/properties/rule_oracle.h"
#include "crossdiv/verification/harness/json_text.h"

namespace crossdiv::verification {
namespace {

using detail::sci;

/// Core's refinement of the input under one rule: levels 0..N (0 the input) and, where core
/// gives it, each refined vertex's origin; or why core refused.
struct CoreRun {
    SchemeRule rule;
    std::optional<FaceVaryingRule> face_varying;
    Refinement refinement;
    std::string error;
    const adapters::LevelTrace& levels() const { return refinement.levels; }
    const PolyMesh& last() const { return refinement.levels.back(); }
};

/// Core's refinements of one input, each rule's made once, through core's implementation.
class CoreRuns {
public:
    CoreRuns(const PolyMesh& input, Scheme scheme, int levels, std::optional<FaceVaryingRule> face_varying)
        : input_(input), scheme_(scheme), levels_(levels), face_varying_(face_varying) {}

    /// The run under `rule` (its error set when core refuses), its face-varying channels under
    /// the request's face-varying rule. A deque: earlier runs stay where they are while later
    /// ones are added.
    const CoreRun& with(const SchemeRule& rule) { return with(rule, face_varying_); }

    /// The run under `rule` with the channels refined under `fvar` (what a face-varying
    /// divergence is measured against; the face-varying rule changes no vertex or face).
    const CoreRun& with(const SchemeRule& rule, std::optional<FaceVaryingRule> fvar) {
        for (const CoreRun& run : runs_)
            if (run.face_varying == fvar && same_rule(scheme_, run.rule, rule)) return run;
        CoreRun& run = runs_.emplace_back();
        run.rule = rule;
        run.face_varying = fvar;
        try {
            run.refinement = core_implementation().refine_with_provenance(input_, {scheme_, rule, levels_, fvar});
        } catch (const InputError& e) {
            run.error = e.what();
            run.refinement.levels = {input_};
        }
        return run;
    }

    int levels() const { return levels_; }

private:
    const PolyMesh& input_;
    Scheme scheme_;
    int levels_;
    std::optional<FaceVaryingRule> face_varying_;
    std::deque<CoreRun> runs_;
};

/// Whether `refine(m)` -- an implementation's refinement, its last level -- gives other
/// face-varying values when the faces of `input` are listed reversed or rotated by half: the
/// largest change relative to the UV box and the order that shows it, or nothing when no
/// order changes them beyond `tolerance` (or the runs cannot be compared).
struct OrderChange {
    double max_rel;
    std::string order;
};
std::optional<OrderChange> face_order_change(const PolyMesh& input, const PolyMesh& as_given,
                                             const std::function<std::optional<PolyMesh>(const PolyMesh&)>& refine,
                                             double tolerance) {
    const int n = input.num_faces();
    std::vector<int> reversed(static_cast<size_t>(n)), rotated(static_cast<size_t>(n));
    for (int f = 0; f < n; ++f) {
        reversed[static_cast<size_t>(f)] = n - 1 - f;
        rotated[static_cast<size_t>(f)] = (f + n / 2) % n;
    }
    for (const auto& [order, name] : {std::pair{&reversed, "reversed"}, std::pair{&rotated, "rotated by half"}}) {
        const std::optional<PolyMesh> other = refine(with_face_order(input, *order));
        if (!other) continue;
        const Correspondence m = match_nearest_and_faces(as_given, *other);
        if (m.method == MatchMethod::None) continue;
        const CornerValueComparison c = compare_corner_values(as_given, *other, m.ref_to_ours);
        if (c.compared() && c.max_rel > tolerance) return OrderChange{c.max_rel, name};
    }
    return std::nullopt;
}

nlohmann::json statistics_json(const MeshStatistics& s) {
    return {{"vertices", s.vertices}, {"faces", s.faces}, {"edges", s.edges}, {"triangles", s.triangles},
            {"quads", s.quads}, {"larger_faces", s.larger_faces}, {"degenerate_faces", s.degenerate_faces},
            {"isolated_vertices", s.isolated_vertices}, {"boundary_edges", s.boundary_edges},
            {"boundary_loops", s.boundary_loops}, {"non_manifold_edges", s.non_manifold_edges},
            {"inconsistent_edges", s.inconsistent_edges}, {"non_manifold_vertices", s.non_manifold_vertices},
            {"components", s.components}, {"euler_characteristic", s.euler_characteristic},
            {"genus", s.genus >= 0 ? nlohmann::json(s.genus) : nlohmann::json()}};
}

/// Whether `rule` brings Hbr's face-varying rules (FaceVaryingOptions::rules).
bool legacy_face_varying_rules(Scheme scheme, const SchemeRule& rule) {
    return (scheme == Scheme::Loop ? rule.loop.crease_rules : rule.catmull_clark.crease_rules) == CreaseRules::Hbr;
}

/// The face-varying values of a run whose positions were matched (`map`: its vertices to
/// ours): agreement within `tolerance` of the UV box, else the rule that explains the
/// difference -- the reference's values are core's under the reference's own face-varying
/// rules (`applied`, the rule it ran with) or under another of the six, or (a subject under
/// test) the subject's are -- else unexplained.
FaceVaryingRun compare_face_varying(const PolyMesh& ours, const PolyMesh& theirs, const std::vector<int>& map,
                                    const Implementation& ref, Scheme scheme, FaceVaryingRule requested,
                                    const SchemeRule& rule, const SchemeRule& applied, const std::string& subject,
                                    double tolerance, CoreRuns& core,
                                    const std::function<std::optional<PolyMesh>(const PolyMesh&)>& rerun_reference,
                                    const PolyMesh& input) {
    FaceVaryingRun u;
    const SchemeSupport* support = ref.support(scheme);
    if (!support || !support->face_varying) {
        u.not_compared = ref.name() + " refines no face-varying data";
        return u;
    }
    u.comparison = compare_corner_values(ours, theirs, map);
    if (!u.comparison.compared()) {
        u.not_compared = u.comparison.not_compared;
        return u;
    }
    const std::string measured = "max difference " + sci(u.comparison.max_rel) + " of the UV box";
    if (u.comparison.max_rel <= tolerance) {
        u.outcome = {Verdict::Agree, DivergenceClass::None};
        u.explanation = measured + " <= " + sci(tolerance) + " over " + std::to_string(u.comparison.corners) + " corners";
        return u;
    }
    u.worst_class = to_string(uv_vertex_class(ours, u.comparison.worst_face, u.comparison.worst_corner));
    const std::string where = measured + ", worst at " + (u.worst_class == "corner" ? std::string("a UV corner")
                                                         : u.worst_class == "interior"
                                                             ? std::string("an interior value")
                                                             : "a " + u.worst_class + " value");
    // The reference's own face-varying rules first (Hbr's, which its crease rules bring): the
    // most direct explanation, the same requested rule read as that library reads it.
    if (legacy_face_varying_rules(scheme, applied) && !legacy_face_varying_rules(scheme, rule)) {
        const CoreRun& run = core.with(applied, requested);
        if (run.error.empty() && !run.last().face_varying.empty()) {
            const CornerValueComparison fit = compare_corner_values(run.last(), theirs, map);
            if (fit.compared() && fit.max_rel <= tolerance) {
                u.outcome = {Verdict::Diverge, DivergenceClass::LegacyFaceVaryingRules};
                u.who_follows = ref.name();
                u.explanation = ref.name() + "'s texture coordinates follow Hbr's face-varying rules (OpenSubdiv 2's, which " +
                                "Far corrected: a sharp edge a face-varying boundary for good, a dart's boundary rule, no " +
                                "fractional sharpness): core under them (" + rule_name(scheme, applied) +
                                ") agrees within " + sci(tolerance) + " (" + where + ")";
                return u;
            }
        }
    }
    std::vector<int> identity(static_cast<size_t>(ours.num_vertices()));
    for (size_t i = 0; i < identity.size(); ++i) identity[i] = static_cast<int>(i);
    for (FaceVaryingRule r : kFaceVaryingRules) {
        if (r == requested) continue;
        const CoreRun& run = core.with(rule, r);
        if (!run.error.empty() || run.last().face_varying.empty()) continue;
        const PolyMesh* with = &run.last();
        const CornerValueComparison ref_fit = compare_corner_values(*with, theirs, map);
        const bool ref_follows = ref_fit.compared() && ref_fit.max_rel <= tolerance;
        bool subject_follows = false;
        if (!ref_follows && subject != "core") {
            const CornerValueComparison s = compare_corner_values(*with, ours, identity);
            subject_follows = s.compared() && s.max_rel <= tolerance;
        }
        if (!ref_follows && !subject_follows) continue;
        u.outcome = {Verdict::Diverge, DivergenceClass::FaceVaryingRule};
        u.follows = r;
        u.who_follows = ref_follows ? ref.name() : subject;
        const std::string follows(to_string(r)), asked(to_string(requested));
        u.explanation = u.who_follows + "'s texture coordinates follow the " + follows + " rule, not " + asked +
                        ": core with " + follows + " agrees with them within " + sci(tolerance) + " (" + where + ")";
        return u;
    }
    // The reference run again on the same mesh with its faces listed otherwise: values that
    // change are read off how the input is written, where core's (checked the same way) stay.
    if (const std::optional<OrderChange> changed = face_order_change(input, theirs, rerun_reference, tolerance)) {
        const auto core_again = [&](const PolyMesh& m) -> std::optional<PolyMesh> {
            try {
                return core_implementation().refine(m, {scheme, rule, core.levels(), requested}).back();
            } catch (const InputError&) {
                return std::nullopt;
            }
        };
        const CoreRun& given = core.with(rule, requested);
        if (given.error.empty() && !face_order_change(input, given.last(), core_again, tolerance)) {
            u.outcome = {Verdict::Diverge, DivergenceClass::FaceOrderDependence};
            u.explanation = ref.name() + "'s texture coordinates change by " + sci(changed->max_rel) +
                            " of the UV box when the input's faces are " + changed->order + ", where core's stay within " +
                            sci(tolerance) + " (" + where + ")";
            return u;
        }
    }
    u.outcome = {Verdict::Diverge, DivergenceClass::Unexplained};
    u.explanation = where + "; no face-varying rule of core's explains it";
    return u;
}

/// The correspondence's vertex map at level `l` of `last`: its level map when matched level by
/// level, the last level's map when matched by position (nullptr at the levels before).
const std::vector<int>* level_map(const Correspondence& c, size_t l, size_t last) {
    if (l < c.level_maps.size()) return &c.level_maps[l];
    return l == last ? &c.ref_to_ours : nullptr;
}

/// Max relative error at each level 1..N that has a map (every level when matched through
/// provenance, the last one when by position). Positions only: topology is compared once, at
/// the end. A level `ours` lacks (a level the subject was not asked for) is skipped.
std::vector<double> level_errors(const adapters::LevelTrace& ours, const adapters::LevelTrace& ref, const Correspondence& c) {
    std::vector<double> e;
    for (size_t l = 1; l < ref.size() && l < ours.size(); ++l) {
        if (ours[l].num_vertices() == 0) continue;
        if (const std::vector<int>* map = level_map(c, l, ref.size() - 1))
            e.push_back(max_relative_distance(ours[l], ref[l], *map));
    }
    return e;
}

/// The weak tier: the same faces, and every compared level within `tolerance`.
bool within_weak(const MeshComparison& c, const std::vector<double>& level_errors, double tolerance) {
    if (!c.topology_equal() || !(c.max_rel <= tolerance)) return false;
    return std::all_of(level_errors.begin(), level_errors.end(), [&](double e) { return e <= tolerance; });
}

/// A reference's vertices in our numbering (`ref_to_ours`: ours for each of its vertices);
/// NaN where none of its vertices maps.
std::vector<Vec3> in_our_numbering(const PolyMesh& ref, const std::vector<int>& ref_to_ours, int our_vertices) {
    std::vector<Vec3> mapped(static_cast<size_t>(our_vertices), Vec3::Constant(NAN));
    for (size_t i = 0; i < ref_to_ours.size(); ++i)
        if (ref_to_ours[i] >= 0 && ref_to_ours[i] < our_vertices) mapped[static_cast<size_t>(ref_to_ours[i])] = ref.positions[i];
    return mapped;
}

/// A reference's levels 0..N in our numbering, each where the correspondence has a map for it.
std::vector<std::vector<Vec3>> levels_in_our_numbering(const adapters::LevelTrace& ours, const adapters::LevelTrace& ref,
                                                       const Correspondence& c) {
    std::vector<std::vector<Vec3>> out(ref.size());
    for (size_t l = 0; l < ref.size() && l < ours.size(); ++l) {
        const std::vector<int>* map = level_map(c, l, ref.size() - 1);
        if (!map || map->empty() || map->size() != ref[l].positions.size()) continue;
        out[l] = in_our_numbering(ref[l], *map, ours[l].num_vertices());
    }
    return out;
}

/// What the reference's rule does, for the explanation.
std::string rule_effect(Scheme scheme, const std::string& ref, const std::string& requested, const std::string& rule,
                        int levels) {
    switch (scheme) {
        case Scheme::Loop: return ref + " has no " + requested + " and applies " + rule;
        case Scheme::DooSabin: return ref + " drops the faces of border edges and vertices";
        case Scheme::Sqrt3:
            return ref + (rule == "restart-each-level"
                              ? " counts generations per call, and was called once per level, so it never refined the boundary"
                              : " counts generations from the input (one call of " + std::to_string(levels) + " levels)");
        case Scheme::Butterfly:
        case Scheme::ModifiedButterfly:
            return ref + (rule == "opposite-vertex-wings" ? " takes a wing point beyond the boundary to be the triangle's own opposite vertex"
                          : rule == "other-face-wings"
                              ? " takes a wing point beyond the boundary to be the other triangle's apex" +
                                    std::string(scheme == Scheme::ModifiedButterfly
                                                    ? ", counts valence in faces, and reads a boundary endpoint by the eight-point stencil"
                                                    : "")
                              : " reflects a wing point beyond the boundary across the wing edge");
        case Scheme::CatmullClark:
        case Scheme::Bilinear:
        case Scheme::Midpoint: break;
    }
    return ref + " applies the " + rule + " boundary rule";
}

/// When the reference's weight table is shorter than the input's largest valence: whether at
/// level 1 exactly the vertices beyond the table differ from `ours` (core's level 1 under the
/// reference's rule; the others agree within `tolerance`); fills `explanation` with the
/// figures. Later levels inherit the difference from them.
bool beyond_valence_table(const Implementation& ref, Scheme scheme, const PolyMesh& input, const PolyMesh& ours,
                          const adapters::LevelTrace& trace, double tolerance, std::string& explanation) {
    const SchemeSupport* support = ref.support(scheme);
    if (!support || support->max_valence <= 0 || trace.size() < 2) return false;
    const int max_valence = support->max_valence;
    const MeshTopology topo = mesh_topology(input);
    int beyond = 0, largest = 0;
    for (int v = 0; v < input.num_vertices(); ++v) {
        beyond += topo.valence[v] > max_valence;
        largest = std::max(largest, topo.valence[v]);
    }
    if (beyond == 0) return false;
    // What it read past the table may be NaN or inf (OpenMesh's Sqrt3T), which no match by
    // position can place: such a vertex is matched at the mean of its finite neighbours (the
    // distances below are still taken to the position it made, and count as differing).
    const PolyMesh& made = trace[1];
    PolyMesh placed = made;
    std::vector<Vec3> sum(made.positions.size(), Vec3::Zero());
    std::vector<int> finite_neighbours(made.positions.size(), 0);
    for (int f = 0; f < made.num_faces(); ++f) {
        const int n = made.face_size(f), start = made.face_start[f];
        for (int k = 0; k < n; ++k) {
            const int a = made.face_vertices[start + k], b = made.face_vertices[start + (k + 1) % n];
            if (made.positions[b].allFinite()) sum[a] += made.positions[b], ++finite_neighbours[a];
            if (made.positions[a].allFinite()) sum[b] += made.positions[a], ++finite_neighbours[b];
        }
    }
    for (size_t v = 0; v < made.positions.size(); ++v)
        if (!made.positions[v].allFinite()) {
            if (finite_neighbours[v] == 0) return false;
            placed.positions[v] = sum[v] / finite_neighbours[v];
        }
    const Correspondence c = match_nearest_and_faces(ours, placed);
    if (c.method == MatchMethod::None) return false;
    const std::vector<double> d = vertex_distances(ours, trace[1], c.ref_to_ours);
    const double diagonal = bounding_box_diagonal(ours.positions);
    int differing = 0, non_finite = 0;
    double worst = 0;
    for (size_t i = 0; i < d.size(); ++i) {
        if (d[i] <= tolerance * diagonal) continue;  // a non-finite position differs too
        const int v = c.ref_to_ours[i];  // core keeps old vertices first, in input order
        if (v >= input.num_vertices() || topo.valence[v] <= max_valence) return false;
        ++differing;
        if (std::isfinite(d[i])) worst = std::max(worst, d[i] / diagonal);
        else ++non_finite;
    }
    if (differing != beyond) return false;
    explanation = ref.name() + "'s weight table ends at valence " + std::to_string(max_valence) + " (" +
                  support->valence_table + ") and what it reads past the table is undefined; at level 1 exactly the " +
                  std::to_string(beyond) + " vertices of larger valence (up to " + std::to_string(largest) + ") differ, " +
                  (non_finite == differing ? std::string("all to non-finite positions")
                                           : "by up to " + sci(worst) + " of the diagonal" +
                                                 (non_finite ? " (" + std::to_string(non_finite) + " non-finite)" : "")) +
                  ", and every other vertex agrees";
    return true;
}

/// For the Butterflies: whether at level 1 only points of boundary edges on boundary loops of
/// three edges differ between `ours` (core's level 1, edge points after the old vertices in
/// PolyConnectivity's edge order) and the reference's level 1 in our numbering (`theirs`,
/// empty entries unmatched), at least one does, and every other vertex agrees within
/// `tolerance`; there the four-point rule's two outer points are one vertex, the loop's third.
/// Fills `explanation` with the figures. Later levels inherit the difference.
bool only_short_boundary_loops_differ(const std::string& reference, const PolyMesh& input, const PolyMesh& ours,
                                      const std::vector<Vec3>& theirs, double tolerance, std::string& explanation) {
    if (theirs.size() != ours.positions.size() || !input.all_triangles()) return false;
    const PolyConnectivity conn = build_poly_connectivity(input);
    const int nv = input.num_vertices();
    if (ours.num_vertices() != nv + conn.num_edges()) return false;
    const double diagonal = bounding_box_diagonal(ours.positions);
    int differing = 0, on_loops = 0;
    double worst = 0;
    for (int v = 0; v < ours.num_vertices(); ++v) {
        const double d = (ours.positions[v] - theirs[static_cast<size_t>(v)]).norm();
        if (d <= tolerance * diagonal) continue;
        if (v < nv) return false;
        const int c = conn.edge_corner[v - nv];
        if (conn.twin[c] >= 0) return false;
        const int a0 = conn.corner_vertex[c], a1 = conn.head(c);
        const int before = conn.boundary_neighbors(a0).before, after = conn.boundary_neighbors(a1).after;
        if (before != after || conn.boundary_neighbors(after).after != a0) return false;  // a loop of more than three
        ++differing;
        worst = std::max(worst, d / diagonal);
    }
    if (differing == 0) return false;
    for (int e = 0; e < conn.num_edges(); ++e) {
        const int c = conn.edge_corner[e];
        if (conn.twin[c] >= 0) continue;
        const int a0 = conn.corner_vertex[c], a1 = conn.head(c);
        on_loops += conn.boundary_neighbors(a0).before == conn.boundary_neighbors(a1).after;
    }
    explanation = "at level 1 only the points of " + std::to_string(differing) + " of the " + std::to_string(on_loops) +
                  " boundary edges on boundary loops of three edges differ, by up to " + sci(worst) +
                  " of the diagonal, and every other vertex agrees: there the four-point rule's two outer points are one "
                  "vertex, the loop's third, which core takes twice and " + reference + " does not";
    return true;
}

/// Whether core refines a non-manifold input of `scheme` by OpenSubdiv's rules under `rule`.
bool takes_nonmanifold_rules(Scheme scheme, const SchemeRule& rule) {
    if (scheme == Scheme::Loop) return rule.loop.nonmanifold == NonManifoldRule::OpenSubdiv;
    if (scheme == Scheme::CatmullClark) return rule.catmull_clark.nonmanifold == NonManifoldRule::OpenSubdiv;
    return false;
}

/// The subject's levels renumbered into core's (level 0 the input): level by level through
/// provenance where the subject keeps old vertices first (as the libraries do), else each
/// level matched by position to core's level. Levels the subject did not make stay empty.
/// The method is the weakest one any level needed; None when some level has no bijection
/// (the note says which).
Correspondence renumber_subject(const adapters::LevelTrace& core, const adapters::LevelTrace& trace,
                                adapters::LevelTrace& subject) {
    subject.assign(core.size(), PolyMesh{});
    subject[0] = core[0];
    Correspondence c = match_by_provenance(level_view(core), trace);
    if (c.method == MatchMethod::Order || c.method == MatchMethod::Topology) {
        for (size_t l = 1; l < trace.size() && l < core.size(); ++l) subject[l] = renumber(trace[l], c.level_maps[l]);
        return c;
    }
    const std::string topological = c.note;
    c = Correspondence{};
    c.method = MatchMethod::Nearest;
    for (size_t l = 1; l < trace.size() && l < core.size(); ++l) {
        if (trace[l].num_vertices() == 0) continue;
        const Correspondence m = match_nearest_and_faces(core[l], trace[l]);
        if (m.method == MatchMethod::None) {
            c.method = MatchMethod::None;
            c.note = "level " + std::to_string(l) + ": " + m.note + " (" + topological + ")";
            return c;
        }
        if (m.method == MatchMethod::NearestAndFaces) c.method = MatchMethod::NearestAndFaces;
        subject[l] = renumber(trace[l], m.ref_to_ours);
        c.ref_to_ours = m.ref_to_ours;
    }
    c.note = topological;
    return c;
}

/// The references of the request; for a tagged input without named references, only those
/// with crease rules (the others would refuse the tags), said in a note.
std::vector<const Implementation*> chosen_references(const PolyMesh& input, const std::string& name,
                                                     const RefinementRequest& req, std::vector<std::string>& notes) {
    if (req.without_references) return {};
    std::vector<const Implementation*> refs = select_references(req.scheme, req.references);
    if (req.references.empty() && !input.creases.empty()) {
        std::erase_if(refs, [&](const Implementation* r) { return !r->support(req.scheme)->creases; });
        std::string names;
        for (const Implementation* r : refs) names += (names.empty() ? "" : ", ") + r->name();
        notes.push_back(name + " has " + input.creases.describe() + "; compared with " +
                        (names.empty() ? std::string("no reference (none has crease rules)") : names) +
                        ", the references with crease and hole rules");
    }
    return refs;
}

std::string counts(const PolyMesh& m) {
    return std::to_string(m.num_faces()) + " faces and " + std::to_string(m.num_vertices()) + " vertices";
}

bool equal_counts(const PolyMesh& a, const PolyMesh& b) { return a.num_vertices() == b.num_vertices() && a.num_faces() == b.num_faces(); }

/// What keeps a float result from being matched to `level` by position: how many of its
/// vertices a float cannot tell apart, and how far from the origin they lie; nothing when a
/// float tells them all apart.
std::optional<std::string> float_cannot_tell_apart(const PolyMesh& level) {
    const size_t merged = vertices_float_cannot_tell_apart(level.positions);
    if (merged == 0) return std::nullopt;
    double reach = 0;
    for (const Vec3& p : level.positions) reach = std::max(reach, p.cwiseAbs().maxCoeff());
    const double step = std::nextafter(static_cast<float>(reach), std::numeric_limits<float>::infinity()) - static_cast<float>(reach);
    return std::to_string(merged) + " of core's " + std::to_string(level.num_vertices()) +
           " vertices share a position once rounded to float (coordinates up to " + sci(reach) + ", where a float's step is " +
           sci(step) + ", against a diagonal of " + sci(bounding_box_diagonal(level.positions)) + ")";
}

}  // namespace

PolyMesh subdivide(Scheme scheme, const SchemeRule& rule, const PolyMesh& mesh, int levels) {
    return core_implementation().refine_last(mesh, {scheme, rule, levels});
}

bool RefinementComparison::all_agree() const {
    if (!core_error.empty() || runs.empty()) return false;
    return std::all_of(runs.begin(), runs.end(), [](const RefinementRun& r) {
        return r.verdict == Verdict::Agree && (!r.uv || !r.uv->compared() || r.uv->outcome.verdict == Verdict::Agree);
    });
}

namespace {

/// "face 12 (3 7 9)": a face of `m` by index and corners.
std::string face_text(const PolyMesh& m, int f) {
    std::string s = "face " + std::to_string(f) + " (";
    for (int k = 0; k < m.face_size(f); ++k) {
        if (k) s += ' ';
        s += std::to_string(m.face(f)[k]);
    }
    return s + ")";
}

/// How the subject's faces (in core's numbering) differ from core's at the first level where
/// they do, naming the first face only in each; "" when every compared level has core's faces.
std::string subject_face_difference(const adapters::LevelTrace& core, const adapters::LevelTrace& subject) {
    for (size_t l = 1; l < subject.size() && l < core.size(); ++l) {
        const PolyMesh &ours = core[l], &theirs = subject[l];
        if (theirs.num_vertices() == 0 && theirs.num_faces() == 0) continue;  // a level not compared
        const MeshComparison c = compare_meshes(ours, theirs, identity_map(static_cast<size_t>(theirs.num_vertices())));
        if (c.face_sets_equal) continue;
        std::string s = "its faces are not core's: at level " + std::to_string(l) + ", " + std::to_string(c.faces_only_in_ref) +
                        " of its " + std::to_string(theirs.num_faces()) + " faces are not core's";
        if (c.first_face_only_in_ref >= 0) s += " (first: " + face_text(theirs, c.first_face_only_in_ref) + ")";
        s += ", " + std::to_string(c.faces_only_in_ours) + " of core's " + std::to_string(ours.num_faces()) + " are not its";
        if (c.first_face_only_in_ours >= 0) s += " (first: " + face_text(ours, c.first_face_only_in_ours) + ")";
        return s + "; vertices in core's numbering";
    }
    return "";
}

}  // namespace

RefinementComparison compare_refinement(const PolyMesh& input, const std::string& name, const RefinementRequest& req) {
    RefinementComparison out;
    out.input = name;
    out.scheme = req.scheme;
    out.rule = req.rule;
    out.rule_name = rule_name(req.scheme, req.rule);
    out.levels = req.levels;
    out.tier = req.tier;
    out.tolerance = req.tolerance;
    out.input_vertices = input.num_vertices();
    out.input_faces = input.num_faces();
    out.input_statistics = mesh_statistics(input);
    const std::vector<const Implementation*> refs = chosen_references(input, name, req, out.notes);
    const bool primal = traits(req.scheme).primal;

    const auto t0 = std::chrono::steady_clock::now();
    const std::optional<FaceVaryingRule> fvar = input.face_varying.empty() ? std::nullopt : req.face_varying;
    out.face_varying = fvar;
    CoreRuns core(input, req.scheme, req.levels, fvar);
    const CoreRun& requested = core.with(req.rule);
    out.core_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out.core_error = requested.error;
    if (fvar && requested.error.empty() && requested.last().face_varying.empty())
        out.notes.push_back(input.creases.edits.empty()
                                ? "core refined the positions only: its face-varying refinement takes a manifold mesh, and " +
                                      name + " is not one (texture coordinates not compared)"
                                : "core refined the positions only: it applies hierarchical edits to positions and does not "
                                  "refine the texture coordinates of an edited mesh (not compared)");

    // The implementation under test: core with the requested rule, or the subject in core's
    // numbering with the rule it is measured to follow (none when no named rule fits).
    const adapters::LevelTrace* under_test = &requested.levels();
    const CoreRun* numbered_as = &requested;  // the core run whose numbering the implementation under test has
    adapters::LevelTrace subject;
    std::optional<SchemeRule> subject_rule = req.rule;
    const std::string subject_name = req.subject ? req.subject->name() : "core";
    if (req.subject && out.core_error.empty()) {
        out.subject = subject_name;
        IsolatedTrace iso = refine_isolated(*req.subject, input, {req.scheme, req.rule, req.levels, fvar}, req.timeout_seconds,
                                            req.isolate);
        out.subject_outcome = iso.outcome;
        if (iso.outcome.status != RunStatus::Ok) return out;
        // Core's numbering under the requested rule; for a scheme whose rules change the
        // vertex set (a Doo-Sabin border dropped, sqrt3's other parity), under the first named
        // rule whose levels the subject's match.
        const std::vector<SchemeRule> rules = named_rules(req.scheme);
        out.subject_match = renumber_subject(requested.levels(), *iso.trace, subject);
        for (size_t r = 0; r < rules.size() && out.subject_match.method == MatchMethod::None && !primal; ++r) {
            const CoreRun& other = core.with(rules[r]);
            if (!other.error.empty() || &other == &requested) continue;
            adapters::LevelTrace renumbered;
            const Correspondence m = renumber_subject(other.levels(), *iso.trace, renumbered);
            if (m.method == MatchMethod::None) continue;
            out.subject_match = m;
            subject = std::move(renumbered);
            numbered_as = &other;
        }
        if (out.subject_match.method == MatchMethod::None) {
            out.subject_unmatched = "no vertex correspondence with core's refinement: " + out.subject_match.note;
            return out;
        }
        std::vector<std::vector<PolyMesh>> by_rule;
        for (const SchemeRule& r : rules) {
            const adapters::LevelTrace& levels = core.with(r).levels();
            by_rule.emplace_back(levels.begin() + 1, levels.end());
        }
        // Its vertices matched, its faces must be core's: positions alone would pass a subject
        // that scrambles, reverses or duplicates faces.
        out.subject_topology = subject_face_difference(numbered_as->levels(), subject);
        if (!out.subject_topology.empty()) return out;
        out.rules = identify_rule(req.scheme, input, {subject.begin() + 1, subject.end()}, by_rule,
                                  numbered_as->refinement.births, req.rule, req.tolerance);
        subject_rule = out.rules->rule;
        if (fvar) {
            std::vector<const PolyMesh*> by_fvar_rule;
            for (FaceVaryingRule r : kFaceVaryingRules) {
                const CoreRun& run = core.with(numbered_as->rule, r);
                by_fvar_rule.push_back(run.error.empty() ? &run.last() : nullptr);
            }
            out.uv_rules = identify_face_varying_rule(subject.back(), by_fvar_rule, *fvar, req.tolerance);
        }
        under_test = &subject;
    }
    const PolyMesh& ours = under_test->back();

    // Counted once, when first needed: the input's largest valence (the float tier's bound)
    // and its interior vertices' valences (where a rule's oracle checks its vertex mask).
    std::optional<MeshTopology> topology;
    auto input_topology = [&]() -> const MeshTopology& {
        if (!topology) topology = mesh_topology(input);
        return *topology;
    };
    std::optional<int> float_sum;  // the float tier's n (tolerances.h), computed once when asked
    auto longest_sum = [&] {
        if (!float_sum) float_sum = longest_float_sum(input);
        return *float_sum;
    };
    auto interior_valences = [&] {
        std::vector<int> list;
        const MeshTopology& t = input_topology();
        for (size_t v = 0; v < t.valence.size(); ++v)
            if (!t.boundary_vertex[v] && t.valence[v] >= 3) list.push_back(t.valence[v]);
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
        return list;
    };

    // Each matched reference's last level in our numbering (every implementation's value at
    // the case's worst vertex) and, for the 3D view, every level it was matched at.
    std::map<std::string, std::vector<Vec3>> in_our_order;
    const bool keep_view = req.view_max_faces > 0 && out.core_error.empty() && ours.num_faces() <= req.view_max_faces;
    std::map<std::string, std::vector<std::vector<Vec3>>> at_each_level;
    std::map<std::string, std::vector<double>> uvs_at_our_corners;  // the view's texture coordinates
    // The faces of each run whose faces are not core's (runs[i] <-> made_by_run[i]), for the post-pass
    // that lets a topology difference stand only where it is shared (shared_topology.h).
    std::vector<std::optional<MadeFaces>> made_by_run;
    // Where each run's result changed when it ran again (runs[i] <-> changed[i]; nondeterminism.h).
    std::vector<std::optional<std::string>> changed;
    // A reference that computes in float is held to the float tier: the weak tier at the
    // float bound (tolerances::kFloatAgreementUlps), whatever tier the case asks of doubles.
    const auto tolerance_for = [&](const Implementation& ref) {
        return ref.capabilities().precision == Precision::Float
                   ? agreement_tolerance(ours, true, req.tolerance, longest_sum(), req.levels)
                   : req.tolerance;
    };
    for (const Implementation* impl : refs) {
        const Implementation& ref = *impl;
        RefinementRun run;
        run.reference = ref.name();
        run.version = ref.version();
        run.ran_with = ref.closest_rule(req.scheme, req.rule);
        run.rule = rule_name(req.scheme, run.ran_with);
        const bool rules_differ = !same_rule(req.scheme, run.ran_with, req.rule);
        // Asked for the rule it applies: a program is handed the rule as it is asked.
        if (fvar) {
            run.uv.emplace();
            run.uv->not_compared = "the positions were not matched";
        }
        IsolatedTrace iso = refine_isolated(ref, input, {req.scheme, run.ran_with, req.levels, fvar}, req.timeout_seconds, req.isolate);
        // The same run again with the heap filled otherwise: a result that changes is recorded
        // as ref-nondeterministic after the classification below (nondeterminism.h).
        changed.emplace_back();
        if (req.isolate && !ref.confines_itself() && reruns_for_determinism(iso.outcome.status))
            changed.back() = first_difference(iso, refine_isolated(ref, input, {req.scheme, run.ran_with, req.levels, fvar},
                                                                    req.timeout_seconds, true, kSecondHeapFill));
        run.outcome = iso.outcome;
        // Non-finite coordinates where its weight table ends below the input's valence are what
        // it read past the table (OpenMesh's Sqrt3T): the valence limit, whether what lay there
        // read as NaN or as a number in this run.
        if (iso.outcome.status == RunStatus::NonFiniteOutput && iso.trace && out.core_error.empty()) {
            const CoreRun& s = core.with(run.ran_with);
            std::string why;
            if (s.error.empty() && s.levels().size() >= 2 &&
                beyond_valence_table(ref, req.scheme, input, s.levels()[1], *iso.trace, tolerance_for(ref), why)) {
                run.verdict = Verdict::Diverge;
                run.divergence_class = DivergenceClass::ValenceLimit;
                run.explanation = why + " (" + iso.outcome.message + ")";
                out.runs.push_back(std::move(run));
                continue;
            }
        }
        const std::string made = iso.trace ? "core refuses the input (" + out.core_error + "); " + ref.name() + " refines it to " +
                                                 counts(iso.trace->back())
                                           : std::string();
        if (const std::optional<EarlyVerdict> early = verdict_before_comparing(run.outcome, out.core_error, made)) {
            run.verdict = early->verdict;
            run.explanation = early->explanation;
            // The class names what the input breaks, from the checker's first error; a refusal
            // the case does not declare is a failure, its class kept in the explanation.
            if (run.verdict == Verdict::OursRejected) {
                run.divergence_class = input_handling_class(input);
                const auto& expected = req.expected_refusals;
                if (std::find(expected.begin(), expected.end(), run.divergence_class) == expected.end()) {
                    run.explanation += "; a refusal (" + std::string(to_string(run.divergence_class)) +
                                       ") the case does not declare expected (refuses=" + to_string(run.divergence_class) + ")";
                    run.divergence_class = DivergenceClass::Unexplained;
                }
            }
            out.runs.push_back(std::move(run));
            continue;
        }
        const adapters::LevelTrace& trace = *iso.trace;
        const PolyMesh& theirs = trace.back();

        const bool in_float = ref.capabilities().precision == Precision::Float;
        const double tolerance = tolerance_for(ref);
        const Tier tier = in_float && req.tier == Tier::Strict ? Tier::Weak : req.tier;
        if (tier == Tier::Geometric) {
            const double d = bounding_box_diagonal(ours.positions);
            run.hausdorff_rel = hausdorff_vertex_sets(ours.positions, theirs.positions) / (d > 0 ? d : 1);
        }
        const std::string geometric_why = "vertex-set Hausdorff distance " + sci(run.hausdorff_rel) + " <= " + sci(tolerance);

        // Core with the reference's rule, to measure what the rule explains (and to match a
        // scheme that is not primal against); a rule core has only for manifold meshes
        // (OpenMesh's midpoint-average on a bowtie) is not measured.
        std::string no_same_rule;
        auto core_with_reference_rule = [&]() -> const CoreRun* {
            const CoreRun& s = core.with(run.ran_with);  // the requested run itself when the rules are the same
            if (s.error.empty()) return &s;
            no_same_rule = "; core cannot apply " + ref.name() + "'s " + run.rule + " rule here (" + s.error + ")";
            return nullptr;
        };
        // Match through provenance where the scheme gives it (positions play no part: a rule
        // that moves vertices far is matched too), else by position against core with the
        // reference's rule, which then coincide up to rounding even where the requested rule
        // moves vertices or makes others.
        const CoreRun* matched_to = &requested;
        if (primal) run.correspondence = match_by_provenance(level_view(requested.levels()), trace);
        if (!primal || run.correspondence.method == MatchMethod::None) {
            const std::string why = run.correspondence.note;
            if (const CoreRun* with = core_with_reference_rule()) matched_to = with;
            // A float reference cannot tell apart two of our vertices closer than its tolerance
            // (a real model's overlapping parts): it names them copies, placed by their faces.
            run.correspondence = match_nearest_and_faces(matched_to->last(), theirs, in_float ? tolerance : kCopyDistance);
            if (!why.empty()) run.correspondence.note = why + (run.correspondence.note.empty() ? "" : "; " + run.correspondence.note);
        }
        // The map holds for the implementation under test where its numbering is that of the
        // run it was matched to: always for a primal scheme (rules do not change its faces).
        const bool map_holds = primal || matched_to == numbered_as || matched_to->last().num_vertices() == ours.num_vertices();
        const std::vector<int> no_map;
        const std::vector<int>& map = map_holds ? run.correspondence.ref_to_ours : no_map;

        // A reference whose weight table ends below the input's valence reads past it: what it
        // puts at those vertices is undefined (OpenMesh's Sqrt3T reads whatever lies beyond its
        // vector), and only level 1, where nothing else has yet mixed it in, shows it. The test
        // stands whether or not the final levels could be matched.
        const DivergenceTest valence_table = [&]() -> std::optional<Classification> {
            const CoreRun* s = core_with_reference_rule();
            std::string why;
            if (!s || s->levels().size() < 2 ||
                !beyond_valence_table(ref, req.scheme, input, s->levels()[1], trace, tolerance, why))
                return std::nullopt;
            return Classification{DivergenceClass::ValenceLimit, why};
        };

        // A Butterfly reference that reads something else than the loop's third vertex for
        // the four-point rule's outer points on a boundary loop of three edges (VTK).
        const DivergenceTest short_boundary_loops = [&]() -> std::optional<Classification> {
            if (req.scheme != Scheme::Butterfly && req.scheme != Scheme::ModifiedButterfly) return std::nullopt;
            const CoreRun* s = core_with_reference_rule();
            if (!s || s->levels().size() < 2 || trace.size() < 2) return std::nullopt;
            const std::vector<std::vector<Vec3>> mapped = levels_in_our_numbering(s->levels(), trace, run.correspondence);
            std::string why;
            if (mapped.size() < 2 || !only_short_boundary_loops_differ(ref.name(), input, s->levels()[1], mapped[1], tolerance, why))
                return std::nullopt;
            return Classification{DivergenceClass::ShortBoundaryLoop, why};
        };

        if (run.correspondence.method == MatchMethod::None) {
            if (tier == Tier::Geometric && run.hausdorff_rel <= tolerance) {
                run.verdict = Verdict::Agree;
                run.explanation = geometric_why + " (no vertex correspondence: " + run.correspondence.note + ")";
                out.runs.push_back(std::move(run));
                continue;
            }
            const PolyMesh& against = matched_to->last();
            // A float reference where a float cannot tell core's own vertices apart (far from
            // the origin, its step there larger than the mesh's details): no position can match
            // its vertices one to one, so nothing is compared, neither agreement nor divergence.
            if (ref.capabilities().precision == Precision::Float && equal_counts(against, theirs)) {
                if (const std::optional<std::string> why = float_cannot_tell_apart(against)) {
                    run.verdict = Verdict::NotCompared;
                    run.explanation = "nothing compared: " + *why + ", so " + ref.name() +
                                      "'s float result cannot be matched to it vertex for vertex (" + run.correspondence.note + ")";
                    out.runs.push_back(std::move(run));
                    made_by_run.resize(out.runs.size());
                    made_by_run.back() = made_faces(theirs, {});
                    continue;
                }
            }
            // Without a correspondence only the valence-table and topology tests of the ladder
            // can be run. With equal counts that is no measured topology difference: a rule
            // that moves vertices far (a wrong weight) breaks a match by position too.
            run.verdict = Verdict::Diverge;
            const std::string unmatched = "no vertex bijection with core's " + rule_name(req.scheme, matched_to->rule) +
                                          " refinement (" + run.correspondence.note + "); " + counts(theirs) +
                                          " against core's " + counts(against);
            DivergenceTests only_topology;
            only_topology.valence_table = valence_table;
            only_topology.nonmanifold = [&]() -> std::optional<Classification> {
                const auto core_refine = [&](const PolyMesh& m) -> std::optional<PolyMesh> {
                    try {
                        return core_implementation().refine(m, {req.scheme, run.ran_with, req.levels}).back();
                    } catch (const std::exception&) {
                        return std::nullopt;
                    }
                };
                return split_fans_handling(input, theirs, core_refine, tolerance, ref.name());
            };
            only_topology.topology = [&]() -> std::optional<Classification> {
                if (!measured_topology_difference(topology_counts(against), topology_counts(theirs), false, MatchMethod::None))
                    return std::nullopt;
                return Classification{DivergenceClass::Topology, unmatched};
            };
            only_topology.unexplained = [&] { return unmatched + ": the same counts, so not a topology difference"; };
            const Classification c = classify_divergence(only_topology);
            run.divergence_class = c.cls;
            run.explanation = c.explanation;
            out.runs.push_back(std::move(run));
            made_by_run.resize(out.runs.size());
            made_by_run.back() = made_faces(theirs, {});
            continue;
        }

        run.comparison = compare_meshes(ours, theirs, map);
        if (fvar && map_holds) {
            const auto rerun = [&](const PolyMesh& m) -> std::optional<PolyMesh> {
                IsolatedTrace again = refine_isolated(ref, m, {req.scheme, run.ran_with, req.levels, fvar}, req.timeout_seconds, req.isolate);
                if (again.outcome.status != RunStatus::Ok || !again.trace) return std::nullopt;
                return again.trace->back();
            };
            run.uv = compare_face_varying(ours, theirs, map, ref, req.scheme, *fvar, req.rule, run.ran_with, subject_name,
                                          tolerance, core,
                                          rerun, input);
            if (keep_view && run.uv->compared()) uvs_at_our_corners[ref.name()] = corner_values_in_our_order(ours, theirs, map);
        }
        if (map_holds) {
            run.level_max_rel = level_errors(*under_test, trace, run.correspondence);
            in_our_order[ref.name()] = in_our_numbering(theirs, map, ours.num_vertices());
            if (keep_view) at_each_level[ref.name()] = levels_in_our_numbering(*under_test, trace, run.correspondence);
        }
        const bool within_tier = tier == Tier::Strict      ? run.comparison.topology_equal() && run.comparison.max_abs == 0.0
                                 : tier == Tier::Geometric ? run.hausdorff_rel <= tolerance
                                                           : within_weak(run.comparison, run.level_max_rel, tolerance);
        if (within_tier) {
            run.verdict = Verdict::Agree;
            run.explanation = tier == Tier::Strict      ? std::string("bitwise identical")
                              : tier == Tier::Geometric ? geometric_why
                                                        : "max relative error " + sci(run.comparison.max_rel) + " <= " +
                                                              sci(tolerance) + (in_float ? " (float tier)" : "");
            out.runs.push_back(std::move(run));
            continue;
        }

        // The ladder (classification.h), each test measured.
        run.verdict = Verdict::Diverge;
        const std::string worst = run.comparison.worst.empty()
                                      ? ""
                                      : " (worst: our vertex " + std::to_string(run.comparison.worst[0].ours_index) +
                                            ", valence " + std::to_string(run.comparison.worst[0].valence) +
                                            (run.comparison.worst[0].boundary ? ", boundary" : ", interior") + ")";
        const bool same_faces = run.comparison.topology_equal();
        const std::string faces = counts(theirs) + " against core's " + counts(ours);
        DivergenceTests tests;
        tests.short_boundary_loops = short_boundary_loops;
        tests.isolated_vertices = [&]() -> std::optional<Classification> {
            if (!same_faces || !only_isolated_vertices_differ(ours, theirs, map, tolerance)) return std::nullopt;
            return Classification{DivergenceClass::IsolatedVertexHandling,
                                  "only vertices no face uses differ, by up to " + sci(run.comparison.max_rel) + worst};
        };
        tests.rounding = [&]() -> std::optional<Classification> {
            // Faces that differ under a match by position, which the reference's rounding may
            // have misled where vertices lie closer than it (the same rule asked and applied).
            const bool by_position = run.correspondence.method == MatchMethod::Nearest ||
                                     run.correspondence.method == MatchMethod::NearestAndFaces;
            if (!same_faces && by_position && !rules_differ)
                if (std::optional<Classification> c = rounding_among_near_vertices(ours, theirs, tolerance)) {
                    c->explanation += "; matched by position it differs by " + sci(run.comparison.max_rel) + worst;
                    return c;
                }
            const double ulps = run.comparison.max_abs / ulp_of_largest_coordinate(ours);
            if (!same_faces || !(ulps <= tolerances::kRoundingUlps)) return std::nullopt;
            return Classification{DivergenceClass::Rounding, "differs by " + sci(run.comparison.max_rel) +
                                                                 " of the diagonal, which is " + sci(ulps) +
                                                                 " ulps of the largest coordinate" + worst};
        };
        // The rule the implementation under test applies, as seen against this reference: the
        // requested one for core; of the named rules that fit a subject, the one nearest the
        // reference's (on a closed mesh both boundary rules fit, and only the weights can
        // tell them apart).
        std::optional<SchemeRule> applied_rule = subject_rule;
        if (req.subject && out.rules) applied_rule = nearest_fitting_rule(*out.rules, run.ran_with);
        std::string still;  // what core with the reference's rule still differs by, when it does
        tests.reference_rule = [&]() -> std::optional<Classification> {
            if (!applied_rule || same_rule(req.scheme, run.ran_with, *applied_rule)) return std::nullopt;
            const CoreRun* with_rule = core_with_reference_rule();
            if (!with_rule) return std::nullopt;
            const CoreRun& with = *with_rule;
            // Measured, not assumed: core re-run with the reference's rule. Whatever the tier,
            // the rule explains the divergence only if core with it equals the reference up to
            // rounding (the weak tier at its tolerance; strict would demand bits, geometric
            // would accept what the rule itself moves).
            const MeshComparison c2 = compare_meshes(with.last(), theirs, run.correspondence.ref_to_ours);
            run.max_rel_with_reference_rule = c2.max_rel;
            const std::vector<double> e2 = level_errors(with.levels(), trace, run.correspondence);
            // Far from the origin two summation orders of the same stencils differ by a few
            // ulps of the coordinates, more than a relative tolerance of a small diagonal: the
            // rule still explains the divergence within that rounding (the rounding class's bound).
            const double diagonal = bounding_box_diagonal(with.last().positions);
            const double rounding = tolerances::kRoundingUlps * ulp_of_largest_coordinate(with.last()) / (diagonal > 0 ? diagonal : 1);
            const double bar = std::max(rounding, tier == Tier::Weak ? tolerance
                                                                    : agreement_tolerance(with.last(), in_float, tolerances::kAgreementRelative,
                                                                                          in_float ? longest_sum() : 0, req.levels));
            // Two named causes at once: the rule explains every vertex a face uses, and only
            // vertices no face uses differ beyond that (a reference that moves them).
            const bool agrees_with_rule = within_weak(c2, e2, bar);
            const bool but_isolated = !agrees_with_rule && c2.topology_equal() &&
                                      only_isolated_vertices_differ(with.last(), theirs, run.correspondence.ref_to_ours, bar);
            const std::string rule = rule_name(req.scheme, *applied_rule);
            if (!agrees_with_rule && !but_isolated) {
                still = "; with " + ref.name() + "'s " + run.rule + " rule still " + sci(c2.max_rel);
                return std::nullopt;
            }
            // A rule difference explains the divergence only if the rule under test is the
            // published one: core's version of it must pass the oracle that does not read its
            // masks, at the input's interior valences too (rule_oracle.h).
            const RuleVerdict oracle = check_core_rule(req.scheme, *applied_rule, interior_valences());
            if (oracle.known && !oracle.passed) {
                still = "; " + rule + " fails its oracle: " + oracle.detail;
                return std::nullopt;
            }
            const std::string agrees =
                but_isolated ? "core with " + run.rule + " agrees at every vertex a face uses; only vertices no face uses "
                                                         "differ beyond that (isolated-vertex-handling too), by up to " +
                                   sci(c2.max_rel)
                             : "core with " + run.rule + " agrees to " + sci(c2.max_rel);
            const auto differs = [&](const char* verb) {
                return same_faces ? " " + std::string(verb) + " by " + sci(run.comparison.max_rel) + " of the diagonal" + worst
                                  : " make" + std::string(verb[std::strlen(verb) - 1] == 's' ? "s" : "") + " different faces (" + faces + ")";
            };
            const DivergenceClass cls = rule_difference_class(req.scheme, run.ran_with, *applied_rule);
            // The reference's rule differs in its triangle weights and in more: when the triangle
            // weights alone explain it (the rest changes nothing on this mesh, a boundary rule on a
            // closed one), that is the class, measured as the whole rule was.
            if (req.scheme == Scheme::CatmullClark && cls != DivergenceClass::TriangleRule &&
                run.ran_with.catmull_clark.smooth_triangles != applied_rule->catmull_clark.smooth_triangles) {
                SchemeRule triangles_only = *applied_rule;
                triangles_only.catmull_clark.smooth_triangles = run.ran_with.catmull_clark.smooth_triangles;
                const CoreRun& t = core.with(triangles_only);
                if (t.error.empty()) {
                    const MeshComparison c3 = compare_meshes(t.last(), theirs, run.correspondence.ref_to_ours);
                    if (within_weak(c3, level_errors(t.levels(), trace, run.correspondence), bar)) {
                        const std::string weights = run.ran_with.catmull_clark.smooth_triangles ? "smooth" : "catmark";
                        return Classification{DivergenceClass::TriangleRule,
                                              ref.name() + " applies the " + weights + " weights at triangles (its " + run.rule +
                                                  " rule differs from " + rule + " in nothing else this mesh shows): core with " +
                                                  rule_name(req.scheme, triangles_only) + " agrees to " + sci(c3.max_rel) +
                                                  "; " + (req.subject ? subject_name : std::string("core")) + "'s " + rule +
                                                  differs("differs")};
                    }
                }
            }
            if (req.subject)
                return Classification{cls, subject_name + " applies " + rule + ", " + ref.name() + " " + run.rule + " (" +
                                               agrees + "); they" + differs("differ")};
            const std::string effect =
                cls == DivergenceClass::TriangleRule
                    ? ref.name() + " applies the " + (run.ran_with.catmull_clark.smooth_triangles ? "smooth" : "catmark") +
                          " weights at triangles"
                : cls == DivergenceClass::CreaseRules
                    ? ref.name() + " applies Hbr's semi-sharp crease rules (" + run.rule +
                          ": a sharpness of exactly 1 stays sharp one step longer, and Chaikin's decay averages every "
                          "sharp edge beside, infinitely sharp ones too)"
                    : rule_effect(req.scheme, ref.name(), rule, run.rule, req.levels);
            return Classification{cls, effect + ": " + agrees + "; core's " + rule + differs("differs")};
        };
        tests.valence_table = valence_table;
        tests.nonmanifold = [&]() -> std::optional<Classification> {
            // Measured: core took OpenSubdiv's non-manifold rules here, and every vertex that
            // differs by more than the tolerance from core under the reference's own rule (the
            // boundary or corner rule it may lack) lies where the non-manifold vertices reach.
            if (!same_faces || !takes_nonmanifold_rules(req.scheme, req.rule) || !primal) return std::nullopt;
            // Those rules are OpenSubdiv's: where OpenSubdiv itself differs, core does not follow
            // them, and no named handling of the reference's excuses that -- save where Far's
            // walk around a vertex mistakes its two fans for one (nonmanifold.h), measured there.
            if (ref.capabilities().defines_nonmanifold_rules) {
                const std::vector<const PolyMesh*> levels = level_view(requested.levels());
                std::vector<int> accepted;
                try {
                    accepted = opensubdiv_walk_accepted_vertices(*levels.at(0));
                } catch (const InputError&) {
                    return std::nullopt;  // a level core did not take: nothing of Far's walk to measure
                }
                std::optional<Classification> c =
                    fan_walk_handling(reach_of(levels, accepted), accepted, ours, theirs,
                                      run.correspondence.ref_to_ours, tolerance, ref.name(), run.comparison.max_rel);
                if (c) c->explanation += worst;
                return c;
            }
            const bool own_rule = !applied_rule || same_rule(req.scheme, run.ran_with, *applied_rule);
            // (Measured against the requested rule when core has the reference's only for manifolds.)
            const CoreRun* with = own_rule ? nullptr : core_with_reference_rule();
            const PolyMesh& core_rule = with ? with->last() : ours;
            std::optional<Classification> c =
                nonmanifold_handling(nonmanifold_reach(level_view(requested.levels())), core_rule, theirs,
                                     run.correspondence.ref_to_ours, tolerance, ref.name(), run.comparison.max_rel,
                                     with ? " from core with " + run.rule : "");
            if (c) c->explanation += worst;
            return c;
        };
        tests.topology = [&]() -> std::optional<Classification> {
            if (same_faces || !measured_topology_difference(run.comparison.ours, run.comparison.ref, false,
                                                            run.correspondence.method))
                return std::nullopt;
            // The first face only in each, by index and corners in its own numbering.
            const auto first = [](const PolyMesh& m, int f) { return f >= 0 ? " (first: " + face_text(m, f) + ")" : std::string(); };
            return Classification{DivergenceClass::Topology,
                                  "refined topology differs: " + faces + "; " + std::to_string(run.comparison.faces_only_in_ref) +
                                      " faces only in " + ref.name() + first(theirs, run.comparison.first_face_only_in_ref) +
                                      ", " + std::to_string(run.comparison.faces_only_in_ours) + " only in core" +
                                      first(ours, run.comparison.first_face_only_in_ours)};
        };
        tests.unexplained = [&] {
            if (!same_faces)
                return faces + "; the face sets differ only under a match by position (" +
                       to_string(run.correspondence.method) + "), which a vertex moved far breaks: not a topology difference";
            if (req.subject && !subject_rule)
                return subject_name + " follows no named rule; differs by " + sci(run.comparison.max_rel) + worst;
            if (!rules_differ) return "same rules, differs by " + sci(run.comparison.max_rel) + worst;
            return "differs by " + sci(run.comparison.max_rel) + worst + (still.empty() ? no_same_rule : still);
        };
        const Classification found = classify_divergence(tests);
        run.divergence_class = found.cls;
        run.explanation = found.explanation;
        out.runs.push_back(std::move(run));
        made_by_run.resize(out.runs.size());
        if (!same_faces) made_by_run.back() = made_faces(theirs, map);
    }
    require_shared_topology(out.runs, made_by_run, subject_name);

    for (size_t i = 0; i < out.runs.size(); ++i) {
        if (!changed[i]) continue;
        RefinementRun& run = out.runs[i];
        // Past a weight table (or for the missing outer point of a short boundary loop) it reads
        // what lies beyond its vector, which may be this process's data that no fill reaches: a
        // second run may or may not change it, and the verdict would flip from suite to suite.
        // The class already says that what it reads there is not the input's.
        if (run.divergence_class == DivergenceClass::ValenceLimit || run.divergence_class == DivergenceClass::ShortBoundaryLoop) {
            run.explanation += "; run again with its heap filled otherwise, " + *changed[i];
            continue;
        }
        run.verdict = Verdict::RefNondeterministic;
        if (run.divergence_class == DivergenceClass::Unexplained) run.divergence_class = DivergenceClass::None;
        run.explanation = run.reference + " gives another result when run again on the same input with its heap filled "
                          "otherwise (it reads memory it never wrote, or depends on more than its input): " + *changed[i] +
                          "; the first run: " + run.explanation;
    }

    const RefinementRun* worst_run = nullptr;
    for (const RefinementRun& r : out.runs)
        if (r.verdict == Verdict::Diverge && !r.comparison.worst.empty() &&
            (!worst_run || r.comparison.worst[0].distance > worst_run->comparison.worst[0].distance))
            worst_run = &r;
    // The texture coordinates' worst corner among the references that diverge on them.
    const FaceVaryingRun* worst_uv = nullptr;
    for (const RefinementRun& r : out.runs)
        if (r.uv && r.uv->compared() && r.uv->outcome.verdict == Verdict::Diverge &&
            (!worst_uv || r.uv->comparison.max_rel > worst_uv->comparison.max_rel))
            worst_uv = &*r.uv;
    const bool diverges =
        worst_uv ||
        std::any_of(out.runs.begin(), out.runs.end(), [](const RefinementRun& r) { return r.verdict == Verdict::Diverge; });
    if (diverges && keep_view) {
        DivergenceView& view = out.view.emplace();
        view.levels.assign(under_test->begin(), under_test->end());
        view.births = requested.refinement.births;
        view.references = std::move(at_each_level);
        view.reference_uvs = std::move(uvs_at_our_corners);
        if (worst_uv)
            view.uv_worst_corner = ours.face_start[static_cast<size_t>(worst_uv->comparison.worst_face)] +
                                   worst_uv->comparison.worst_corner;
    }
    if (worst_run) {
        const WorstVertex& w = worst_run->comparison.worst[0];
        out.worst_vertex = CaseWorstVertex{w.ours_index, w.valence, w.boundary, w.ours, std::nullopt, {}};
        if (req.subject && numbered_as == &requested)
            out.worst_vertex->core_with_requested_rule = requested.last().positions[static_cast<size_t>(w.ours_index)];
        for (const auto& [reference, positions] : in_our_order)
            out.worst_vertex->reference_positions[reference] = positions[static_cast<size_t>(w.ours_index)];
    }
    return out;
}

namespace {

nlohmann::json subject_json(const RefinementComparison& c) {
    using nlohmann::json;
    auto fits = [&](const std::vector<RuleFit>& list) {
        json a = json::array();
        for (const RuleFit& f : list) a.push_back({{"rule", f.name}, {"max_rel", finite_or_null(f.max_rel)}, {"fits", f.fits}});
        return a;
    };
    json s = {{"name", c.subject},
              {"status", to_string(c.subject_outcome.status)},
              {"status_message", c.subject_outcome.message},
              {"seconds", c.subject_outcome.seconds},
              {"unmatched", c.subject_unmatched},
              {"topology", c.subject_topology}};
    if (c.subject_outcome.status == RunStatus::Ok)
        s["match"] = {{"method", to_string(c.subject_match.method)}, {"note", c.subject_match.note}};
    if (c.rules) {
        json rows = json::array();
        for (const VertexClassRow& r : c.rules->rows)
            rows.push_back({{"class", to_string(r.cls)}, {"valence", r.valence}, {"count", r.count},
                            {"worst_vertex", r.worst_vertex}, {"fits", fits(r.fits)}});
        s["rules"] = {{"classified_level", c.rules->classified_level},
                      {"rule", c.rules->rule ? json(rule_name(c.scheme, *c.rules->rule)) : json(nullptr)},
                      {"whole", fits(c.rules->whole)},
                      {"classes", rows}};
        json others = json::array();
        for (const OtherSchemeFit& f : c.rules->other_schemes)
            others.push_back({{"scheme", to_string(f.scheme)}, {"rule", f.rule}, {"max_rel", finite_or_null(f.max_rel)}, {"fits", f.fits}});
        s["rules"]["other_schemes"] = others;
    }
    if (c.uv_rules) {
        json rows = json::array();
        for (const UvClassFit& r : c.uv_rules->rows) {
            json fits = json::array();
            for (size_t k = 0; k < r.max_rel.size(); ++k)
                fits.push_back({{"rule", to_string(kFaceVaryingRules[k])}, {"max_rel", finite_or_null(r.max_rel[k])},
                                {"fits", r.max_rel[k] <= c.uv_rules->tolerance}});
            rows.push_back({{"class", to_string(r.cls)}, {"corners", r.corners}, {"worst_corner", r.worst_corner}, {"fits", fits}});
        }
        json whole = json::array();
        for (size_t k = 0; k < c.uv_rules->whole.size(); ++k)
            whole.push_back({{"rule", to_string(kFaceVaryingRules[k])}, {"max_rel", finite_or_null(c.uv_rules->whole[k])},
                             {"fits", c.uv_rules->whole[k] <= c.uv_rules->tolerance}});
        s["uv_rules"] = {{"rule", c.uv_rules->rule ? json(to_string(*c.uv_rules->rule)) : json(nullptr)},
                         {"summary", c.uv_rules->summary()},
                         {"whole", whole},
                         {"classes", rows}};
    }
    return s;
}

}  // namespace

nlohmann::json to_json(const RefinementComparison& c) {
    using nlohmann::json;
    auto loop_options = [](const SchemeRule& r) {
        return json{{"weights", std::string(to_string(r.loop.weights))}, {"boundary", std::string(to_string(r.loop.boundary))}};
    };
    auto topo = [](const TopologyCounts& t) {
        return json{{"vertices", t.vertices}, {"edges", t.edges}, {"faces", t.faces}, {"euler", t.euler},
                    {"boundary_loops", t.boundary_loops}};
    };
    auto vec = [](const Vec3& v) { return json::array({v.x(), v.y(), v.z()}); };
    json worst = nullptr;
    if (c.worst_vertex) {
        json at = json::object();
        for (const auto& [name, p] : c.worst_vertex->reference_positions) at[name] = p.allFinite() ? vec(p) : json(nullptr);
        worst = {{"ours_index", c.worst_vertex->ours_index}, {"valence", c.worst_vertex->valence},
                 {"boundary", c.worst_vertex->boundary}, {"core", vec(c.worst_vertex->core)}, {"references", at}};
        if (c.worst_vertex->core_with_requested_rule) {
            // The subject's value under "subject"; "core" is then core's with the requested rule.
            worst["subject"] = worst["core"];
            worst["core"] = vec(*c.worst_vertex->core_with_requested_rule);
        }
    }
    json runs = json::array();
    for (const RefinementRun& r : c.runs) {
        json worst_list = json::array();
        for (const WorstVertex& w : r.comparison.worst)
            worst_list.push_back({{"ours_index", w.ours_index}, {"ref_index", w.ref_index}, {"valence", w.valence},
                                  {"boundary", w.boundary}, {"ours", vec(w.ours)}, {"ref", vec(w.ref)}, {"distance", w.distance}});
        json run = {{"reference", r.reference},
                    {"version", r.version},
                    {"rule", r.rule},
                    {"status", to_string(r.outcome.status)},
                    {"status_message", r.outcome.message},
                    {"seconds", r.outcome.seconds},
                    {"verdict", to_string(r.verdict)},
                    {"divergence_class", to_string(r.divergence_class)},
                    {"explanation", r.explanation}};
        if (c.scheme == Scheme::Loop) run["ran_with"] = loop_options(r.ran_with);
        if (r.uv) {
            json uv = {{"compared", r.uv->compared()}, {"not_compared", r.uv->not_compared}};
            if (r.uv->compared()) {
                uv["verdict"] = to_string(r.uv->outcome.verdict);
                uv["divergence_class"] = to_string(r.uv->outcome.cls);
                uv["explanation"] = r.uv->explanation;
                uv["corners"] = r.uv->comparison.corners;
                uv["max_abs"] = finite_or_null(r.uv->comparison.max_abs);
                uv["max_rel"] = finite_or_null(r.uv->comparison.max_rel);
                uv["uv_box"] = r.uv->comparison.uv_box;
                if (r.uv->follows) {
                    uv["follows"] = std::string(to_string(*r.uv->follows));
                    uv["who_follows"] = r.uv->who_follows;
                }
                if (!r.uv->worst_class.empty()) uv["worst_class"] = r.uv->worst_class;
            }
            run["uv"] = uv;
        }
        if (!std::isnan(r.hausdorff_rel)) run["hausdorff_rel"] = finite_or_null(r.hausdorff_rel);
        if (r.outcome.status == RunStatus::Ok && c.core_error.empty()) {
            run["match"] = {{"method", to_string(r.correspondence.method)}, {"note", r.correspondence.note}};
            if (r.correspondence.method != MatchMethod::None) {
                run["topology"] = {{"core", topo(r.comparison.ours)},
                                   {"reference", topo(r.comparison.ref)},
                                   {"face_sets_equal", r.comparison.face_sets_equal},
                                   {"faces_only_in_core", r.comparison.faces_only_in_ours},
                                   {"faces_only_in_reference", r.comparison.faces_only_in_ref}};
                json levels = json::array();
                for (double e : r.level_max_rel) levels.push_back(finite_or_null(e));
                run["positions"] = {{"diagonal", r.comparison.diagonal},  {"max_abs", finite_or_null(r.comparison.max_abs)},
                                    {"rms_abs", finite_or_null(r.comparison.rms_abs)}, {"max_rel", finite_or_null(r.comparison.max_rel)},
                                    {"rms_rel", finite_or_null(r.comparison.rms_rel)}, {"level_max_rel", levels},
                                    {"max_rel_with_reference_rule", finite_or_null(r.max_rel_with_reference_rule)},
                                    {"worst", worst_list}};
            }
        }
        runs.push_back(run);
    }
    json out = {{"input", c.input},
                {"input_vertices", c.input_vertices},
                {"input_faces", c.input_faces},
                {"input_statistics", statistics_json(c.input_statistics)},
                {"scheme", to_string(c.scheme)},
                {"rule", c.rule_name},
                {"levels", c.levels},
                {"core_seconds", c.core_seconds},
                {"tier", to_string(c.tier)},
                {"tolerance_rel", finite_or_null(c.tolerance)},
                {"core_error", c.core_error},
                {"all_agree", c.all_agree()},
                {"runs", runs},
                {"worst_vertex", worst}};
    if (c.scheme == Scheme::Loop) out["options"] = loop_options(c.rule);
    if (c.face_varying) out["face_varying"] = std::string(to_string(*c.face_varying));
    if (!c.notes.empty()) out["notes"] = c.notes;
    if (c.subject != "core") out["subject"] = subject_json(c);
    return out;
}

}  // namespace crossdiv::verification
