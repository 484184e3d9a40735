#include "crossdiv/verification/properties/surface_checks.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

#include "crossdiv/curves/cubic_spline.h"
#include "crossdiv/datasets/bundled_surfaces.h"
#include "crossdiv/error.h"
#include "crossdiv/io/curve_io.h"
#include "crossdiv/io/patch_io.h"
#include "crossdiv/mesh/mesh_checks.h"
#include "crossdiv/surfaces/sweep_surface.h"
#include "crossdiv/verification/harness/convergence_order.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/harness/vector_angle.h"
#include "harness/check_inputs.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {
using nlohmann::json;

namespace {

using tolerances::kEps;

/// Largest |signed distance| of the mesh from an implicit surface, sampled on every
/// triangle at the barycentric points (i, j, k) / 6: the mesh-to-surface distance.
template <class Distance>
double mesh_to_surface(const TriMesh& m, Distance&& dist) {
    double worst = 0;
    constexpr int k = 6;
    for (const Triangle& t : m.triangles)
        for (int i = 0; i <= k; ++i)
            for (int j = 0; i + j <= k; ++j) {
                const double a = static_cast<double>(i) / k, b = static_cast<double>(j) / k;
                const Vec3 p = a * m.positions[t[0]] + b * m.positions[t[1]] + (1 - a - b) * m.positions[t[2]];
                worst = std::max(worst, std::abs(dist(p)));
            }
    return worst;
}


/// Largest angle between each vertex normal / each face normal and the exact normal there
/// (the face's at its centroid).
template <class Normal>
std::pair<double, double> normal_errors(const SurfaceMesh& s, Normal&& exact) {
    double vertex = 0, face = 0;
    for (int v = 0; v < s.mesh.num_vertices(); ++v) vertex = std::max(vertex, vector_angle(s.normals[v], exact(s.mesh.positions[v])));
    const std::vector<Vec3> fn = face_normals(s.mesh);
    for (int f = 0; f < s.mesh.num_faces(); ++f) {
        const Triangle& t = s.mesh.triangles[f];
        face = std::max(face, vector_angle(fn[f], exact((s.mesh.positions[t[0]] + s.mesh.positions[t[1]] + s.mesh.positions[t[2]]) / 3)));
    }
    return {vertex, face};
}

}  // namespace

json check_surface_mesh(const std::string& name, const SurfaceMesh& s, bool closed, std::vector<Check>& checks,
                        const MeshCheckContext& context) {
    const TriMesh& m = s.mesh;
    int errors = 0, contacts = 0;
    std::string first_error, first_contact;
    for (const MeshIssue& issue : check_mesh(to_poly_mesh(m))) {
        if (issue.severity != Severity::Error) continue;
        if (context.point_contacts_expected && issue.kind == MeshIssueKind::NonManifoldVertex) {
            if (contacts++ == 0) first_contact = issue.message;
        } else if (errors++ == 0) {
            first_error = issue.message;
        }
    }
    checks.push_back(count_check(name, "mesh-errors", "ours", errors,
                                 errors ? "first: " + first_error
                                        : "check_mesh: manifold, consistently oriented, no bad face" +
                                              std::string(contacts ? " (point contacts counted apart)" : "")));
    // A face disagrees when its geometric normal points away from its corners' mean normal.
    // Where a tube is wider than its sweep's radius of curvature it folds over, and there
    // the faces turn over while the normals do not: such faces are counted apart.
    const std::vector<Vec3> fn = face_normals(m);
    int disagree = 0, folded = 0, disagree_folded = 0;
    for (int f = 0; f < m.num_faces(); ++f) {
        const Triangle& t = m.triangles[f];
        const bool bad = fn[f].dot(s.normals[t[0]] + s.normals[t[1]] + s.normals[t[2]]) <= 0;
        const bool in_fold = !context.folded_vertex.empty() &&
                             (context.folded_vertex[t[0]] || context.folded_vertex[t[1]] || context.folded_vertex[t[2]]);
        folded += in_fold;
        (in_fold ? disagree_folded : disagree) += bad;
    }
    checks.push_back(count_check(name, "normals-vs-faces", "ours", disagree,
                                 "faces whose normal points away from their vertex normals" +
                                     (folded ? ", outside the " + std::to_string(folded) + " faces where the tube folds over" : std::string())));
    const int boundary = boundary_edge_count(m);
    const double volume = signed_volume(m);
    json row = {{"surface", name}, {"vertices", m.num_vertices()}, {"faces", m.num_faces()},
                {"collapsed_triangles", s.collapsed_triangles}, {"closed", closed}, {"boundary_edges", boundary},
                {"signed_volume", volume}, {"mesh_errors", errors}, {"normals_disagreeing", disagree}};
    if (contacts) row["point_contacts"] = {{"count", contacts}, {"first", first_contact}};
    if (!context.folded_vertex.empty()) row["fold"] = {{"faces", folded}, {"faces_disagreeing", disagree_folded}};
    if (!closed) return row;
    checks.push_back(count_check(name, "watertight", "ours", boundary, "edges used by one triangle only"));
    checks.push_back(count_check(name, "outward", "ours", volume > 0 ? 0 : 1, "signed volume " + std::to_string(volume) + " must be > 0"));
    const std::vector<const Implementation*> mesh_refs = references_with(&Capabilities::closed_mesh_report);
    if (mesh_refs.empty()) return row;
    const adapters::ClosedMeshReport cg = mesh_refs.front()->closed_mesh_report(m);
    checks.push_back(count_check(name, "valid-closed", "cgal", !cg.built + !cg.valid + !cg.closed,
                                 cg.built ? "is_valid_polygon_mesh " + std::string(cg.valid ? "yes" : "no") + ", is_closed " +
                                                (cg.closed ? "yes" : "no")
                                          : cg.error));
    checks.push_back(count_check(name, "outward", "cgal", cg.closed && cg.outward ? 0 : 1, "PMP::is_outward_oriented"));
    const double rel = cg.closed ? std::abs(cg.volume - volume) / std::max(std::abs(volume), 1e-300) : 1;
    checks.push_back({name, "volume", "cgal", rel, tolerances::kVolumeAgreementRelative, "rel",
                      "PMP::volume " + std::to_string(cg.volume) + " against our signed volume"});
    row["cgal"] = {{"built", cg.built}, {"valid", cg.valid}, {"closed", cg.closed}, {"outward", cg.outward}, {"volume", cg.volume}};
    return row;
}

namespace {

/// Whether the input says a sweep encloses a volume, read from its records alone and not from
/// the tessellation under test (a tessellation that drops a profile's last point must fail the
/// closed-surface checks, not skip them): a revolution whose profile is closed or whose exact
/// end points lie on the axis; a generalized cylinder whose profile and sweep are closed and
/// whose frames are closed up.
bool input_says_closed(const CurveFile& file, const SweepRecord& rec, const SweepOptions& o) {
    const CurveRecord& profile = file.curves.at(rec.profile_index);
    if (rec.kind == SweepRecord::Kind::Cylinder)
        return profile.closed() && file.curves.at(rec.sweep_index).closed() && o.close_frames;
    if (profile.closed()) return true;
    const auto at = record_evaluator(profile);
    const Vec3 first = at(0).position, last = at(record_param_end(profile)).position;
    const double tol = kWeldRelative * bounding_box_diagonal(profile.control);
    return (first - last).norm() <= tol || (std::abs(first.x()) <= tol && std::abs(last.x()) <= tol);
}

/// Whether a patch model encloses a volume, read from its control points alone (not from the
/// tessellation under test): every patch edge's control polygon is collapsed to a point (a
/// pole) or is another patch's edge polygon, in either direction, within kWeldRelative of
/// the model's size.
bool patches_enclose(std::span<const BezierPatch> patches) {
    std::vector<std::vector<Vec3>> edges;
    std::vector<Vec3> all;
    for (const BezierPatch& p : patches) {
        all.insert(all.end(), p.control.begin(), p.control.end());
        std::vector<Vec3> top, bottom, left, right;
        for (int c = 0; c < p.cols; ++c) {
            top.push_back(p.at(0, c));
            bottom.push_back(p.at(p.rows - 1, c));
        }
        for (int r = 0; r < p.rows; ++r) {
            left.push_back(p.at(r, 0));
            right.push_back(p.at(r, p.cols - 1));
        }
        for (auto* e : {&top, &bottom, &left, &right}) edges.push_back(std::move(*e));
    }
    const double tol = kWeldRelative * bounding_box_diagonal(all);
    const auto same = [&](const std::vector<Vec3>& a, const std::vector<Vec3>& b, bool reversed) {
        if (a.size() != b.size()) return false;
        for (size_t i = 0; i < a.size(); ++i)
            if ((a[i] - b[reversed ? b.size() - 1 - i : i]).norm() > tol) return false;
        return true;
    };
    for (size_t i = 0; i < edges.size(); ++i) {
        const bool collapsed = std::all_of(edges[i].begin(), edges[i].end(),
                                           [&](const Vec3& q) { return (q - edges[i].front()).norm() <= tol; });
        bool shared = collapsed;
        for (size_t j = 0; j < edges.size() && !shared; ++j)
            shared = j / 4 != i / 4 && (same(edges[i], edges[j], false) || same(edges[i], edges[j], true));
        if (!shared) return false;
    }
    return !edges.empty();
}

std::vector<char> folded_vertices(const CurveFile& file, const SweepSurface& s) {
    const SweepGrid& g = s.grid;
    // Welding a tube joins nothing unless the surface touches itself at a grid point; the
    // mesh's vertices are then the grid's, in order, and the classification applies.
    if (s.surface.mesh.num_vertices() != static_cast<int>(g.positions.size())) return {};
    const auto sweep = record_evaluator(file.curves.at(s.record.sweep_index));
    std::vector<char> folded(g.positions.size(), 0);
    for (int i = 0; i < g.rings; ++i) {
        const ChainJet j = sweep(g.sweep_params[i]);
        const double speed = j.d1.norm();
        if (!(speed > 0)) continue;
        // Curvature vector k = (d1 x d2) x d1 / |d1|^4: the tube map's Jacobian along the sweep
        // is 1 - k . d for the offset d of a profile point; it vanishes at the fold.
        const Vec3 k = j.d1.cross(j.d2).cross(j.d1) / (speed * speed * speed * speed);
        const Vec3 centre = j.position;
        for (int jj = 0; jj < g.ring_size; ++jj) {
            const Vec3 d = g.at(i, jj) - centre;
            folded[static_cast<size_t>(i) * g.ring_size + jj] = 1 - k.dot(d) <= 0;
        }
    }
    return folded;
}

/// At each corner of a generalized cylinder's sweep, how far the mitred ring's points are from
/// the wall of either tube: each point's distance from the arriving and from the leaving axis
/// line, the two against each other, and against the profile point's radius when the profile
/// is not scaled. The sweep's corner and the profile points are evaluated exactly at the grid's
/// parameters, not taken from the tessellation under test. Relative to the largest radius.
double corner_thickness_error(const CurveFile& file, const SweepSurface& s) {
    const auto profile = record_evaluator(file.curves.at(s.record.profile_index));
    const auto sweep = record_evaluator(file.curves.at(s.record.sweep_index));
    const SweepGrid& g = s.grid;
    std::vector<double> radius(g.ring_size);
    for (int j = 0; j < g.ring_size; ++j) radius[j] = profile(g.profile_params[j]).position.head<2>().norm();
    double worst = 0;
    for (const SweepCorner& c : s.corners) {
        const Vec3 v = sweep(g.sweep_params[c.sample]).position;
        for (int j = 0; j < g.ring_size; ++j) {
            const Vec3 d = g.at(c.sample, j) - v;
            const double to_in = (d - d.dot(c.in) * c.in).norm(), to_out = (d - d.dot(c.out) * c.out).norm();
            worst = std::max(worst, std::abs(to_in - to_out));
            if (s.record.scale_index < 0) worst = std::max(worst, std::abs(to_in - radius[j]));
        }
    }
    const double largest = *std::max_element(radius.begin(), radius.end());
    return largest > 0 ? worst / largest : worst;
}

/// A small surface's mesh for the report's picture (nothing above kPictureTriangles).
json mesh_picture(const SurfaceMesh& s) {
    constexpr int kPictureTriangles = 6000;
    if (s.mesh.num_faces() > kPictureTriangles) return nullptr;
    json positions = json::array(), triangles = json::array();
    for (const Vec3& p : s.mesh.positions) positions.push_back({p.x(), p.y(), p.z()});
    for (const Triangle& t : s.mesh.triangles) triangles.push_back({t[0], t[1], t[2]});
    return {{"positions", positions}, {"triangles", triangles}};
}

}  // namespace

CheckReport check_sweep_file(const CurveFile& file, const std::string& input, const SweepBuilder& build) {
    CheckReport r;
    r.input = input;
    r.operation = "surfaces";
    json rows = json::array();
    for (int k = 0; k < static_cast<int>(file.sweeps.size()); ++k) {
        const bool cylinder = file.sweeps[k].kind == SweepRecord::Kind::Cylinder;
        for (FrameMethod frames : {FrameMethod::Recursive, FrameMethod::DoubleReflection}) {
            if (!cylinder && frames != FrameMethod::Recursive) continue;  // revolution has no frames
            SweepOptions o;
            o.frames = frames;
            const SweepSurface s = build(file, k, o);
            const std::string name = cylinder ? s.name + " (" + std::string(to_string(frames)) + ")" : s.name;
            r.subjects.push_back(name);
            MeshCheckContext context;
            if (cylinder) context.folded_vertex = folded_vertices(file, s);
            const bool closed = input_says_closed(file, file.sweeps[k], o);
            // The construction's own claim must match the input's (a surface it calls open
            // would otherwise be built and checked as open).
            r.checks.push_back(count_check(name, "closed-as-input", "input", closed != s.closed ? 1 : 0,
                                           std::string("the records say ") + (closed ? "closed" : "open") +
                                               ", the construction " + (s.closed ? "closed" : "open")));
            json row = check_surface_mesh(name, s.surface, closed, r.checks, context);
            row["kind"] = cylinder ? "gcyl" : "srev";
            row["line"] = s.record.line;
            if (cylinder) {
                row["frames"] = to_string(frames);
                row["closure_angle_deg"] = s.closure_angle * 180 / std::numbers::pi;
                row["corners"] = s.corners.size();
                if (!s.corners.empty()) {
                    const double thickness = corner_thickness_error(file, s);
                    row["corner_thickness_rel"] = thickness;
                    r.checks.push_back({name, "corner-thickness", "analytic", thickness, tolerances::kCornerThickness, "rel",
                                        "at each of the " + std::to_string(s.corners.size()) +
                                            " mitred corners, every ring point's distance from the arriving and the "
                                            "leaving tube's axis vs its profile radius"});
                    if (frames == FrameMethod::DoubleReflection) row["mesh"] = mesh_picture(s.surface);
                }
            } else {
                row["deviation"] = grid_deviation(s.grid, exact_revolution(file.curves[s.record.profile_index]));
                row["slices"] = s.grid.rings;
            }
            rows.push_back(row);
        }
    }
    r.tables["surfaces"] = rows;
    return r;
}

CheckReport check_patch_file(std::span<const BezierPatch> patches, const std::string& input) {
    CheckReport r;
    r.input = input;
    r.operation = "surfaces";
    const std::string name = input;
    r.subjects.push_back(name);
    // Second algorithm: the Bernstein tensor sum, relative to each patch's control diagonal.
    double worst = 0, allowed = 0;
    std::vector<Vec3> all;
    for (const BezierPatch& p : patches) {
        all.insert(all.end(), p.control.begin(), p.control.end());
        const double diag = std::max(bounding_box_diagonal(p.control), 1e-300);
        for (int i = 0; i <= 10; ++i)
            for (int j = 0; j <= 10; ++j)
                worst = std::max(worst, (patch_point(p, i / 10.0, j / 10.0) - patch_bernstein_point(p, i / 10.0, j / 10.0)).norm() / diag);
        allowed = std::max(allowed, tolerances::kCurveRoundingUlps * (std::max(p.rows, p.cols)) * kEps);
    }
    r.checks.push_back({name, "position", "bernstein", worst, allowed, "rel",
                        "de Casteljau (rows at u, column at v) against the tensor Bernstein sum, 11 x 11 per patch"});
    int shared = 0;
    const double gap = max_boundary_gap(patches, 32, &shared);
    const double diag = bounding_box_diagonal(all);
    r.checks.push_back({name, "boundary-gap", "neighbour patch", diag > 0 ? gap / diag : gap, tolerances::kCurveRoundingUlps * kEps, "rel",
                        std::to_string(shared) + " shared patch edges, 33 samples each"});
    const SurfaceMesh s = tessellate_patches(patches, 8);
    const bool closed = patches_enclose(patches);  // from the control points, not the tessellation
    MeshCheckContext context;
    context.point_contacts_expected = true;
    json row = check_surface_mesh(name, s, closed, r.checks, context);
    row["kind"] = "bez";
    row["patches"] = patches.size();
    row["shared_edges"] = shared;
    row["boundary_gap"] = gap;
    r.tables["surfaces"] = json::array({row});
    return r;
}

namespace {

/// The semicircle x <= 0 from the top pole down, exactly (the circle primitive's s in
/// [pi/2, 3pi/2]) or as two cubic Bezier quarters.
Polyline semicircle(int n, bool bezier) {
    Polyline p;
    if (bezier) {
        const double k = 4.0 / 3.0 * std::tan(std::numbers::pi / 8);
        const std::vector<Vec3> c{{0, 1, 0}, {-k, 1, 0}, {-1, k, 0}, {-1, 0, 0}, {-1, -k, 0}, {-k, -1, 0}, {0, -1, 0}};
        return tessellate_uniform(bezier_chain(c), n / 2);
    }
    for (int i = 0; i <= n; ++i) {
        const double s = std::numbers::pi / 2 + std::numbers::pi * i / n;
        p.positions.emplace_back(std::cos(s), std::sin(s), 0);
        p.tangents.emplace_back(-std::sin(s), std::cos(s), 0);
        p.normals.emplace_back(-std::cos(s), -std::sin(s), 0);
        p.params.push_back(s);
    }
    return p;
}

void sphere_study(CheckReport& r) {
    json rows = json::array();
    for (bool bezier : {false, true}) {
        const std::string name = bezier ? "sphere (cubic Bezier profile)" : "sphere (exact circle profile)";
        std::vector<double> hs, errs;
        double vertex_normal = 0;
        for (int n = 8; n <= 128; n *= 2) {
            RevolutionOptions o;
            o.slices = 2 * n;
            const SurfaceMesh s = revolve(semicircle(n, bezier), false, o);
            const double radial = mesh_to_surface(s.mesh, [](const Vec3& p) { return p.norm() - 1; });
            const auto [vn, fnorm] = normal_errors(s, [](const Vec3& p) { return p.normalized(); });
            hs.push_back(std::numbers::pi / n);
            errs.push_back(radial);
            vertex_normal = vn;
            rows.push_back({{"surface", name}, {"profile_intervals", n}, {"slices", 2 * n}, {"faces", s.mesh.num_faces()},
                            {"radial_error", radial}, {"vertex_normal_error_rad", vn}, {"face_normal_error_rad", fnorm},
                            {"signed_volume", signed_volume(s.mesh)}, {"exact_volume", 4 * std::numbers::pi / 3}});
            if (n == 128) check_surface_mesh(name + " n=128", s, true, r.checks);
        }
        const double order = fitted_order(hs, errs);
        rows.push_back({{"surface", name}, {"fitted_order", order}});
        if (!bezier) {
            r.checks.push_back({name, "radial-order", "analytic", tolerances::kSecondOrderMin - order, 0, "order",
                                "fitted order " + std::to_string(order) + " must be >= " + std::to_string(tolerances::kSecondOrderMin)});
            r.checks.push_back({name, "vertex-normal", "analytic", vertex_normal, tolerances::kExactNormalRad, "rad",
                                "vertex normals against p / |p| at the finest level"});
        } else {
            const double off = std::abs(errs.back() - tolerances::kBezierCircleError) / tolerances::kBezierCircleError;
            r.checks.push_back({name, "radial-plateau", "analytic", off, tolerances::kBezierCirclePlateauRelative, "rel",
                                "finest radial error " + std::to_string(errs.back()) + " against the Bezier circle's 2.7253e-4"});
        }
        r.subjects.push_back(name);
    }
    r.tables["sphere"] = rows;
}

void torus_study(CheckReport& r) {
    constexpr double R = 2, rr = 0.5;
    json rows = json::array();
    for (FrameMethod frames : {FrameMethod::Recursive, FrameMethod::DoubleReflection}) {
        const std::string name = "torus (" + std::string(to_string(frames)) + ")";
        std::vector<double> hs, errs;
        double vertex_normal = 0;
        for (int n = 8; n <= 128; n *= 2) {
            std::istringstream in("circ profile " + std::to_string(n) + " 0.5\ncirc sweep " + std::to_string(2 * n) +
                                  " 2\ngcyl torus profile sweep\n");
            const CurveFile f = read_swp(in, "torus.swp");
            SweepOptions o;
            o.frames = frames;
            const SweepSurface s = build_sweep(f, 0, o);
            auto dist = [](const Vec3& p) { return std::hypot(std::hypot(p.x(), p.y()) - R, p.z()) - rr; };
            auto normal = [](const Vec3& p) {
                const double rho = std::hypot(p.x(), p.y());
                const Vec3 core(R * p.x() / rho, R * p.y() / rho, 0);
                return Vec3((p - core).normalized());
            };
            const double err = mesh_to_surface(s.surface.mesh, dist);
            const auto [vn, fnorm] = normal_errors(s.surface, normal);
            hs.push_back(2 * std::numbers::pi / n);
            errs.push_back(err);
            vertex_normal = vn;
            rows.push_back({{"surface", name}, {"profile_steps", n}, {"sweep_steps", 2 * n}, {"faces", s.surface.mesh.num_faces()},
                            {"distance_error", err}, {"vertex_normal_error_rad", vn}, {"face_normal_error_rad", fnorm},
                            {"signed_volume", signed_volume(s.surface.mesh)},
                            {"exact_volume", 2 * std::numbers::pi * std::numbers::pi * R * rr * rr}});
            if (n == 128) check_surface_mesh(name + " n=128", s.surface, true, r.checks);
        }
        const double order = fitted_order(hs, errs);
        rows.push_back({{"surface", name}, {"fitted_order", order}});
        r.checks.push_back({name, "distance-order", "analytic", tolerances::kSecondOrderMin - order, 0, "order",
                            "fitted order " + std::to_string(order) + " must be >= " + std::to_string(tolerances::kSecondOrderMin)});
        r.checks.push_back({name, "vertex-normal", "analytic", vertex_normal, tolerances::kExactNormalRad, "rad",
                            "vertex normals against the analytic torus normal at the finest level"});
        r.subjects.push_back(name);
    }
    r.tables["torus"] = rows;
}

/// A generalized cylinder whose scale varies: a unit circle swept along the z axis from z = 1 to
/// z = 2 with the scale curve's y = z, which is the cone rho = z. Every ring lies on the cone
/// exactly (the sweep and the scale are the same straight cubic, so sample i's height and
/// scale are one number), and the steps between rings are straight, so the normals, tilted
/// along T by the central (or one-sided) difference of the rings, must be the cone's exact
/// normal (cos theta, sin theta, -1) / sqrt 2 to rounding: a tilt of the wrong sign or size,
/// or a scale applied to the wrong sample, is off by an angle of order one.
void cone_study(CheckReport& r) {
    json rows = json::array();
    for (FrameMethod frames : {FrameMethod::Recursive, FrameMethod::DoubleReflection}) {
        const std::string name = "cone (gcyl scaled by z, " + std::string(to_string(frames)) + ")";
        std::istringstream in("circ profile 32 1\n"
                              "bez3 sweep 8 4 [0 0 1] [0 0 1.3333333333333333] [0 0 1.6666666666666667] [0 0 2]\n"
                              "bez2 size 8 4 [0 1] [1 1.3333333333333333] [2 1.6666666666666667] [3 2]\n"
                              "gcyl cone profile sweep size\n");
        const CurveFile f = read_swp(in, "cone.swp");
        SweepOptions o;
        o.frames = frames;
        const SweepSurface s = build_sweep(f, 0, o);
        double off_cone = 0;  // |rho - z| / sqrt 2, the distance of a vertex from the cone
        for (const Vec3& p : s.surface.mesh.positions) off_cone = std::max(off_cone, std::abs(std::hypot(p.x(), p.y()) - p.z()) / std::sqrt(2.0));
        const auto [vn, fnorm] = normal_errors(s.surface, [](const Vec3& p) {
            const double rho = std::hypot(p.x(), p.y());
            return Vec3(Vec3(p.x() / rho, p.y() / rho, -1).normalized());
        });
        rows.push_back({{"surface", name}, {"vertices", s.surface.mesh.num_vertices()}, {"vertex_distance", off_cone},
                        {"vertex_normal_error_rad", vn}, {"face_normal_error_rad", fnorm}});
        // Coordinates up to 2 from a cubic evaluated in a few operations: a few ulps of 2.
        r.checks.push_back({name, "on-surface", "analytic", off_cone, tolerances::kCurveRoundingUlps * 2 * kEps, "abs",
                            "largest distance of a vertex from the cone rho = z"});
        r.checks.push_back({name, "vertex-normal", "analytic", vn, tolerances::kExactNormalRad, "rad",
                            "vertex normals against the cone's normal (cos theta, sin theta, -1) / sqrt 2"});
        r.subjects.push_back(name);
    }
    r.tables["cone"] = rows;
}

/// A 6 x 6 control grid (25 quads) with seeded random heights: its 9 inner faces are
/// regular, and each is the uniform bicubic B-spline patch of the 4 x 4 window around it.
void bfr_study(const Implementation& bfr, CheckReport& r) {
    json rows = json::array();
    std::mt19937 rng(20261122);
    std::uniform_real_distribution<double> jitter(-0.5, 0.5);
    for (int trial = 0; trial < 3; ++trial) {
        constexpr int N = 6;
        PolyMesh grid;
        for (int i = 0; i < N; ++i)
            for (int j = 0; j < N; ++j) grid.positions.emplace_back(j + 0.2 * jitter(rng), i + 0.2 * jitter(rng), jitter(rng));
        for (int i = 0; i + 1 < N; ++i)
            for (int j = 0; j + 1 < N; ++j) grid.add_face({i * N + j, i * N + j + 1, (i + 1) * N + j + 1, (i + 1) * N + j});
        const double diag = bounding_box_diagonal(grid.positions);
        std::vector<std::array<double, 2>> uv;
        for (int a = 0; a <= 10; ++a)
            for (int b = 0; b <= 10; ++b) uv.push_back({a / 10.0, b / 10.0});
        double pos = 0, der = 0;
        int regular = 0, faces = 0;
        for (int i = 1; i + 2 < N; ++i)
            for (int j = 1; j + 2 < N; ++j) {
                const adapters::LimitEvaluation ev = bfr.limit_surface(grid, Scheme::CatmullClark, i * (N - 1) + j, uv);
                regular += ev.regular;
                ++faces;
                // Our side: the 4 x 4 window, each row then each column to Bezier form.
                BezierPatch p;
                p.rows = p.cols = 4;
                std::array<std::array<Vec3, 4>, 4> rows_bz;
                for (int a = 0; a < 4; ++a) {
                    std::array<Vec3, 4> row;
                    for (int b = 0; b < 4; ++b) row[b] = grid.positions[(i - 1 + a) * N + (j - 1 + b)];
                    rows_bz[a] = bspline_to_bezier(row);
                }
                p.control.resize(16);
                for (int b = 0; b < 4; ++b) {
                    std::array<Vec3, 4> col{rows_bz[0][b], rows_bz[1][b], rows_bz[2][b], rows_bz[3][b]};
                    const std::array<Vec3, 4> c = bspline_to_bezier(col);
                    for (int a = 0; a < 4; ++a) p.control[a * 4 + b] = c[a];
                }
                for (size_t k = 0; k < uv.size(); ++k) {
                    const PatchJet jet = patch_jet(p, uv[k][0], uv[k][1]);
                    const auto& ref = ev.samples[k];
                    pos = std::max(pos, (jet.position - ref.position).norm() / diag);
                    der = std::max(der, std::max((jet.du - ref.du).norm(), (jet.dv - ref.dv).norm()) / (3 * diag));
                }
            }
        const std::string name = "bfr grid " + std::to_string(trial + 1);
        r.subjects.push_back(name);
        r.checks.push_back({name, "limit-position", "opensubdiv-bfr", pos, tolerances::kLimitSurfaceAgreement, "rel",
                            std::to_string(faces) + " regular faces x 121 (u, v): bicubic B-spline as Bezier against Bfr"});
        r.checks.push_back({name, "limit-derivatives", "opensubdiv-bfr", der, tolerances::kLimitSurfaceAgreement, "rel",
                            "du and dv, relative to 3 x the grid's diagonal"});
        r.checks.push_back(count_check(name, "regular-faces", "opensubdiv-bfr", faces - regular, "inner faces Bfr does not call regular"));
        rows.push_back({{"grid", name}, {"faces", faces}, {"regular", regular}, {"samples", faces * uv.size()},
                        {"max_position_rel", pos}, {"max_derivative_rel", der}});
    }
    r.tables["bfr"] = rows;
}

}  // namespace

namespace {

/// A square section of side a around a square path of side L, mitred at the corners: the
/// square frame, whose volume (L + a)^2 a - (L - a)^2 a = 4 L a^2 the mesh must enclose exactly
/// (its faces are planar quads split in two, so the signed volume is exact to rounding).
void square_frame_study(CheckReport& r) {
    std::istringstream text(datasets::bundled_surface("square-frame").text);
    const CurveFile f = read_swp(text, "surface:square-frame");
    for (FrameMethod frames : {FrameMethod::Recursive, FrameMethod::DoubleReflection}) {
        SweepOptions o;
        o.frames = frames;
        const SweepSurface s = build_sweep(f, 0, o);
        const double want = 4 * 4.0 * 1.0 * 1.0, got = signed_volume(s.surface.mesh);
        // A sum of 32 triple products of coordinates up to 4.5: a few hundred ulps of 16 at most.
        r.checks.push_back({"square frame (" + std::string(to_string(frames)) + ")", "volume", "exact",
                            std::abs(got - want) / want, 1e-13, "rel",
                            "signed volume of the mitred square frame vs 4 L a^2 = 16 (L = 4, a = 1), " +
                                std::to_string(s.corners.size()) + " corners"});
    }
    r.subjects.push_back("square frame");
}

}  // namespace

CheckReport check_surface_studies() {
    CheckReport r;
    r.input = "surfaces:synthetic";
    r.operation = "surfaces";
    sphere_study(r);
    torus_study(r);
    cone_study(r);
    square_frame_study(r);
    if (const auto refs = references_with(&Capabilities::limit_surface); !refs.empty()) bfr_study(*refs.front(), r);
    return r;
}

namespace {

std::vector<std::string> bundled_surface_names() {
    std::vector<std::string> names;
    for (const auto& b : datasets::bundled_surfaces()) names.push_back(b.name);
    return names;
}

const detail::CheckInputFamily& surface_inputs() {
    static const detail::CheckInputFamily f{"surfaces", "surface", {".swp", ".bez"}, bundled_surface_names, datasets::course_surface_files};
    return f;
}

}  // namespace

std::vector<std::string> expand_surface_inputs(const std::vector<std::string>& specs) {
    return detail::expand_check_inputs(surface_inputs(), specs);
}

CheckReport check_surface_input(const std::string& spec, const SweepBuilder& build) {
    if (spec == "surfaces:synthetic") return check_surface_studies();
    if (spec.starts_with("surfaces:")) throw InputError("'" + spec + "' is a collection, not one surface input");
    if (spec.starts_with("surface:")) {
        const datasets::BundledCurve& b = datasets::bundled_surface(spec.substr(8));
        std::istringstream in(b.text);
        if (b.format == "bez") return check_patch_file(read_bez(in, spec), spec);
        return check_sweep_file(read_swp(in, spec), spec, build);
    }
    if (spec.ends_with(".bez") || spec.ends_with(".BEZ")) return check_patch_file(read_bez(spec), spec);
    return check_sweep_file(read_swp(spec), spec, build);
}

}  // namespace crossdiv::verification
