#pragma once
// The subcommands of the polygon schemes and of limit behaviour: subdivide and compare with
// --scheme catmull-clark (Loop stays in main.cpp), limit and spectrum.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/nonmanifold_rule.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/implementations/implementation.h"
#include "crossdiv/verification/implementations/inputs.h"

namespace crossdiv::cli {

/// Writes `j` to `path` (parent folders made), and says so. @throws InputError when it cannot.
void write_json(const std::string& path, const nlohmann::json& j);

/// What `subdivide`/`compare` were given, for a scheme other than Loop.
struct PolySchemeArgs {
    std::string scheme, boundary;
    int levels = 1;
    std::string creasing;  ///< --crease-method; empty: the file's, else uniform
    long long max_faces = 0;  ///< --max-faces: the final level's face limit
    verification::UnknownTags unknown_tags = verification::UnknownTags::Refuse;  ///< --ignore-unknown-tags
    NonManifoldRule nonmanifold = NonManifoldRule::OpenSubdiv;                      ///< --nonmanifold
    std::string face_varying;  ///< --fvar; empty: the file's tag, else all
    std::string triangles;     ///< --triangles (Catmull-Clark); empty: the file's tag, else catmark
};

/// The rule a run of `scheme` uses on `mesh` (verification::rule_with_tags: the flags, else the
/// file's tags), its notes printed.
verification::SchemeRule rule_with_tags(verification::Scheme scheme, const PolySchemeArgs& s, PolyMesh& mesh);

/// The face-varying rule of a run on `mesh` (verification::face_varying_rule), its notes printed.
std::optional<FaceVaryingRule> face_varying_rule_noted(verification::Scheme scheme, const std::string& flag,
                                                       const PolyMesh& mesh);

/// The face-varying verdict of each run of `c`, one line each, when `c` compared texture
/// coordinates ("uv <rule>: reference verdict max rel  class: explanation").
void print_uv_runs(const verification::RefinementComparison& c);

/// Writes a refinement's emitted mesh (hole faces dropped) to `out`, saying when its texture
/// coordinates were not refined or cannot be written.
PolyMesh write_emitted(const std::string& out, const PolyMesh& result, const std::optional<FaceVaryingRule>& fvar,
                       const std::string& impl);

/// `crossdiv subdivide IN --scheme catmull-clark --impl core|opensubdiv|openmesh|cgal -o OUT`;
/// `color` "age" colours the vertices by the level they were born at (color_by_age). A reference
/// runs isolated with `timeout` seconds (refine_or_throw). Core's Catmull-Clark runs on `threads`
/// (catmull_clark_streaming.h), every other run on one (a note says so).
int run_scheme_subdivide(const std::string& in, const PolySchemeArgs& s, const std::string& impl, const std::string& out,
                         const std::string& color, double timeout, int threads);

/// `subdivide --color age`: colours `result`, the last of core's levels of `scheme`, by the
/// level each vertex was born at (crossdiv/subdiv/vertex_age.h), from the vertex count of
/// every level (`counts[0]` the input's, `counts.back()` result's).
void color_by_age(PolyMesh& result, const std::string& scheme, const std::vector<size_t>& counts);

/// The vertex count of each of `levels`.
std::vector<size_t> vertex_counts(const std::vector<PolyMesh>& levels);

/// `crossdiv compare INPUTS --scheme catmull-clark`: a table per input, exit 0 when every
/// reference agrees, 1 otherwise (each divergence printed with its class).
int run_scheme_compare(const std::vector<std::string>& specs, const PolySchemeArgs& s, const std::string& against,
                       const std::string& json_path, double timeout, bool no_isolate,
                       const verification::Implementation* subject = nullptr, const std::string& subject_command = {});

/// What `crossdiv diff` writes and prints of a shrunk input, for every scheme: OUT_DIR/
/// neighbourhood.obj (the k-ring around `seed`, or the whole mesh when k is 0) and
/// OUT_DIR/minimal.obj, a line for each, with what the minimal input still shows and the
/// comparison's explanation. Returns the minimal file's path, for the reproduce line.
std::string write_shrunk(const std::string& out_dir, const PolyMesh& neighbourhood, int k, const std::string& seed,
                         const PolyMesh& minimal, int tests, const std::string& minimal_shows, const std::string& explanation);

/// `crossdiv diff IN --scheme catmull-clark --against REF`: shrinks REF's divergence from core
/// (shrink_divergence), writes OUT_DIR/neighbourhood.obj and OUT_DIR/minimal.obj and
/// prints the compare line that reproduces the minimal one.
int run_scheme_diff(const std::string& in, const PolySchemeArgs& s, const std::string& against, const std::string& out_dir,
                    double timeout, const verification::Implementation* subject = nullptr,
                    const std::string& subject_command = {});

struct LimitArgs {
    std::string input, scheme = "loop", weights = "loop", boundary = "edge-only", against, json, out;
    std::string face_varying;  ///< --fvar; empty: the file's tag, else all
    int levels = 0;
    void add_to(CLI::App& app);
};
/// `crossdiv limit IN --scheme loop|catmull-clark [--weights] [--boundary] [--levels N]
/// [--fvar RULE] [--against opensubdiv] [--json F] [-o OUT]`: the level-N mesh with every vertex
/// moved to its limit position, and its texture coordinates (when it has them) to their limit
/// values; with --against, the comparison with OpenSubdiv's Limit() and LimitFaceVarying() (exit
/// 1 when it diverges).
int run_limit(const LimitArgs& a);

struct SpectrumArgs {
    std::string scheme = "loop", valence = "3..20", json;
    int levels = 8;  ///< of the convergence table
    void add_to(CLI::App& app);
};
/// `crossdiv spectrum --scheme loop|warren|catmull-clark|all --valences A..B [--json F]`: the eigen
/// table (core's local matrix against the closed form) and the convergence table; exit 1 when
/// a spectrum departs from its closed form by more than 1e-12.
int run_spectrum(const SpectrumArgs& a);

/// Adds limit and spectrum; the one selected stores its exit status in `status`.
void add_scheme_commands(CLI::App& app, int& status);

}  // namespace crossdiv::cli
