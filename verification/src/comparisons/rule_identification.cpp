#include "crossdiv/verification/comparisons/rule_identification.h"

#include <algorithm>
#include <cmath>

#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/nonmanifold.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/implementations/registry.h"
#include "harness/sci.h"

namespace crossdiv::verification {
namespace {

using detail::sci;

/// The vertices of `parent` OpenSubdiv's non-manifold rules treat apart (nonmanifold.h), or
/// none when the mesh is one no rule refines (a face naming a vertex twice).
std::vector<char> nonmanifold_flags(const PolyMesh& parent) {
    std::vector<char> flags(static_cast<size_t>(parent.num_vertices()), 0);
    try {
        for (int v : nonmanifold_vertices(parent)) flags[static_cast<size_t>(v)] = 1;
    } catch (const InputError&) {
    }
    return flags;
}

/// The class of each vertex of level l from its birth and level l-1's topology.
std::vector<std::pair<VertexClass, int>> classify(const std::vector<VertexBirth>& births, const PolyMesh& parent) {
    const MeshTopology t = mesh_topology(parent);
    const std::vector<char> nonmanifold = nonmanifold_flags(parent);
    std::vector<int> faces_of(static_cast<size_t>(parent.num_vertices()), 0);
    for (int v : parent.face_vertices) ++faces_of[static_cast<size_t>(v)];
    // Each edge's faces, counted by its directed key: an edge is on the boundary with one
    // face, and manifold with two that traverse it in opposite directions.
    std::vector<std::array<int, 2>> half_edges;
    for (int f = 0; f < parent.num_faces(); ++f) {
        const int* fv = parent.face(f);
        const int n = parent.face_size(f);
        for (int k = 0; k < n; ++k) half_edges.push_back({fv[k], fv[(k + 1) % n]});
    }
    std::sort(half_edges.begin(), half_edges.end());
    auto directed = [&](int a, int b) {
        const auto range = std::equal_range(half_edges.begin(), half_edges.end(), std::array<int, 2>{a, b});
        return static_cast<int>(range.second - range.first);
    };
    // The tags: each sharp edge once as (smaller, larger), and at each vertex its sharp edges
    // and whether it is tagged a corner.
    std::vector<std::array<int, 2>> sharp;
    std::vector<int> sharp_at(static_cast<size_t>(parent.num_vertices()), 0);
    std::vector<char> corner_tag(static_cast<size_t>(parent.num_vertices()), 0);
    for (const SharpEdge& e : parent.creases.edges) {
        if (!(e.sharpness > 0)) continue;
        sharp.push_back({std::min(e.a, e.b), std::max(e.a, e.b)});
    }
    std::sort(sharp.begin(), sharp.end());
    sharp.erase(std::unique(sharp.begin(), sharp.end()), sharp.end());
    for (const auto& [a, b] : sharp) ++sharp_at[static_cast<size_t>(a)], ++sharp_at[static_cast<size_t>(b)];
    for (const SharpVertex& v : parent.creases.vertices) corner_tag[static_cast<size_t>(v.v)] |= v.sharpness > 0;
    const auto is_sharp = [&](int a, int b) {
        return std::binary_search(sharp.begin(), sharp.end(), std::array<int, 2>{std::min(a, b), std::max(a, b)});
    };
    std::vector<std::pair<VertexClass, int>> out;
    out.reserve(births.size());
    for (const VertexBirth& o : births) {
        if (o.kind == VertexBirth::Kind::Face) {
            out.push_back({VertexClass::FacePoint, parent.face_size(o.a)});
            continue;
        }
        if (o.kind == VertexBirth::Kind::Edge) {
            const int ab = directed(o.a, o.b), ba = directed(o.b, o.a);
            out.push_back({ab + ba == 1                          ? VertexClass::BoundaryEdgePoint
                           : !(ab == 1 && ba == 1)               ? VertexClass::NonManifoldEdgePoint
                           : is_sharp(o.a, o.b)                  ? VertexClass::CreaseEdgePoint
                                                                 : VertexClass::InteriorEdgePoint,
                           0});
            continue;
        }
        const size_t v = static_cast<size_t>(o.a);
        const bool boundary = t.boundary_vertex[v];
        // Boundary edges are sharp to OpenSubdiv: a boundary vertex with a sharp edge inside
        // has three.
        const int sharp_edges = sharp_at[v] + (boundary ? 2 : 0);
        if (faces_of[v] == 0) out.push_back({VertexClass::IsolatedVertex, 0});
        else if (nonmanifold[v]) out.push_back({VertexClass::NonManifoldVertex, 0});
        else if (corner_tag[v] || (sharp_at[v] > 0 && sharp_edges >= 3)) out.push_back({VertexClass::SharpCorner, 0});
        else if (!boundary && sharp_edges == 2) out.push_back({VertexClass::CreaseVertex, 0});
        else if (!boundary && sharp_edges == 1) out.push_back({VertexClass::Dart, t.valence[v]});
        else if (!boundary) out.push_back({VertexClass::InteriorVertex, t.valence[v]});
        else if (faces_of[v] == 1) out.push_back({VertexClass::Corner, 0});
        else out.push_back({VertexClass::BoundaryVertex, 0});
    }
    return out;
}

/// The classes of Doo-Sabin's level 1 of `parent` with `count` vertices: core makes corner c's
/// point row c, then the Chaikin points of the boundary edges (chaikin-boundary). Empty when
/// the level has fewer vertices than corners.
std::vector<std::pair<VertexClass, int>> doo_sabin_classes(const PolyMesh& parent, int count) {
    const int corners = static_cast<int>(parent.face_vertices.size());
    if (count < corners) return {};
    const MeshTopology t = mesh_topology(parent);
    std::vector<std::pair<VertexClass, int>> out;
    out.reserve(static_cast<size_t>(count));
    for (int f = 0; f < parent.num_faces(); ++f)
        for (int k = 0; k < parent.face_size(f); ++k)
            out.push_back({t.boundary_vertex[static_cast<size_t>(parent.face(f)[k])] ? VertexClass::BoundaryCornerPoint
                                                                                      : VertexClass::CornerPoint,
                           parent.face_size(f)});
    out.resize(static_cast<size_t>(count), {VertexClass::BoundaryEdgePoint, 0});
    return out;
}

/// sqrt3's level 1 as births: the old vertices, then one point per face (the boundary waits
/// at the first step, under either parity rule); empty when the count is not that.
std::vector<VertexBirth> sqrt3_births(const PolyMesh& parent, int count) {
    if (count != parent.num_vertices() + parent.num_faces()) return {};
    std::vector<VertexBirth> out;
    for (int v = 0; v < parent.num_vertices(); ++v) out.push_back({VertexBirth::Kind::Vertex, v, -1});
    for (int f = 0; f < parent.num_faces(); ++f) out.push_back({VertexBirth::Kind::Face, f, -1});
    return out;
}

/// The distance, relative to `diagonal`, under which a subject fits a rule at `level`: the
/// agreement tolerance, or, far from the origin, the rounding of two summation orders of the
/// same stencils (tolerances::kRoundingUlps of the largest coordinate), as the ladder's
/// rounding class allows it: a subject that differs from core by that much follows the rule.
double fit_threshold(const PolyMesh& level, double diagonal, double tolerance) {
    const double rounding = tolerances::kRoundingUlps * ulp_of_largest_coordinate(level) / (diagonal > 0 ? diagonal : 1);
    return std::max(tolerance, rounding);
}

/// A vertex's birth as one sortable key: its kind, then its vertex, edge (ends ascending) or face.
std::array<int, 3> birth_key(const VertexBirth& b) {
    if (b.kind == VertexBirth::Kind::Edge) return {1, std::min(b.a, b.b), std::max(b.a, b.b)};
    return {b.kind == VertexBirth::Kind::Vertex ? 0 : 2, b.a, -1};
}

/// The largest distance over the diagonal between the subject's level 1 (in the numbering of
/// `births`) and `theirs`, whose vertices were born as `their_births`; INFINITY when a vertex
/// has no counterpart of the same birth.
double level_one_distance(const PolyMesh& subject, const std::vector<VertexBirth>& births, const PolyMesh& theirs,
                          const std::vector<VertexBirth>& their_births) {
    if (their_births.size() != births.size() || theirs.num_vertices() != subject.num_vertices()) return INFINITY;
    std::vector<std::pair<std::array<int, 3>, int>> index;
    index.reserve(their_births.size());
    for (size_t v = 0; v < their_births.size(); ++v) index.push_back({birth_key(their_births[v]), static_cast<int>(v)});
    std::sort(index.begin(), index.end());
    const double d = bounding_box_diagonal(theirs.positions);
    double worst = 0;
    for (size_t v = 0; v < births.size(); ++v) {
        const auto key = birth_key(births[v]);
        const auto it = std::lower_bound(index.begin(), index.end(), std::pair{key, -1});
        if (it == index.end() || it->first != key) return INFINITY;
        const double e = (subject.positions[v] - theirs.positions[static_cast<size_t>(it->second)]).norm() / (d > 0 ? d : 1);
        worst = std::isnan(e) ? INFINITY : std::max(worst, e);
    }
    return worst;
}

/// The schemes whose refinement has the connectivity of `scheme`'s (itself excluded).
std::vector<Scheme> same_connectivity(Scheme scheme) {
    const std::vector<Scheme> triangle_split{Scheme::Loop, Scheme::Butterfly, Scheme::ModifiedButterfly, Scheme::Midpoint};
    const std::vector<Scheme> quad_split{Scheme::CatmullClark, Scheme::Bilinear};
    for (const auto& family : {triangle_split, quad_split})
        if (std::find(family.begin(), family.end(), scheme) != family.end()) {
            std::vector<Scheme> out;
            for (Scheme s : family)
                if (s != scheme) out.push_back(s);
            return out;
        }
    return {};
}

/// The rules of the other schemes with `scheme`'s connectivity, and midpoint averaging where
/// no such scheme has it, each measured against the subject's level 1.
std::vector<OtherSchemeFit> fit_other_schemes(Scheme scheme, const PolyMesh& input, const PolyMesh& subject,
                                              const std::vector<VertexBirth>& births, double tolerance) {
    std::vector<OtherSchemeFit> out;
    // Core's level 1 of `mesh` under (s, r) against the subject's, matched by birth; nothing
    // measured where core refuses the input under it (a tag the Butterflies lack).
    const auto measure = [&](const PolyMesh& mesh, Scheme s, const SchemeRule& r, std::string label) {
        OtherSchemeFit fit{s, std::move(label), INFINITY, false};
        try {
            const Refinement ref = core_implementation().refine_with_provenance(mesh, {s, r, 1});
            if (ref.levels.size() > 1 && !ref.births.empty()) {
                fit.max_rel = level_one_distance(subject, births, ref.levels[1], ref.births[0]);
                fit.fits = fit.max_rel <= fit_threshold(ref.levels[1], bounding_box_diagonal(ref.levels[1].positions), tolerance);
            }
        } catch (const std::exception&) {
        }
        out.push_back(fit);
    };
    if (!input.creases.empty()) {
        // A program that reads past the 't' lines it is given refines the mesh as if untagged.
        PolyMesh untagged = input;
        untagged.creases = {};
        for (const SchemeRule& r : named_rules(scheme)) measure(untagged, scheme, r, rule_name(scheme, r) + ", tags ignored");
    }
    const std::vector<Scheme> others = same_connectivity(scheme);
    for (Scheme other : others)
        for (const SchemeRule& r : named_rules(other)) measure(input, other, r, rule_name(other, r));
    const auto linear = [](Scheme s) { return s == Scheme::Bilinear || s == Scheme::Midpoint; };
    if (std::none_of(others.begin(), others.end(), linear) && !linear(scheme)) {
        // Midpoint averaging on this connectivity: each point the average of what it was born from.
        PolyMesh midpoint = subject;
        for (size_t v = 0; v < births.size(); ++v) {
            const VertexBirth& b = births[v];
            if (b.kind == VertexBirth::Kind::Vertex) {
                midpoint.positions[v] = input.positions[static_cast<size_t>(b.a)];
            } else if (b.kind == VertexBirth::Kind::Edge) {
                midpoint.positions[v] = 0.5 * (input.positions[static_cast<size_t>(b.a)] + input.positions[static_cast<size_t>(b.b)]);
            } else {
                Vec3 sum = Vec3::Zero();
                const int n = input.face_size(b.a);
                for (int k = 0; k < n; ++k) sum += input.positions[static_cast<size_t>(input.face(b.a)[k])];
                midpoint.positions[v] = sum / n;
            }
        }
        OtherSchemeFit fit{Scheme::Bilinear, "midpoint", level_one_distance(subject, births, midpoint, births), false};
        fit.fits = fit.max_rel <= fit_threshold(midpoint, bounding_box_diagonal(midpoint.positions), tolerance);
        out.push_back(fit);
    }
    return out;
}

}  // namespace

std::string OtherSchemeFit::label() const {
    if (rule == "midpoint") return std::string(to_string(scheme)) + " (midpoint)";
    // A scheme of one rule is named alone ("midpoint", not "midpoint linear").
    if (rule == "linear") return to_string(scheme);
    return std::string(to_string(scheme)) + " " + rule;
}

bool OtherSchemeFit::tags_ignored() const { return rule.ends_with(", tags ignored"); }

std::string OtherSchemeFit::family() const {
    return std::string(to_string(scheme)) + (tags_ignored() ? "/untagged" : "") + (rule == "midpoint" ? "/midpoint" : "");
}

const OtherSchemeFit* RuleIdentification::other_scheme() const {
    for (const OtherSchemeFit& f : other_schemes)
        if (f.fits) return &f;
    return nullptr;
}

const char* to_string(VertexClass cls) {
    switch (cls) {
        case VertexClass::InteriorVertex: return "interior-vertex";
        case VertexClass::BoundaryVertex: return "boundary-vertex";
        case VertexClass::Corner: return "corner";
        case VertexClass::InteriorEdgePoint: return "interior-edge-point";
        case VertexClass::BoundaryEdgePoint: return "boundary-edge-point";
        case VertexClass::FacePoint: return "face-point";
        case VertexClass::IsolatedVertex: return "isolated-vertex";
        case VertexClass::NonManifoldVertex: return "non-manifold-vertex";
        case VertexClass::NonManifoldEdgePoint: return "non-manifold-edge-point";
        case VertexClass::CreaseVertex: return "crease-vertex";
        case VertexClass::Dart: return "dart";
        case VertexClass::SharpCorner: return "sharp-corner";
        case VertexClass::CreaseEdgePoint: return "crease-edge-point";
        case VertexClass::CornerPoint: return "corner-point";
        case VertexClass::BoundaryCornerPoint: return "boundary-corner-point";
    }
    return "unknown";
}

std::vector<SchemeRule> named_rules(Scheme scheme) {
    const SchemeSupport* support = core_implementation().support(scheme);
    return support ? support->rules : std::vector<SchemeRule>{};
}

RuleIdentification identify_rule(Scheme scheme, const PolyMesh& input, const std::vector<PolyMesh>& subject,
                                 const std::vector<std::vector<PolyMesh>>& core,
                                 const std::vector<std::vector<VertexBirth>>& births, const SchemeRule& requested,
                                 double tolerance) {
    const std::vector<SchemeRule> rules = named_rules(scheme);
    RuleIdentification id;
    id.scheme = scheme;
    const auto fit_of = [&](size_t r) { return RuleFit{rules[r], rule_name(scheme, rules[r]), 0, false}; };
    // Whole mesh, every compared level. A named rule may make another vertex count (a
    // Doo-Sabin border dropped, sqrt3's other parity) or none at all (core refuses the input
    // under it: midpoint-average on a tagged mesh): it does not fit.
    const auto comparable = [&](size_t r, size_t l) {
        return l < core[r].size() && core[r][l].num_vertices() == subject[l].num_vertices();
    };
    for (size_t r = 0; r < rules.size(); ++r) {
        RuleFit fit = fit_of(r);
        fit.fits = true;
        for (size_t l = 0; l < subject.size(); ++l) {
            if (subject[l].num_vertices() == 0) continue;
            if (!comparable(r, l)) {
                fit.max_rel = INFINITY;
                fit.fits = false;
                continue;
            }
            const PolyMesh& c = core[r][l];
            const double d = bounding_box_diagonal(c.positions);
            double level_max = 0;
            for (size_t v = 0; v < c.positions.size(); ++v) {
                const double e = (subject[l].positions[v] - c.positions[v]).norm() / (d > 0 ? d : 1);
                level_max = std::isnan(e) ? INFINITY : std::max(level_max, e);
            }
            fit.max_rel = std::max(fit.max_rel, level_max);
            fit.fits = fit.fits && level_max <= fit_threshold(c, d, tolerance);
        }
        id.whole.push_back(fit);
    }
    for (const RuleFit& f : id.whole)
        if (f.fits && same_rule(scheme, f.rule, requested)) id.rule = f.rule;
    for (const RuleFit& f : id.whole)
        if (f.fits && !id.rule) id.rule = f.rule;

    // Classes at level 1, the only level whose vertices see the rule of their class alone.
    if (subject.empty() || subject[0].num_vertices() == 0) return id;
    const bool primal = !births.empty() && !births[0].empty();
    std::vector<std::pair<VertexClass, int>> cls;
    if (primal) cls = classify(births[0], input);
    else if (scheme == Scheme::DooSabin) cls = doo_sabin_classes(input, subject[0].num_vertices());
    else if (scheme == Scheme::Sqrt3)
        if (const std::vector<VertexBirth> b = sqrt3_births(input, subject[0].num_vertices()); !b.empty()) cls = classify(b, input);
    if (cls.empty()) return id;
    id.classified_level = 1;
    // The diagonal of core's level 1 under the first rule core refines the input with.
    size_t first = 0;
    while (first + 1 < rules.size() && core[first].empty()) ++first;
    const double d = bounding_box_diagonal(core[first].empty() ? subject[0].positions : core[first][0].positions);
    for (size_t v = 0; v < cls.size(); ++v) {
        auto row = std::find_if(id.rows.begin(), id.rows.end(), [&](const VertexClassRow& x) {
            return x.cls == cls[v].first && x.valence == cls[v].second;
        });
        if (row == id.rows.end()) {
            VertexClassRow fresh{cls[v].first, cls[v].second, 0, {}, -1};
            for (size_t r = 0; r < rules.size(); ++r) fresh.fits.push_back(fit_of(r));
            id.rows.push_back(fresh);
            row = id.rows.end() - 1;
        }
        ++row->count;
        for (size_t r = 0; r < rules.size(); ++r) {
            if (!comparable(r, 0)) {
                row->fits[r].max_rel = INFINITY;
                continue;
            }
            const double e = (subject[0].positions[v] - core[r][0].positions[v]).norm() / (d > 0 ? d : 1);
            row->fits[r].max_rel = std::isnan(e) ? INFINITY : std::max(row->fits[r].max_rel, e);
        }
    }
    for (VertexClassRow& row : id.rows)
        for (size_t r = 0; r < rules.size(); ++r)
            row.fits[r].fits = comparable(r, 0) && row.fits[r].max_rel <= fit_threshold(core[r][0], d, tolerance);
    // Each row's worst vertex under its best rule, for the diagnosis of what no rule fits.
    for (VertexClassRow& row : id.rows) {
        const auto best = std::min_element(row.fits.begin(), row.fits.end(),
                                           [](const RuleFit& a, const RuleFit& b) { return a.max_rel < b.max_rel; });
        const size_t r = static_cast<size_t>(best - row.fits.begin());
        double worst = -1;
        if (!comparable(r, 0)) continue;
        for (size_t v = 0; v < cls.size(); ++v) {
            if (cls[v].first != row.cls || cls[v].second != row.valence) continue;
            const double e = (subject[0].positions[v] - core[r][0].positions[v]).norm();
            if (!(e <= worst)) {
                worst = e;
                row.worst_vertex = static_cast<int>(v);
            }
        }
    }
    std::sort(id.rows.begin(), id.rows.end(), [](const VertexClassRow& a, const VertexClassRow& b) {
        return std::pair{a.cls, a.valence} < std::pair{b.cls, b.valence};
    });
    if (!id.rule && primal) id.other_schemes = fit_other_schemes(scheme, input, subject[0], births[0], tolerance);
    return id;
}

std::optional<SchemeRule> nearest_fitting_rule(const RuleIdentification& id, const SchemeRule& other) {
    std::optional<SchemeRule> best;
    int best_score = -1;
    for (const RuleFit& f : id.whole) {
        if (!f.fits) continue;
        // The same rule first; then (Loop) the same weights before the same boundary rule;
        // then (the other schemes) the most options in common, so that on a closed mesh, where
        // boundary rules coincide, the reference's boundary rule is kept and only the rule that
        // matters is named.
        const SchemeRule& r = f.rule;
        int score = 0;
        if (same_rule(id.scheme, r, other)) score = 10;
        else if (id.scheme == Scheme::Loop) score = r.loop.weights == other.loop.weights ? 2 : r.loop.boundary == other.loop.boundary;
        else if (id.scheme == Scheme::CatmullClark)
            score = (r.catmull_clark.boundary == other.catmull_clark.boundary) + (r.catmull_clark.vertex == other.catmull_clark.vertex) +
                    (r.catmull_clark.smooth_triangles == other.catmull_clark.smooth_triangles);
        else if (id.scheme == Scheme::DooSabin)
            score = (r.doo_sabin.boundary == other.doo_sabin.boundary) + (r.doo_sabin.weights == other.doo_sabin.weights);
        if (score > best_score) {
            best = f.rule;
            best_score = score;
        }
    }
    return best;
}

void RuleTally::add(const RuleIdentification& id) {
    if (!id.other_schemes.empty()) {
        ++other_tried_;
        for (const OtherSchemeFit& f : id.other_schemes) {
            if (!f.fits) continue;
            const std::string label = f.label();
            auto it = std::find_if(other_fits_.begin(), other_fits_.end(), [&](const OtherFit& o) { return o.label == label; });
            if (it == other_fits_.end()) other_fits_.push_back({label, f.family(), 1});
            else ++it->inputs;
        }
    }
    const size_t n = named_rules(scheme_).size();
    if (whole_fits_.empty()) {
        whole_fits_.assign(n, 0);
        whole_max_.assign(n, 0);
    }
    ++inputs_;
    for (size_t r = 0; r < id.whole.size(); ++r) {
        if (id.whole[r].fits) {
            ++whole_fits_[r];
            whole_max_[r] = std::max(whole_max_[r], id.whole[r].max_rel);
        }
    }
    for (const VertexClassRow& row : id.rows) {
        const Key key{row.cls, row.valence};
        auto it = std::find_if(rows_.begin(), rows_.end(), [&](const Tally& t) { return t.key == key; });
        if (it == rows_.end()) {
            rows_.push_back({key, 0, 0, std::vector<double>(n, 0.0), std::vector<char>(n, 1)});
            it = rows_.end() - 1;
        }
        ++it->inputs;
        it->count += row.count;
        for (size_t r = 0; r < row.fits.size(); ++r) {
            it->max_rel[r] = std::max(it->max_rel[r], row.fits[r].max_rel);
            it->fits[r] = it->fits[r] && row.fits[r].fits;
        }
    }
}

std::string RuleTally::other_scheme_phrase() const {
    if (other_fits_.empty()) return "";
    // Rules a closed mesh cannot tell apart fit together: one per scheme (and per tags
    // ignored or not), the one that fits the most inputs, with how many others fit as often.
    std::vector<std::pair<std::string, int>> shown;  // label, how many more fit as often
    std::vector<int> inputs_of;
    std::vector<std::string> families;
    for (const OtherFit& o : other_fits_) {
        const auto at = std::find(families.begin(), families.end(), o.family);
        if (at == families.end()) {
            families.push_back(o.family);
            shown.push_back({o.label, 0});
            inputs_of.push_back(o.inputs);
            continue;
        }
        const size_t k = static_cast<size_t>(at - families.begin());
        if (o.inputs > inputs_of[k]) {
            shown[k] = {o.label, 0};
            inputs_of[k] = o.inputs;
        } else if (o.inputs == inputs_of[k]) {
            ++shown[k].second;
        }
    }
    std::string s;
    for (size_t k = 0; k < shown.size(); ++k)
        s += (s.empty() ? "" : ", ") + shown[k].first + " on " + std::to_string(inputs_of[k]) + " of " +
             std::to_string(other_tried_) + " inputs" +
             (shown[k].second ? " (and " + std::to_string(shown[k].second) + " other rules of it alike)" : "");
    return ", and at level 1 it is " + s;
}

std::string RuleTally::rule_phrase() const {
    if (scheme_ == Scheme::Loop) return loop_phrase() + other_scheme_phrase();
    // Another scheme: the named rules that fit every input's whole mesh, and the classes no
    // named rule fits.
    const std::vector<SchemeRule> rules = named_rules(scheme_);
    std::vector<std::string> parts;
    std::string fitting;
    for (size_t r = 0; r < rules.size() && r < whole_fits_.size(); ++r)
        if (whole_fits_[r] == inputs_ && inputs_ > 0) fitting += (fitting.empty() ? "" : " or ") + rule_name(scheme_, rules[r]);
    if (!fitting.empty()) {
        parts.push_back("the " + fitting + " rule");
    } else {
        // The rule that fits the most inputs, and on how many: a subject that follows a rule
        // except on the inputs it handles otherwise (non-manifold ones, say) is named by it.
        const auto most = std::max_element(whole_fits_.begin(), whole_fits_.end());
        if (most == whole_fits_.end() || *most == 0) parts.push_back("no named rule on any input");
        else
            parts.push_back("the " + rule_name(scheme_, rules[static_cast<size_t>(most - whole_fits_.begin())]) + " rule on " +
                            std::to_string(*most) + " of " + std::to_string(inputs_) + " inputs");
    }
    for (const Tally& t : rows_) {
        if (std::any_of(t.fits.begin(), t.fits.end(), [](char f) { return f != 0; })) continue;
        parts.push_back("no named rule at " + std::string(to_string(t.key.cls)) +
                        (t.key.valence ? " " + std::to_string(t.key.valence) : "") + " (off by " +
                        sci(*std::min_element(t.max_rel.begin(), t.max_rel.end())) + ")");
    }
    std::string s = std::string(to_string(scheme_)) + " scheme";
    for (const std::string& p : parts) s += ", " + p;
    return s + other_scheme_phrase();
}

std::string RuleTally::loop_phrase() const {
    const std::vector<SchemeRule> rule_list = named_rules(Scheme::Loop);
    std::vector<LoopOptions> rules;
    for (const SchemeRule& r : rule_list) rules.push_back(r.loop);
    auto fits_any = [&](const Tally& t, auto&& pred) {
        for (size_t r = 0; r < rules.size(); ++r)
            if (t.fits[r] && pred(rules[r])) return true;
        return false;
    };
    auto best = [&](const Tally& t) {
        return *std::min_element(t.max_rel.begin(), t.max_rel.end());
    };
    std::vector<std::string> parts;

    // Interior vertices: the weight family that fits at every valence seen.
    // Interior vertices: the weight families that fit at every valence seen (families coincide
    // at some valences: Loop and Warren at 3 and 6, every family at 6).
    int lo = 0, hi = 0;
    bool any_interior = false;
    std::vector<char> family_all(kAllLoopWeights.size(), 1);
    std::vector<std::string> unfit;
    for (const Tally& t : rows_) {
        if (t.key.cls != VertexClass::InteriorVertex) continue;
        lo = any_interior ? std::min(lo, t.key.valence) : t.key.valence;
        hi = any_interior ? std::max(hi, t.key.valence) : t.key.valence;
        any_interior = true;
        bool any = false;
        for (size_t w = 0; w < kAllLoopWeights.size(); ++w) {
            const bool fits = fits_any(t, [&](const LoopOptions& o) { return o.weights == kAllLoopWeights[w]; });
            family_all[w] &= fits;
            any |= fits;
        }
        if (!any) unfit.push_back(std::to_string(t.key.valence) + " (off by " + sci(best(t)) + ")");
    }
    const std::string valences = " (valence " + std::to_string(lo) + (hi > lo ? ".." + std::to_string(hi) : "") + ")";
    std::string families;
    for (size_t w = 0; w < kAllLoopWeights.size(); ++w)
        if (family_all[w]) families += (families.empty() ? "" : " or ") + std::string(to_string(kAllLoopWeights[w]));
    if (!any_interior) parts.push_back("no interior vertices in the inputs");
    else if (!unfit.empty()) {
        std::string s = "no named weights at interior vertices of valence ";
        for (size_t k = 0; k < unfit.size(); ++k) s += (k ? ", " : "") + unfit[k];
        parts.push_back(s);
    } else if (!families.empty()) {
        parts.push_back("weights=" + families + " at interior vertices" + valences +
                        (families.find(" or ") != std::string::npos ? " (they coincide at the valences seen)" : ""));
    } else {
        parts.push_back("one named family at each valence but none at all of them" + valences);
    }

    auto class_phrase = [&](VertexClass cls, const std::string& fits, const std::string& none) -> std::optional<std::string> {
        for (const Tally& t : rows_)
            if (t.key.cls == cls) return fits_any(t, [](const LoopOptions&) { return true; }) ? fits : none + " (off by " + sci(best(t)) + ")";
        return std::nullopt;
    };
    const auto boundary = class_phrase(VertexClass::BoundaryVertex, "edge-only boundary", "no named rule at boundary vertices");
    const auto boundary_edges = class_phrase(VertexClass::BoundaryEdgePoint, "", "no named rule at boundary edge points");
    if (boundary) parts.push_back(*boundary);
    if (boundary_edges && !boundary_edges->empty()) parts.push_back(*boundary_edges);
    for (const Tally& t : rows_) {
        if (t.key.cls != VertexClass::Corner) continue;
        const bool edge_only = fits_any(t, [](const LoopOptions& o) { return o.boundary == LoopBoundary::EdgeOnly; });
        const bool corner = fits_any(t, [](const LoopOptions& o) { return o.boundary == LoopBoundary::EdgeAndCorner; });
        parts.push_back(edge_only && corner ? "corners indistinguishable"
                        : edge_only        ? "no corner rule"
                        : corner           ? "corner rule"
                                           : "no named rule at corners (off by " + sci(best(t)) + ")");
    }
    if (!boundary && !boundary_edges) parts.push_back("no boundary in the inputs");
    if (const auto e = class_phrase(VertexClass::InteriorEdgePoint, "", "no named rule at interior edge points"); e && !e->empty())
        parts.push_back(*e);
    if (const auto e = class_phrase(VertexClass::IsolatedVertex, "", "isolated vertices moved"); e && !e->empty())
        parts.push_back(*e);
    const auto nonmanifold = class_phrase(VertexClass::NonManifoldVertex, "OpenSubdiv's rules at non-manifold vertices",
                                          "no named rule at non-manifold vertices");
    if (nonmanifold) parts.push_back(*nonmanifold);
    if (const auto e = class_phrase(VertexClass::NonManifoldEdgePoint, "", "no named rule at non-manifold edge points");
        e && !e->empty())
        parts.push_back(*e);
    for (const auto& [cls, what] : {std::pair{VertexClass::CreaseVertex, "crease vertices"}, std::pair{VertexClass::Dart, "darts"},
                                    std::pair{VertexClass::SharpCorner, "sharp corners"},
                                    std::pair{VertexClass::CreaseEdgePoint, "crease edge points"}})
        if (const auto e = class_phrase(cls, "", std::string("no named rule at ") + what); e && !e->empty()) parts.push_back(*e);
    std::string s = "Loop scheme";
    for (const std::string& p : parts) s += ", " + p;
    return s;
}

std::string RuleTally::core_phrase() const {
    const std::vector<SchemeRule> rules = named_rules(scheme_);
    if (whole_fits_.empty()) return "no input compared";
    const size_t best = static_cast<size_t>(std::max_element(whole_fits_.begin(), whole_fits_.end()) - whole_fits_.begin());
    if (whole_fits_[best] == 0) return "agrees with core under no named rule on any input";
    return "agrees with core " + rule_name(scheme_, rules[best]) + " to " + sci(whole_max_[best]) + " on " +
           std::to_string(whole_fits_[best]) + " of " + std::to_string(inputs_) + " meshes";
}

}  // namespace crossdiv::verification
