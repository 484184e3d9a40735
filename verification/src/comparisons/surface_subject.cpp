#include "crossdiv/verification/comparisons/surface_subject.h"

#include <nanoflann.hpp>

#include <Eigen/Geometry>
#include <cmath>
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

bool SurfaceSubjectComparison::passed() const {
    return outcome.status == RunStatus::Ok && positions_fit && normal_rule == "as core's" && faces_against_normals == 0;
}

std::string SurfaceSubjectComparison::summary() const {
    if (outcome.status != RunStatus::Ok) return "subject '" + subject + "' failed: " + outcome.summary();
    std::string s = "subject '" + subject + "': " + std::to_string(subject_vertices) + " vertices (core " +
                    std::to_string(core_vertices) + " welded); ";
    s += positions_fit ? "positions on core's to " + detail::sci(std::max(subject_to_core, core_to_subject))
                       : "positions off: " + detail::sci(subject_to_core) + " from core's, core's " + detail::sci(core_to_subject) +
                             " from its";
    if (positions_fit) {
        if (!normal_rule.empty()) s += "; normals " + normal_rule;
        else if (!normals.empty())
            s += "; normals off at " + std::to_string(normals.front().off) + " vertices (up to " +
                 detail::sci(normals.front().max_deg) + " deg)";
        if (zero_normals) s += " (" + std::to_string(zero_normals) + " left zero)";
    }
    if (faces) s += faces_against_normals ? "; " + std::to_string(faces_against_normals) + " of " + std::to_string(faces) +
                                                " faces turn against their normals"
                                          : "; faces turn with the normals";
    return s;
}

SurfaceSubjectComparison compare_surface_subject(const std::string& input_file, const SurfaceSamples& core,
                                                 const std::string& subject, const std::string& command,
                                                 double timeout_seconds) {
    SurfaceSubjectComparison out;
    out.input = input_file;
    out.subject = subject;
    out.core_vertices = core.welded_vertices;
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
    if (mine.num_vertices() == 0 || core.positions.empty()) {
        out.outcome.status = RunStatus::WrongCount;
        out.outcome.message = "out.obj: " + std::to_string(mine.num_vertices()) + " vertices; core's surface has " +
                              std::to_string(core.welded_vertices);
        return out;
    }
    if (normals.size() != mine.positions.size()) {
        out.outcome.status = RunStatus::WrongCount;
        out.outcome.message = "out.obj: " + std::to_string(normals.size()) + " normals (vn) for " +
                              std::to_string(mine.positions.size()) + " vertices (v); the task writes one per vertex";
        return out;
    }
    const std::vector<Vec3>& ours = core.positions;
    const double diagonal = bounding_box_diagonal(ours), d = diagonal > 0 ? diagonal : 1;
    // One tree over core's samples, for the nearest neighbours and the samples at each vertex.
    const PointCloud cloud{ours}, their_cloud{mine.positions};
    PointTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    PointTree their_tree(3, their_cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    tree.buildIndex();
    their_tree.buildIndex();
    const auto to_core = nearest(mine.positions, tree), back = nearest(ours, their_tree);
    for (const auto& [i, dist] : to_core) out.subject_to_core = std::max(out.subject_to_core, dist / d);
    for (const auto& [i, dist] : back) out.core_to_subject = std::max(out.core_to_subject, dist / d);
    out.positions_fit = out.subject_to_core <= kSurfacePositionTolerance && out.core_to_subject <= kSurfacePositionTolerance;
    if (!out.positions_fit) return out;
    // The core samples at each subject vertex (a seam's point once per piece).
    const double radius = kSurfacePositionTolerance * d;
    std::vector<std::vector<size_t>> at(normals.size());
    for (size_t v = 0; v < normals.size(); ++v) {
        std::vector<std::pair<unsigned, double>> hits;  // nanoflann 1.4's result type
        tree.radiusSearch(mine.positions[v].data(), radius * radius, hits, nanoflann::SearchParams());
        for (const auto& h : hits) at[v].push_back(h.first);
        if (at[v].empty()) at[v].push_back(to_core[v].first);
    }
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
        if (fit.fits && out.normal_rule.empty()) out.normal_rule = fit.name;
        out.normals.push_back(fit);
    }
    for (const Vec3& n : normals) out.zero_normals += n.isZero();
    out.faces = mine.num_faces();
    for (int f = 0; f < mine.num_faces(); ++f) {
        const int* c = mine.face(f);
        const int k = mine.face_size(f);
        Vec3 geometric = Vec3::Zero(), along = Vec3::Zero();
        for (int i = 0; i < k; ++i) {
            const Vec3& p = mine.positions[static_cast<size_t>(c[i])];
            const Vec3& q = mine.positions[static_cast<size_t>(c[(i + 1) % k])];
            geometric += p.cross(q);  // twice the area vector (Newell)
            along += normals[static_cast<size_t>(c[i])];
        }
        // A face of no area (at a collapsed patch edge) has no side to turn.
        if (geometric.norm() > 1e-12 * d * d) out.faces_against_normals += geometric.dot(along) < 0;
    }
    return out;
}

}  // namespace crossdiv::verification
