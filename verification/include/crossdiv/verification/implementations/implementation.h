#pragma once
/// @file
/// One interface for everything the harness runs: core under each named rule, each reference
/// library, and (through the same interface) code a user brings. An implementation declares
/// what it can do in its Capabilities; the harness reads them instead of probing, and an
/// operation it lacks throws adapters::Rejected, which the harness records as a refusal.
///
/// Implementations are created and listed by the registry (registry.h), the one place that
/// knows which libraries this binary was built with.

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/implementations/scheme.h"
#include "crossdiv/volume/marching_cubes.h"

namespace crossdiv::verification {

/// Where an implementation comes from.
enum class ImplementationKind {
    Core,     ///< this testbed's own algorithms
    Library,  ///< a reference library compiled in through its adapter
    Program,  ///< a program run from a command line, or result files it wrote (program_implementation.h)
    Callback, ///< a C++ function of the user's program (callback_implementation.h)
};
/// "core", "library", "program", "callback".
const char* to_string(ImplementationKind kind);

/// The arithmetic an implementation refines in.
enum class Precision { Double, Float };
/// "double", "float".
const char* to_string(Precision precision);

/// A scheme an implementation refines, with the rule it applies when asked for another.
struct SchemeSupport {
    Scheme scheme = Scheme::Loop;
    /// The rules it has; when asked for a rule it lacks it applies the first of these that
    /// keeps the most of the request (closest_rule), and the harness classifies the difference.
    std::vector<SchemeRule> rules;
    /// Honours crease and corner tags (Sdc semantics); without, a tagged mesh is refused.
    bool creases = false;
    /// The largest valence its weight table holds (0: any), and where that is written; past
    /// it the implementation reads outside the table.
    int max_valence = 0;
    std::string valence_table;
    /// Refines face-varying channels under OpenSubdiv's six rules (RefineRequest::face_varying).
    bool face_varying = false;
    /// Applies hierarchical edits (mesh/hierarchical_edit.h); without, a mesh with them is
    /// refused before it is run (every library would drop them silently).
    bool hierarchical_edits = false;
};

/// What an implementation can do, declared.
struct Capabilities {
    std::vector<SchemeSupport> schemes;
    bool limit_positions = false;  ///< limit positions and normals of a refined level
    bool limit_surface = false;    ///< evaluation of the limit surface of a face at (u, v)
    bool edits = false;            ///< flips and splits on its own mesh (open_edit)
    bool vertex_normals = false;
    bool spline_evaluation = false;   ///< B-spline and Bezier evaluation with derivatives
    bool closed_mesh_report = false;  ///< validity, closedness, orientation and volume of a mesh
    bool curvatures = false;          ///< per-vertex principal curvatures of a triangle mesh
    bool hausdorff_distance = false;  ///< two-sided Hausdorff distance between triangle meshes
    bool simplification = false;      ///< edge-collapse simplification to an edge budget
    bool isosurface = false;          ///< marching cubes of a sampled scalar field
    Precision precision = Precision::Double;
    /// Core's non-manifold refinement (NonManifoldRule::OpenSubdiv, subdiv/nonmanifold.h)
    /// takes this implementation's rules: where it differs from core at a non-manifold vertex,
    /// core is wrong, and no named handling of its own excuses the difference.
    bool defines_nonmanifold_rules = false;
};

/// One named set of vertex normals an implementation computes, with the call that made them.
struct NamedNormals {
    std::string name;    ///< "openmesh-correct", "openmesh-fast", "cgal"
    std::string method;  ///< the library call
    std::vector<Vec3> normals;
    std::string error;   ///< the library refused the mesh (then `normals` is empty)
};

/// Per-vertex principal curvatures in crossdiv's sign convention (mesh/discrete_curvature.h:
/// positive where the surface bends away from the outward normal, 1/r on a sphere), k1 >= k2.
struct PrincipalCurvatures {
    std::string method;  ///< the estimator: "cotangent Laplacian and angle defect (Meyer et al. 2002)", ...
    std::vector<unsigned char> estimated;  ///< 0 where the estimator gives nothing (a boundary vertex, too few neighbours)
    std::vector<double> k1, k2;
    /// The estimator's own mean and Gaussian curvature: (k1 + k2) / 2 and k1 k2 for a fit, but
    /// the angle defect over the area for core, whose k1, k2 clamp H^2 - K at 0.
    std::vector<double> mean, gaussian;
    std::vector<Vec3> direction1;  ///< unit direction of k1; 0 where undefined (an umbilic)
};

/// A mesh held in an implementation's own structures and edited in lockstep with ours.
class EditSession {
public:
    virtual ~EditSession() = default;
    /// Whether the implementation would flip the edge, when it can say (OpenMesh's
    /// is_flip_ok); nothing when flipping a refused edge is just a broken precondition (CGAL).
    virtual std::optional<bool> flip_ok(int a, int b) const = 0;
    virtual void flip(int a, int b) = 0;
    /// Splits at the midpoint; returns the new vertex's index.
    virtual int split(int a, int b) = 0;
    /// The implementation's own validity report, one line per problem (empty when valid).
    virtual std::vector<std::string> check() const = 0;
    virtual std::vector<Triangle> faces() const = 0;
    virtual std::vector<Vec3> positions() const = 0;
};

/// Levels 0..N of a refinement with, where the implementation knows it, where each refined
/// vertex was born.
struct Refinement {
    adapters::LevelTrace levels;
    /// births[l-1]: for each vertex of level l, the vertex, edge or face of level l-1 it was
    /// born from. Empty when the implementation does not say (the correspondence then infers
    /// it from the faces: match_by_provenance).
    adapters::LevelBirths births;
};

/// Which spline an implementation is asked to evaluate.
enum class SplineKind {
    UniformCubicBSpline,  ///< control points p_0..p_n, knots 0..n+4, parameter u in [0, n-2]
    ClampedBezier,        ///< one Bezier segment as a clamped B-spline, t in [0, 1]
};

/// Something that refines, evaluates or edits. The base versions of the operations throw
/// adapters::Rejected naming what the implementation lacks.
class Implementation {
public:
    Implementation(std::string name, std::string version, ImplementationKind kind, Capabilities capabilities);
    virtual ~Implementation() = default;
    Implementation(const Implementation&) = delete;
    Implementation& operator=(const Implementation&) = delete;

    const std::string& name() const { return name_; }
    const std::string& version() const { return version_; }
    ImplementationKind kind() const { return kind_; }
    const Capabilities& capabilities() const { return capabilities_; }
    /// Whether it runs its work in child processes with their own time limit (a program), so
    /// that the harness need not fork around it (refine_isolated).
    virtual bool confines_itself() const { return false; }
    /// For a program: the value of `crossdiv compare --reference` that makes it again, from any
    /// folder (program_implementation.h); empty for an implementation built into crossdiv.
    virtual std::string reference_option() const { return ""; }

    /// Its support of `scheme`, or nullptr when it lacks the scheme.
    const SchemeSupport* support(Scheme scheme) const;
    bool has(Scheme scheme) const { return support(scheme) != nullptr; }
    /// The rule it applies when asked for `requested`: the request itself when it has it,
    /// else its rule that keeps the most of the request (for Loop: the weights first, then
    /// the boundary rule). The request when it lacks the scheme (refine then refuses).
    SchemeRule closest_rule(Scheme scheme, const SchemeRule& requested) const;
    /// Whether it applies exactly `rule`.
    bool applies(Scheme scheme, const SchemeRule& rule) const;

    /// Levels 0..N of `request` on `mesh` in the implementation's own vertex and face order
    /// (levels[0]: the input as it stored it). It applies closest_rule(request).
    /// @throws adapters::Rejected when it refuses the mesh, the scheme or the tags.
    virtual adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& request) const;
    /// refine() with each refined vertex's birth where the implementation knows it (core, for
    /// every primal scheme; OpenSubdiv, from Far's child queries); the base gives refine()'s
    /// levels and no births.
    virtual Refinement refine_with_provenance(const PolyMesh& mesh, const RefineRequest& request) const;
    /// The last level of refine(), for callers that compare only that one; an implementation
    /// that can make it without the levels before it overrides this.
    virtual PolyMesh refine_last(const PolyMesh& mesh, const RefineRequest& request) const;
    /// The same refinement kept in the implementation's own structures, for timing; returns
    /// the number of output faces.
    virtual size_t refine_native(const TriMesh& mesh, const RefineRequest& request) const;
    /// The same for a polygon scheme on a polygon mesh (Catmull-Clark): the implementation's
    /// fastest way, its own mesh built from ours and nothing converted back.
    virtual size_t refine_polygons_native(const PolyMesh& mesh, const RefineRequest& request) const;
    /// `request.levels` levels, then the limit position and normal of every vertex of that level.
    virtual adapters::LimitPoints limit_points(const PolyMesh& mesh, const RefineRequest& request) const;
    /// The limit surface of face `face` at each (u, v) (boundary rule edge-only).
    virtual adapters::LimitEvaluation limit_surface(const PolyMesh& mesh, Scheme scheme, int face,
                                                    std::span<const std::array<double, 2>> uv) const;
    /// Every set of vertex normals it computes.
    virtual std::vector<NamedNormals> vertex_normals(const TriMesh& mesh) const;
    /// A copy of `base` in its own structures, to be flipped and split.
    virtual std::unique_ptr<EditSession> open_edit(const TriMesh& base) const;
    /// The spline of `control` and its first two derivatives at each parameter.
    virtual adapters::SplineSamples evaluate_spline(SplineKind kind, std::span<const Vec3> control,
                                                    std::span<const double> params) const;
    virtual adapters::ClosedMeshReport closed_mesh_report(const TriMesh& mesh) const;
    /// Principal curvatures of every vertex. @throws InputError or adapters::Rejected for a
    /// mesh the estimator cannot take (non-manifold), naming the element.
    virtual PrincipalCurvatures curvatures(const TriMesh& mesh) const;
    /// The two-sided (symmetric) Hausdorff distance between two triangle meshes.
    /// @throws adapters::Rejected for a mesh it cannot take, naming the element.
    virtual double hausdorff_distance(const TriMesh& a, const TriMesh& b) const;
    /// The mesh with edges collapsed until fewer than `edges` remain, topology kept.
    /// @throws adapters::Rejected for a mesh it cannot take, naming the element.
    virtual TriMesh simplify(const TriMesh& mesh, int edges) const;
    /// The isosurface of `grid` at `options.level` by the implementation's marching cubes named
    /// `method` (scikit-image: "lewiner", MC33, or "lorensen", 1987).
    /// @throws ImplementationFailure naming how the run failed (RunStatus::Unavailable when the
    ///         implementation is not on this machine), adapters::Rejected for a method it lacks.
    virtual TriMesh isosurface(const ScalarGrid& grid, const IsosurfaceOptions& options, const std::string& method) const;

protected:
    /// adapters::Rejected("<name> has no <what>").
    [[noreturn]] void lacks(const std::string& what) const;
    /// Refuses a scheme it lacks (adapters::Rejected). Tags are refused by the adapters of
    /// libraries without crease rules, in the library's words.
    void check_refinable(Scheme scheme) const;

private:
    std::string name_, version_;
    ImplementationKind kind_;
    Capabilities capabilities_;
};

/// Why `impl` is not run on `mesh` under `scheme`: the mesh has hierarchical edits and the
/// implementation does not declare them (SchemeSupport::hierarchical_edits), so it would drop
/// them and refine another surface. "" when it may run.
std::string hierarchical_edits_refusal(const Implementation& impl, Scheme scheme, const PolyMesh& mesh);

/// `impl.refine(mesh, request)` in a child process with a time limit and its heap filled with
/// `heap_fill` (run_isolated), so that a crash, a hang or an exception is recorded as the run's
/// outcome; an implementation that confines itself runs here. With `isolate` false everything
/// runs here (debugging). A result with a non-finite coordinate is NonFiniteOutput, naming the
/// first such vertex, and keeps its trace.
IsolatedTrace refine_isolated(const Implementation& impl, const PolyMesh& mesh, const RefineRequest& request,
                              double timeout_seconds, bool isolate, int heap_fill = kHeapFill);

}  // namespace crossdiv::verification
