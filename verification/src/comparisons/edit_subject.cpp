#include "crossdiv/verification/comparisons/edit_subject.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

#include "crossdiv/io/output_file.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/mesh/halfedge_mesh.h"
#include "crossdiv/verification/harness/temporary_folder.h"
#include "crossdiv/verification/implementations/program_implementation.h"
#include "crossdiv/verification/implementations/task_program.h"
#include "harness/sci.h"

namespace crossdiv::verification {
namespace {

/// Positions are written as text: six significant digits put 5e-7 of a coordinate into a
/// split point; 1e-5 of the diagonal passes that, while a split anywhere but the midpoint
/// (a third of the edge, an endpoint) moves it by a part of an edge.
constexpr double kEditPositionTolerance = 1e-5;

/// The faces as oriented triangles, each from its least vertex, sorted.
std::vector<std::array<int, 3>> face_keys(const PolyMesh& m) {
    std::vector<std::array<int, 3>> out;
    for (int f = 0; f < m.num_faces(); ++f) {
        if (m.face_size(f) != 3) continue;
        const int* c = m.face(f);
        const int k = static_cast<int>(std::min_element(c, c + 3) - c);
        out.push_back({c[k], c[(k + 1) % 3], c[(k + 2) % 3]});
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

std::string EditOperation::text() const {
    return std::string(kind == Kind::Flip ? "flip " : "split ") + std::to_string(a) + " " + std::to_string(b);
}

bool EditStep::agrees() const {
    return outcome.status == RunStatus::Ok && core_vertices == subject_vertices && faces_only_in_subject == 0 &&
           faces_only_in_core == 0 && max_position <= kEditPositionTolerance;
}

bool EditSubjectComparison::passed() const {
    return !steps.empty() && std::all_of(steps.begin(), steps.end(), [](const EditStep& s) { return s.agrees(); });
}

std::string EditSubjectComparison::summary() const {
    const std::string who = "subject '" + subject + "': ";
    for (size_t k = 0; k < steps.size(); ++k) {
        const EditStep& s = steps[k];
        if (s.agrees()) continue;
        std::string at = "operation " + std::to_string(k + 1) + " (" + s.operation + "; core: " + s.core + "): ";
        if (s.outcome.status != RunStatus::Ok) return who + at + "failed: " + s.outcome.summary();
        if (s.subject_vertices != s.core_vertices)
            return who + at + std::to_string(s.subject_vertices) + " vertices, core " + std::to_string(s.core_vertices);
        if (s.faces_only_in_subject || s.faces_only_in_core)
            return who + at + std::to_string(s.faces_only_in_subject) + " faces only in the subject, " +
                   std::to_string(s.faces_only_in_core) + " only in core";
        return who + at + "vertex " + std::to_string(s.worst_vertex) + " off by " + detail::sci(s.max_position) +
               " of the diagonal (a split point that is not the midpoint)";
    }
    return who + std::to_string(steps.size()) + " of " + std::to_string(steps.size()) + " operations agree";
}

std::vector<EditOperation> parse_edit_operations(const std::string& text) {
    std::vector<EditOperation> out;
    std::string item;
    std::istringstream all(text);
    while (std::getline(all, item, item.find('\n') == std::string::npos && text.find('\n') == std::string::npos ? ',' : '\n')) {
        std::istringstream words(item);
        std::string kind, extra;
        EditOperation op;
        if (!(words >> kind)) continue;
        if (kind != "flip" && kind != "split") throw InputError("operation '" + item + "': expected flip A B or split A B");
        op.kind = kind == "flip" ? EditOperation::Kind::Flip : EditOperation::Kind::Split;
        if (!(words >> op.a >> op.b) || (words >> extra) || op.a < 0 || op.b < 0)
            throw InputError("operation '" + item + "': expected two vertex indices, as in flip 3 7");
        out.push_back(op);
    }
    if (out.empty()) throw InputError("no operations (flip A B, split A B, separated by commas)");
    return out;
}

EditSubjectComparison compare_edit_subject(const std::string& input, const TriMesh& mesh,
                                           const std::vector<EditOperation>& operations, const std::string& subject,
                                           const TaskCommand& command, double timeout_seconds) {
    EditSubjectComparison out;
    out.input = input;
    out.subject = subject;
    const TemporaryFolder folder("edit-input");
    const std::string obj = (folder.path() / "mesh.obj").string(), ops = (folder.path() / "ops.txt").string();
    write_mesh(obj, to_poly_mesh(mesh));
    HalfedgeMesh he = HalfedgeMesh::from_triangles(mesh);
    std::vector<Vec3> positions = mesh.positions;
    double d = bounding_box_diagonal(mesh.positions);
    if (!(d > 0)) d = 1;
    std::string listed;
    for (const EditOperation& op : operations) {
        EditStep step;
        step.operation = op.text();
        if (op.a >= he.num_vertices() || op.b >= he.num_vertices())
            throw InputError(input + ": " + op.text() + ": the mesh has " + std::to_string(he.num_vertices()) + " vertices then");
        const HalfedgeId h = he.find_halfedge(VertexId(op.a), VertexId(op.b));
        if (!h.valid()) throw InputError(input + ": " + op.text() + ": no edge joins the two vertices then");
        const EdgeId e = HalfedgeMesh::edge(h);
        if (op.kind == EditOperation::Kind::Flip) {
            const FlipRefusal r = he.flip(e);
            const HalfedgeId nh = HalfedgeMesh::halfedge(e);
            step.core = r == FlipRefusal::None ? "flipped to " + std::to_string(he.origin(nh).idx) + "-" + std::to_string(he.target(nh).idx)
                                               : "refused: " + std::string(to_string(r));
        } else {
            step.core = "new vertex " + std::to_string(split_at_midpoint(he, positions, e).idx);
        }
        listed += op.text() + "\n";
        write_text_file(ops, listed);
        const TaskRun run = run_task_program(command, obj, "out.obj", timeout_seconds, ops);
        step.outcome = run.outcome;
        const PolyMesh ours = to_poly_mesh(to_tri_mesh(he, positions));
        step.core_vertices = ours.num_vertices();
        if (run.outcome.status == RunStatus::Ok) {
            try {
                const PolyMesh theirs = read_program_result(run.out, "out.obj");
                step.subject_vertices = theirs.num_vertices();
                for (int v = 0; v < std::min(theirs.num_vertices(), ours.num_vertices()); ++v) {
                    const double e2 = (theirs.positions[static_cast<size_t>(v)] - ours.positions[static_cast<size_t>(v)]).norm() / d;
                    if (e2 > step.max_position) {
                        step.max_position = e2;
                        step.worst_vertex = v;
                    }
                }
                const auto a = face_keys(theirs), b = face_keys(ours);
                std::vector<std::array<int, 3>> only;
                std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(only));
                step.faces_only_in_subject = static_cast<int>(only.size()) + (theirs.num_faces() - static_cast<int>(a.size()));
                only.clear();
                std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(only));
                step.faces_only_in_core = static_cast<int>(only.size());
            } catch (const ImplementationFailure& f) {
                step.outcome.status = f.status();
                step.outcome.message = f.what() + run.stderr_tail;
            }
        }
        const bool stop = step.outcome.status != RunStatus::Ok;
        out.steps.push_back(std::move(step));
        if (stop) break;  // a program that fails once fails on the longer lists too: one outcome is enough
    }
    return out;
}

}  // namespace crossdiv::verification
