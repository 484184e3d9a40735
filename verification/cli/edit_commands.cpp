#include "edit_commands.h"

#include <fmt/format.h>

#include "crossdiv/io/output_file.h"
#include "crossdiv/verification/comparisons/edit_subject.h"
#include "crossdiv/verification/comparisons/normals_subject.h"

#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "command.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/mesh/halfedge_mesh.h"
#include "crossdiv/mesh/halfedge_validity.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/comparisons/normals_comparison.h"

namespace crossdiv::cli {

void EditArgs::add_to(CLI::App& app) {
    app.add_option("input", input, "Triangle mesh: file (.obj, .off, .dae, .ply, .stl) or bundled:NAME")->required();
    app.add_option("-o,--output", out, "Output mesh (.obj, .off); required without --subject");
    // One callback per occurrence, so that flips and splits keep their command-line order.
    app.add_option_function<std::string>("--flip", [this](const std::string& e) { ops.emplace_back("flip", e); },
                                         "Flip the edge A-B (vertex indices, 0-based)")
        ->trigger_on_parse()
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    app.add_option_function<std::string>("--split", [this](const std::string& e) { ops.emplace_back("split", e); },
                                         "Split the edge A-B at its midpoint (the new vertex is appended)")
        ->trigger_on_parse()
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    app.add_flag("--check", check, "Run the half-edge validity check after every operation");
    subject.add_to(app, "'python3 edit.py {in} {ops} {out}' ({in}: the mesh as OBJ, {ops}: one 'flip A B' or 'split A B' "
                        "per line, {out}: the mesh after them); run once per prefix of the operations, each result "
                        "compared with core's: vertex count, positions by index, faces");
}

namespace {

/// "A-B" as two vertex indices of `mesh`. @throws InputError naming the argument.
std::pair<int, int> parse_edge(const std::string& text, int num_vertices) {
    const size_t dash = text.find('-');
    int a = -1, b = -1;
    try {
        size_t used_a = 0, used_b = 0;
        if (dash == std::string::npos) throw std::invalid_argument("no dash");
        a = std::stoi(text.substr(0, dash), &used_a);
        b = std::stoi(text.substr(dash + 1), &used_b);
        if (used_a != dash || used_b != text.size() - dash - 1) throw std::invalid_argument("trailing text");
    } catch (const std::logic_error&) {
        throw InputError("edge '" + text + "': expected A-B with two vertex indices, e.g. 3-7");
    }
    for (int v : {a, b})
        if (v < 0 || v >= num_vertices)
            throw InputError("edge '" + text + "': vertex " + std::to_string(v) + " out of range [0, " + std::to_string(num_vertices) + ")");
    return {a, b};
}

int print_issues(const HalfedgeMesh& he, const std::string& after) {
    const auto issues = check_halfedge_mesh(he);
    for (const HalfedgeIssue& i : issues) fmt::print("invalid after {}: [{}] {}\n", after, to_string(i.kind), i.message);
    return static_cast<int>(issues.size());
}

}  // namespace

int run_edit(const EditArgs& a) {
    const TriMesh mesh = to_tri_mesh(verification::load_input(a.input, verification::UnknownTags::Ignore), "edit");
    if (!a.subject.command.empty()) {
        std::vector<verification::EditOperation> ops;
        for (const auto& [kind, text] : a.ops) {
            const auto [u, v] = parse_edge(text, std::numeric_limits<int>::max());
            ops.push_back({kind == "flip" ? verification::EditOperation::Kind::Flip : verification::EditOperation::Kind::Split, u, v});
        }
        if (ops.empty()) throw InputError("--subject needs operations: --flip A-B, --split A-B");
        const auto c = verification::compare_edit_subject(a.input, mesh, ops, a.subject.name, a.subject.command, a.subject.timeout);
        for (const auto& s : c.steps)
            fmt::print("  {:<12} core {:<28} {}\n", s.operation, s.core, s.agrees() ? "agrees" : "differs");
        fmt::print("{}\n", c.summary());
        return c.passed() ? 0 : 1;
    }
    if (a.out.empty()) throw InputError("edit needs -o OUT, or --subject CMD");
    HalfedgeMesh he = HalfedgeMesh::from_triangles(mesh);
    std::vector<Vec3> pos = mesh.positions;
    int refused = 0, invalid = 0;
    for (const auto& [kind, text] : a.ops) {
        const auto [u, v] = parse_edge(text, he.num_vertices());
        const HalfedgeId h = he.find_halfedge(VertexId(u), VertexId(v));
        if (!h.valid()) throw InputError("--" + kind + " " + text + ": no edge joins vertices " + std::to_string(u) + " and " + std::to_string(v));
        const EdgeId e = HalfedgeMesh::edge(h);
        if (kind == "flip") {
            const FlipRefusal r = he.flip(e);
            if (r == FlipRefusal::None) {
                const HalfedgeId nh = HalfedgeMesh::halfedge(e);
                fmt::print("flip {}: now {}-{}\n", text, he.origin(nh).idx, he.target(nh).idx);
            } else {
                ++refused;
                fmt::print("flip {}: refused: {}\n", text, to_string(r));
            }
        } else {
            const VertexId m = split_at_midpoint(he, pos, e);
            fmt::print("split {}: new vertex {} at ({}, {}, {})\n", text, m.idx, pos[m.idx].x(), pos[m.idx].y(), pos[m.idx].z());
        }
        if (a.check) invalid += print_issues(he, "--" + kind + " " + text);
    }
    write_mesh(a.out, to_poly_mesh(to_tri_mesh(he, pos)));
    fmt::print("{}: {} vertices, {} faces -> {} ({} vertices, {} faces; {} operation(s), {} refused{})\n", a.input,
               mesh.num_vertices(), mesh.num_faces(), a.out, he.num_vertices(), he.num_faces(), a.ops.size(), refused,
               a.check ? fmt::format(", {} invalid", invalid) : "");
    return refused || invalid ? 1 : 0;
}

void NormalsArgs::add_to(CLI::App& app) {
    app.add_option("input", input, "Triangle mesh: file (.obj, .off, .dae, .ply, .stl) or bundled:NAME")->required();
    app.add_option("--weighting", weighting, "area (the seed's), angle or uniform")
        ->check(CLI::IsMember({"area", "angle", "uniform"}))
        ->capture_default_str();
    app.add_option("--against", against, "Comma-separated references: openmesh, cgal");
    app.add_option("--json", json, "Write the normals and each reference's comparison as JSON");
    subject.add_to(app, "'python3 normals.py {in} {out}' ({in}: the mesh as OBJ, {out}: one normal per vertex as OBJ vn lines or x y z lines); the weighting it follows is named");
}

int run_normals(const NormalsArgs& a) {
    const TriMesh mesh = to_tri_mesh(verification::load_input(a.input, verification::UnknownTags::Ignore), "vertex normals");
    if (!a.subject.command.empty()) {
        const auto c = verification::compare_normals_subject(a.input, mesh, a.subject.name, a.subject.command, a.subject.timeout);
        for (const auto& w : c.weightings)
            fmt::print("  {:<18} {}{:.3g} deg (worst vertex {})\n", w.name, w.fits ? "= " : "  ", w.max_deg, w.worst_vertex);
        fmt::print("{}\n", c.summary());
        return c.passed() ? 0 : 1;
    }
    const auto c = verification::compare_normals(mesh, *parse_normal_weighting(a.weighting), split_commas(a.against));
    int zero = 0;
    for (const Vec3& n : c.ours) zero += n.norm() == 0;
    fmt::print("{}: {} vertices ({} on the boundary), {} weighting; {} without a normal\n", a.input, c.vertices,
               c.boundary_vertices, a.weighting, zero);
    for (const auto& r : c.references) {
        if (!r.error.empty()) {
            fmt::print("  {:<17} refused the mesh: {}\n", r.name, r.error);
            continue;
        }
        fmt::print("  {:<17} vs area {:.3e}  angle {:.3e}  uniform {:.3e} rad: {}\n", r.name, r.max_angle[0], r.max_angle[1],
                   r.max_angle[2], r.classification);
    }
    if (!a.json.empty()) {
        nlohmann::json j;
        j["input"] = a.input;
        j["weighting"] = a.weighting;
        j["normals"] = nlohmann::json::array();
        for (const Vec3& n : c.ours) j["normals"].push_back({n.x(), n.y(), n.z()});
        j["references"] = nlohmann::json::array();
        for (const auto& r : c.references) {
            nlohmann::json jr{{"name", r.name}, {"method", r.method}};
            if (!r.error.empty()) jr["error"] = r.error;
            else {
                jr["max_angle_rad"] = {{"area", r.max_angle[0]}, {"angle", r.max_angle[1]}, {"uniform", r.max_angle[2]}};
                jr["matches"] = r.matches;
                jr["closest"] = r.closest;
                jr["mismatched_vertices"] = r.mismatched;
                jr["mismatched_boundary_vertices"] = r.mismatched_boundary;
                jr["most_visible_vertices"] = r.most_visible;
                jr["classification"] = r.classification;
            }
            j["references"].push_back(jr);
        }
        write_text_file(a.json, verification::json_text(j, 1) + "\n");
    }
    return 0;
}

int print_halfedge_report(const PolyMesh& poly) {
    TriMesh mesh;
    HalfedgeMesh he;
    try {
        mesh = to_tri_mesh(poly, "a half-edge mesh");
        he = HalfedgeMesh::from_triangles(mesh);
    } catch (const InputError& e) {
        fmt::print("half-edge mesh: not built: {}\n", e.what());
        return 0;  // the mesh checks above already report the cause as errors
    }
    const auto issues = check_halfedge_mesh(he);
    for (const HalfedgeIssue& i : issues) fmt::print("error [half-edge {}] {}\n", to_string(i.kind), i.message);
    fmt::print("half-edge mesh: {} vertices, {} edges, {} faces, {} boundary loop(s), V - E + F = {}, {}\n", he.num_vertices(),
               he.num_edges(), he.num_faces(), he.num_boundary_loops(), he.num_vertices() - he.num_edges() + he.num_faces(),
               issues.empty() ? "every invariant holds" : fmt::format("{} broken invariant(s)", issues.size()));
    return static_cast<int>(issues.size());
}

void add_edit_commands(CLI::App& app, int& status) {
    add_command<EditArgs>(app, "edit", "Flip and split edges in order on a half-edge mesh (edges as A-B, 0-based)", status,
                          run_edit);
    add_command<NormalsArgs>(app, "normals", "Vertex normals (area, angle, uniform) against OpenMesh and CGAL", status,
                             run_normals);
}

}  // namespace crossdiv::cli
