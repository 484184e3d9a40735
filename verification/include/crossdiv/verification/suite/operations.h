#pragma once
/// @file
/// The suite's operations, by name: what a manifest `case` line may ask for. Each operation
/// expands its inputs and turns one job into a typed CaseRecord.
///
///   loop             core against every reference on a mesh, under the case's rules and tier
///   catmull-clark, doo-sabin, sqrt3, butterfly, modified-butterfly
///                    the same for each other scheme: core against every reference that has it
///   curves           a curve file (or the synthetic studies) against Eigen and exact properties
///   surfaces         a surface file (or the studies) built and checked as closed surfaces
///   edits            a mesh: seeded flip and split sequences against OpenMesh and CGAL
///   normals          a mesh: vertex normals against OpenMesh's and CGAL's, the angle oracle
///   schemes          the Butterfly properties and the rule oracles of Doo-Sabin, sqrt3, the Butterflies
///   creases          the crease catalog against OpenSubdiv, and the crease-cube figure
///   limit-positions  limit positions and normals against OpenSubdiv's Limit(), and Bfr at (u, v)
///   vertex-age       the level each vertex was born at, every scheme, against the topology
///   curvature        discrete curvature: analytic convergence, CGAL's jet fitting, Gauss-Bonnet, Loop's growth
///   spectrum         the eigen table of the local subdivision matrices, valence 3..20, against
///                    the published closed forms; the Loop rule oracle of loop and warren
///   convergence      the convergence table, valence 3..12, levels 1..8
///   invariance      each implementation of a scheme on a mesh and on the mesh written otherwise
///                    (suite/invariance_case.h): the same surface, no reference needed
///   tessellate, casteljau, patch, sweep, vertex-normals, flip-split
///                    the course tasks, each with a subject in core's place (task_cases.h)

#include <string>
#include <string_view>
#include <vector>

#include "crossdiv/verification/suite/case_record.h"
#include "crossdiv/verification/suite/manifest.h"
#include "crossdiv/verification/implementations/scheme.h"

namespace crossdiv::verification {

/// How an operation's records read.
enum class OperationKind {
    Comparison,  ///< one run per reference (a scheme's refinement); takes rule keys
    Checks,      ///< one run per measured check of an input file (curves, surfaces)
    Study,       ///< one job over a fixed catalog, measured checks and tables
    Task,        ///< a subject put in core's place for a course task (task_cases.h); takes the task's keys
    /// one run per implementation and transformation of a mesh (invariance_case.h); takes
    /// scheme= with its rule keys, impls=, transform=, seed=
    Invariance,
};

struct SuiteOperation {
    std::string name;
    OperationKind kind;
    std::string description;  ///< one line, for errors and documentation
    /// The single inputs the specs name, in a stable order.
    /// @throws InputError for a spec the operation does not take.
    std::vector<std::string> (*expand)(const std::vector<std::string>& specs);
    /// Runs one job; core's refusal of an input is recorded, not thrown.
    /// @param out_dir where side files (error fields) go.
    CaseRecord (*run)(const SuiteJob& job, const std::string& out_dir);
    Scheme scheme = Scheme::Loop;  ///< a comparison's scheme (an invariance case names its own)
};

/// Every operation, in the order above.
const std::vector<SuiteOperation>& suite_operations();

/// "comparison", "checks", "study", "task", "invariance".
const char* to_string(OperationKind kind);
/// Every operation's name, kind and (a comparison) scheme, as results.json lists them: what
/// the report reads to tell the kinds of cases apart.
nlohmann::json operations_json();

/// @throws InputError naming the unknown operation and the known ones.
const SuiteOperation& find_operation(std::string_view name);

/// The rule a comparison case refines `input` by: for a scheme other than Loop, the one its
/// tags ask for under the case's keys (a `none` boundary tags `input`'s boundary faces as
/// holes); the texture coordinates' rule (the case's fvar=, the file's tag, or all of them)
/// where the input has some. What the tags resolved to goes into `notes`.
void resolve_input_rules(RefinementRequest& req, const ManifestEntry& entry, PolyMesh& input,
                         std::vector<std::string>& notes);

/// The `crossdiv compare` line that runs `req`'s comparison of `mesh_file` against one
/// reference: what a minimal mesh is listed with, to reproduce it.
std::string compare_command(const RefinementRequest& req, const std::string& mesh_file, const std::string& reference);

}  // namespace crossdiv::verification
