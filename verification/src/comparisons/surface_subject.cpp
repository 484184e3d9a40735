#include "crossdiv/verification/comparisons/surface_subject.h"

#include <nanoflann.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <fstream>
#include <sstream>

#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/vector_angle.h"
#include "crossdiv/verification/implementations/program_implementation.h"
#include "crossdiv/verification/implementations/task_program.h"
#include "harness/point_cloud.h"
#include "harness/sci.h"

namespace crossdiv::verification {
namespace {

/// Six printed digits put 5e-7 of a coordinate into a vertex and 1e-6 rad into a normal;
/// positions fit within 1e-5 of the diagonal and normals within 0.01 degrees (1.7e-4 rad), while
/// another resolution, a swapped patch index or a turned normal moves them by 1e-2 and degrees.
constexpr double kSurfacePositionTolerance = 1e-5, kSurfaceNormalToleranceDeg = 0.01;

/// A face whose Newell area is below this times the diagonal squared has no side to turn: the
/// area rounding leaves on a face collapsed at a pole or a degenerate patch edge.
constexpr double kFlatFaceArea = 1e-12;

double surface_angle_deg(const Vec3& a, const Vec3& b) { return vector_angle(a, b) * 180 / M_PI; }

/// For each point of `from`, the index of the nearest point of `tree`'s cloud and the distance.
std::vector<std::pair<size_t, double>> nearest(const std::vector<Vec3>& from, const PointTree& tree) {
    std::vector<std::pair<size_t, double>> out(from.size());
    for (size_t i = 0; i < from.size(); ++i) {
        unsigned index = 0;  // the tree's default index type
        double d2 = 0;
        tree.knnSearch(from[i].data(), 1, &index, &d2);
        out[i] = {index, std::sqrt(d2)};
    }
    return out;
}

/// The `vn` lines of an OBJ (the mesh reader keeps positions and faces only).
/// @throws ImplementationFailure naming file:line.
std::vector<Vec3> read_vn(const std::string& path, const std::string& shown) {
    std::ifstream in(path);
    std::vector<Vec3> out;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::istringstream words(line);
        std::string first;
        if (!(words >> first) || first != "vn") continue;
        Vec3 n;
        for (int k = 0; k < 3; ++k) {
            std::string w;
            double v = 0;
            bool ok = static_cast<bool>(words >> w);
            if (ok) {
                try {
                    size_t used = 0;
                    v = std::stod(w, &used);
                    ok = used == w.size();
                } catch (const std::exception&) {
                    ok = false;
                }
            }
            if (!ok) throw ImplementationFailure(RunStatus::UnreadableOutput, shown + ":" + std::to_string(number) + ": vn needs three numbers");
            if (!std::isfinite(v))
                throw ImplementationFailure(RunStatus::NonFiniteOutput, shown + ":" + std::to_string(number) + ": vn '" + w + "' is not finite");
            n[k] = v;
        }
        out.push_back(n);
    }
    return out;
}

}  // namespace

void add_surface_piece(SurfaceSamples& samples, std::span<const Vec3> positions, std::span<const Vec3> normals,
                       const SurfaceMesh& welded) {
    samples.positions.insert(samples.positions.end(), positions.begin(), positions.end());
    samples.normals.insert(samples.normals.end(), normals.begin(), normals.end());
    samples.welded_vertices += welded.mesh.num_vertices();
    samples.boundary_edges += boundary_edge_count(welded.mesh);
    const double d = bounding_box_diagonal(welded.mesh.positions);
    samples.folded_faces += faces_against_normals(to_poly_mesh(welded.mesh), welded.normals, kFlatFaceArea * d * d);
}

std::vector<SurfaceSamples> sweep_conventions(const CurveFile& file, const SweepOptions& options) {
    const auto samples = [&](const SweepOptions& o) {
        SurfaceSamples c;
        for (int k = 0; k < static_cast<int>(file.sweeps.size()); ++k) {
            const SweepSurface s = build_sweep(file, k, o);
            add_surface_piece(c, s.grid.positions, s.grid.normals, s.surface);
        }
        return c;
    };
    std::vector<SurfaceSamples> out{samples(options)};
    const bool cylinders = std::any_of(file.sweeps.begin(), file.sweeps.end(),
                                       [](const SweepRecord& r) { return r.kind == SweepRecord::Kind::Cylinder; });
    if (!cylinders) return out;
    // A generalized cylinder's frames are a convention (the seed leaves the initial frame and
    // a closed sweep's seam to the program): a subject that misses core's is told which of the
    // others it follows.
    const auto frames_name = [](FrameMethod m) { return m == FrameMethod::Recursive ? "recursive frames" : "rotation-minimizing frames"; };
    const FrameMethod other = options.frames == FrameMethod::Recursive ? FrameMethod::DoubleReflection : FrameMethod::Recursive;
    for (const FrameMethod m : {options.frames, other})
        for (const bool closed : {true, false}) {
            const std::string name = std::string(frames_name(m)) + ", seam " + (closed ? "closed" : "left open");
            if (m == options.frames && closed) {
                out.front().convention = name;  // core's own
                continue;
            }
            SweepOptions o = options;
            o.frames = m;
            o.close_frames = closed;
            out.push_back(samples(o));
            out.back().convention = name;
        }
    return out;
}

SurfaceSamples patch_samples(const std::vector<BezierPatch>& patches, int res, const SurfaceMesh& welded) {
    std::vector<Vec3> positions, normals;
    for (const BezierPatch& p : patches)
        for (int i = 0; i <= res; ++i)
            for (int j = 0; j <= res; ++j) {
                const double u = static_cast<double>(i) / res, v = static_cast<double>(j) / res;
                positions.push_back(patch_point(p, u, v));
                normals.push_back(patch_normal(p, u, v));
            }
    SurfaceSamples samples;
    add_surface_piece(samples, positions, normals, welded);
    return samples;
}

int faces_against_normals(const PolyMesh& mesh, std::span<const Vec3> normals, double area_floor) {
    int against = 0;
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const int* c = mesh.face(f);
        const int k = mesh.face_size(f);
        Vec3 geometric = Vec3::Zero(), along = Vec3::Zero();
        for (int i = 0; i < k; ++i) {
            const Vec3& p = mesh.positions[static_cast<size_t>(c[i])];
            const Vec3& q = mesh.positions[static_cast<size_t>(c[(i + 1) % k])];
            geometric += p.cross(q);  // twice the area vector (Newell)
            along += normals[static_cast<size_t>(c[i])];
        }
        // A face of no area (at a collapsed patch edge, a pole) has no side to turn.
        if (geometric.norm() > area_floor) against += geometric.dot(along) < 0;
    }
    return against;
}

int welded_boundary_edges(const PolyMesh& mesh, double tol) {
    const std::vector<int> weld = weld_classes(mesh.positions, tol);
    std::vector<std::uint64_t> edges;  // every edge of the welded faces, as edge_key
    edges.reserve(mesh.face_vertices.size());
    std::vector<int> corners;
    for (int f = 0; f < mesh.num_faces(); ++f) {
        corners.clear();
        for (int i = 0; i < mesh.face_size(f); ++i) {
            const int v = weld[static_cast<size_t>(mesh.face(f)[i])];
            if (corners.empty() || corners.back() != v) corners.push_back(v);
        }
        while (corners.size() > 1 && corners.back() == corners.front()) corners.pop_back();
        if (corners.size() < 3) continue;  // collapsed by welding (a pole's triangle): no side, no edges
        for (size_t i = 0; i < corners.size(); ++i) edges.push_back(edge_key(corners[i], corners[(i + 1) % corners.size()]));
    }
    return unpaired_edge_count(std::move(edges));
}

bool SurfaceSubjectComparison::passed() const {
    return outcome.status == RunStatus::Ok && positions_fit && follows_core() && normal_rule == "as core's" &&
           faces_against_normals <= core_folded_faces && boundary_edges <= core_boundary_edges;
}

bool SurfaceSubjectComparison::follows_core() const {
    return convention == (core_convention.empty() ? "core's" : core_convention);
}

std::string SurfaceSubjectComparison::summary() const {
    if (outcome.status != RunStatus::Ok) return "subject '" + subject + "' failed: " + outcome.summary();
    std::string s = "subject '" + subject + "': " + std::to_string(subject_vertices) + " vertices (core " +
                    std::to_string(core_vertices) + " welded); ";
    const bool other = !convention.empty() && !positions_fit;
    if (positions_fit) {
        s += "positions on core's to " + detail::sci(std::max(subject_to_core, core_to_subject));
    } else if (other) {
        const auto fit = std::find_if(conventions.begin(), conventions.end(),
                                      [&](const SurfacePositionFit& c) { return c.convention == convention; });
        s += "positions follow " + convention + " (to " + detail::sci(std::max(fit->subject_to_core, fit->core_to_subject)) +
             "), not core's " + core_convention + " (" + detail::sci(subject_to_core) + " off)";
    } else {
        s += "positions off: " + detail::sci(subject_to_core) + " from core's, core's " + detail::sci(core_to_subject) + " from its";
    }
    if (convention.empty()) return s;
    if (!follows_core()) {
        // Normals are held to the convention it follows; say so rather than "as core's".
        const std::string under = positions_fit ? " under " + convention + ", not core's " + core_convention : " under it";
        if (normal_rule == "as core's") s += "; normals as" + under;
        else if (normal_rule == "reversed") s += "; normals reversed from those" + under;
    } else if (!normal_rule.empty()) {
        s += "; normals " + normal_rule;
    }
    if (normal_rule.empty() && !normals.empty())
        s += "; normals off at " + std::to_string(normals.front().off) + " vertices (up to " + detail::sci(normals.front().max_deg) +
             " deg)";
    if (zero_normals) s += " (" + std::to_string(zero_normals) + " left zero)";
    if (faces) {
        if (faces_against_normals == 0) s += "; faces turn with the normals";
        else
            s += "; " + std::to_string(faces_against_normals) + " of " + std::to_string(faces) + " faces turn against their normals" +
                 (core_folded_faces ? " (core's own surface folds over itself at " + std::to_string(core_folded_faces) + ")" : "");
        if (boundary_edges > core_boundary_edges)
            s += "; NOT watertight: " + std::to_string(boundary_edges) + " boundary edges where core's surface has " +
                 std::to_string(core_boundary_edges);
        else if (boundary_edges == 0)
            s += "; watertight";
    }
    return s;
}

namespace {

/// The subject's positions against one convention: nearest neighbours both ways over `d`.
SurfacePositionFit position_fit(const SurfaceSamples& core, const std::vector<Vec3>& theirs, const PointTree& their_tree, double d) {
    SurfacePositionFit fit{core.convention};
    const PointCloud cloud{core.positions};
    PointTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    for (const auto& [i, dist] : nearest(theirs, tree)) fit.subject_to_core = std::max(fit.subject_to_core, dist / d);
    for (const auto& [i, dist] : nearest(core.positions, their_tree)) fit.core_to_subject = std::max(fit.core_to_subject, dist / d);
    fit.fits = fit.subject_to_core <= kSurfacePositionTolerance && fit.core_to_subject <= kSurfacePositionTolerance;
    return fit;
}

/// The subject's normals held to the convention's, and to their reversal, at matched points: a
/// subject normal fits where it matches the normal of some sample at its position.
std::vector<SurfaceNormalFit> normal_fits(const SurfaceSamples& core, const std::vector<Vec3>& positions,
                                          const std::vector<Vec3>& normals, double d) {
    const PointCloud cloud{core.positions};
    PointTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    const auto to_core = nearest(positions, tree);
    // The core samples at each subject vertex (a seam's point once per piece).
    const double radius = kSurfacePositionTolerance * d;
    std::vector<std::vector<size_t>> at(normals.size());
    for (size_t v = 0; v < normals.size(); ++v) {
        std::vector<std::pair<unsigned, double>> hits;  // nanoflann 1.4's result type
        tree.radiusSearch(positions[v].data(), radius * radius, hits, nanoflann::SearchParams());
        for (const auto& h : hits) at[v].push_back(h.first);
        if (at[v].empty()) at[v].push_back(to_core[v].first);
    }
    std::vector<SurfaceNormalFit> out;
    for (const bool reversed : {false, true}) {
        SurfaceNormalFit fit{reversed ? "reversed" : "as core's", 0, 0, false};
        for (size_t v = 0; v < normals.size(); ++v) {
            const Vec3& n = normals[v];
            if (n.isZero()) continue;
            double best = 180;
            for (size_t c : at[v]) best = std::min(best, surface_angle_deg(n, core.normals[c] * (reversed ? -1.0 : 1.0)));
            fit.max_deg = std::max(fit.max_deg, best);
            fit.off += best > kSurfaceNormalToleranceDeg;
        }
        fit.fits = fit.off == 0;
        out.push_back(fit);
    }
    return out;
}

}  // namespace

SurfaceSubjectComparison compare_surface_subject(const std::string& input_file, std::span<const SurfaceSamples> conventions,
                                                 const std::string& subject, const TaskCommand& command,
                                                 double timeout_seconds) {
    if (conventions.empty()) throw std::invalid_argument("compare_surface_subject: no samples of core's surface");
    SurfaceSubjectComparison out;
    out.input = input_file;
    out.subject = subject;
    out.core_vertices = conventions.front().welded_vertices;
    out.core_convention = conventions.front().convention;
    const TaskRun run = run_task_program(command, input_file, "out.obj", timeout_seconds);
    out.outcome = run.outcome;
    if (run.outcome.status != RunStatus::Ok) return out;
    PolyMesh mine;
    std::vector<Vec3> normals;
    try {
        mine = read_program_result(run.out, "out.obj");
        normals = read_vn(run.out, "out.obj");
    } catch (const ImplementationFailure& e) {
        out.outcome.status = e.status();
        out.outcome.message = e.what() + run.stderr_tail;
        return out;
    }
    out.subject_vertices = mine.num_vertices();
    if (mine.num_vertices() == 0 || conventions.front().positions.empty()) {
        out.outcome.status = RunStatus::WrongCount;
        out.outcome.message = "out.obj: " + std::to_string(mine.num_vertices()) + " vertices; core's surface has " +
                              std::to_string(out.core_vertices);
        return out;
    }
    if (normals.size() != mine.positions.size()) {
        out.outcome.status = RunStatus::WrongCount;
        out.outcome.message = "out.obj: " + std::to_string(normals.size()) + " normals (vn) for " +
                              std::to_string(mine.positions.size()) + " vertices (v); the task writes one per vertex";
        return out;
    }
    const double diagonal = bounding_box_diagonal(conventions.front().positions), d = diagonal > 0 ? diagonal : 1;
    const PointCloud their_cloud{mine.positions};
    PointTree their_tree(3, their_cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    for (const SurfaceSamples& c : conventions) out.conventions.push_back(position_fit(c, mine.positions, their_tree, d));
    out.subject_to_core = out.conventions.front().subject_to_core;
    out.core_to_subject = out.conventions.front().core_to_subject;
    out.positions_fit = out.conventions.front().fits;
    // Normals and faces are held to the first convention whose positions fit and whose normals
    // fit too (a seam left open may move only normals), else to the first whose positions fit.
    const SurfaceSamples* chosen = nullptr;
    for (size_t k = 0; k < conventions.size(); ++k) {
        if (!out.conventions[k].fits) continue;
        std::vector<SurfaceNormalFit> fits = normal_fits(conventions[k], mine.positions, normals, d);
        if (!chosen || fits.front().fits) {
            const bool first = !chosen;
            chosen = &conventions[k];
            out.normals = std::move(fits);
            if (!first || out.normals.front().fits) break;
        }
    }
    if (!chosen) return out;
    out.convention = chosen->convention.empty() ? "core's" : chosen->convention;
    for (const SurfaceNormalFit& f : out.normals)
        if (f.fits && out.normal_rule.empty()) out.normal_rule = f.name;
    for (const Vec3& n : normals) out.zero_normals += n.isZero();
    out.faces = mine.num_faces();
    out.core_folded_faces = chosen->folded_faces;
    out.core_boundary_edges = conventions.front().boundary_edges;  // watertight where core's own surface is
    if (out.faces) {
        out.faces_against_normals = faces_against_normals(mine, normals, kFlatFaceArea * d * d);
        out.boundary_edges = welded_boundary_edges(mine, kSurfacePositionTolerance * d);
    }
    return out;
}

}  // namespace crossdiv::verification
