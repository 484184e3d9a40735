// The Python module `crossdiv`: meshes and curves in and out as numpy arrays, subdivision by
// core or any reference, the subdivision matrix as scipy.sparse, and the Loop comparison with
// a Python function as the implementation under test.
//
// Arrays going out are not copied: the module moves the mesh's own vectors into a capsule the
// array keeps alive (a Vec3 is three contiguous doubles, so positions are an n x 3 array as
// they lie). Arrays coming in are read once into the mesh.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <csignal>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/io/curve_io.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/catmull_clark_streaming.h"
#include "crossdiv/subdiv/loop_streaming.h"
#include "crossdiv/verification/comparisons/invariance.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/verification/implementations/callback_implementation.h"
#include "crossdiv/verification/implementations/refine_or_throw.h"
#include "crossdiv/verification/implementations/output_size.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/implementations/tag_rules.h"

namespace py = pybind11;
using namespace crossdiv;
using namespace crossdiv::verification;

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "positions are read as an n x 3 array in place");

/// A numpy array over `values`, which it then owns (moved, not copied).
template <class T>
py::array_t<T> owning_array(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
    auto* held = new std::vector<T>(std::move(values));
    py::capsule owner(held, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    return py::array_t<T>(shape, held->data(), owner);
}

py::array_t<double> positions_array(std::vector<Vec3>&& positions) {
    auto* held = new std::vector<Vec3>(std::move(positions));
    py::capsule owner(held, [](void* p) { delete static_cast<std::vector<Vec3>*>(p); });
    return py::array_t<double>({static_cast<py::ssize_t>(held->size()), py::ssize_t{3}},
                               reinterpret_cast<const double*>(held->data()), owner);
}

/// F as an m x k int32 array when every face has k corners, else a list of int32 arrays.
py::object faces_object(PolyMesh& mesh) {
    const int m = mesh.num_faces();
    const int k = m > 0 ? mesh.face_size(0) : 3;
    bool uniform = true;
    for (int f = 0; f < m && uniform; ++f) uniform = mesh.face_size(f) == k;
    if (uniform) return owning_array<int>(std::move(mesh.face_vertices), {m, k});
    py::list faces;
    for (int f = 0; f < m; ++f)
        faces.append(py::array_t<int>(mesh.face_size(f), mesh.face(f)));
    return faces;
}

py::tuple mesh_tuple(PolyMesh&& mesh) {
    py::object faces = faces_object(mesh);
    return py::make_tuple(positions_array(std::move(mesh.positions)), faces);
}

/// One index of F as a whole number: a Python or NumPy integer, or a float with a whole,
/// finite value (2.0); a bool, a fraction (1.999999999 would be truncated to 1), a NaN or
/// anything else is refused, naming face `f` and corner `c`.
long long vertex_index(const py::handle index, size_t f, size_t c) {
    const std::string where = "F face " + std::to_string(f) + " corner " + std::to_string(c) + ": ";
    const std::string type = py::str(py::type::handle_of(index).attr("__name__"));
    if (py::isinstance<py::bool_>(index) || type == "bool_") throw InputError(where + "a bool is not a vertex index");
    if (py::hasattr(index, "__index__")) {  // int and NumPy's integers
        try {
            return py::int_(index.attr("__index__")()).cast<long long>();
        } catch (const py::error_already_set&) {
            throw InputError(where + py::str(index).cast<std::string>() + " does not fit a 64-bit index");
        } catch (const py::cast_error&) {
            throw InputError(where + py::str(index).cast<std::string>() + " does not fit a 64-bit index");
        }
    }
    if (py::isinstance<py::float_>(index) || type.starts_with("float")) {
        const double d = index.cast<double>();
        if (!std::isfinite(d) || d != std::floor(d) || std::abs(d) > 9.0e15)
            throw InputError(where + py::str(py::repr(index)).cast<std::string>() + " is not a whole number");
        return static_cast<long long>(d);
    }
    throw InputError(where + "a " + type + " is not a vertex index");
}

/// V as float64 positions. Refused when its values are not real numbers, rather than cast:
/// complex values would lose their imaginary parts, bools and strings are no coordinates.
py::array_t<double, py::array::c_style | py::array::forcecast> positions_of(const py::object& V) {
    const py::array a = py::array::ensure(V);
    if (!a) throw InputError("V must be an n x 3 array of numbers");
    const char kind = a.dtype().kind();
    if (kind == 'c') throw InputError("V is complex: positions are real numbers (the imaginary parts would be dropped)");
    if (kind == 'b') throw InputError("V holds bools, not coordinates");
    if (kind == 'U' || kind == 'S') throw InputError("V holds strings, not coordinates");
    auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!d) throw InputError("V must be an n x 3 array of numbers (its values do not convert to float64)");
    return d;
}

/// The faces of F (an m x k integer array, or a sequence of index sequences), each handed to
/// `add` as indices checked against `count` targets. `what` names the argument ("F", "FUV"),
/// `element` what its indices name ("vertex", "texture coordinate") in messages.
template <class Add>
void read_faces(const py::object& F, long long count, const char* what, const char* element, const char* targets,
                const Add& add_face) {
    std::vector<long long> corners;
    std::vector<int> face;
    const auto add = [&](size_t f) {
        if (corners.size() < 3) throw InputError(std::string(what) + " face " + std::to_string(f) + " has fewer than 3 corners");
        face.clear();
        for (size_t c = 0; c < corners.size(); ++c) {
            if (corners[c] < 0 || corners[c] >= count)
                throw InputError(std::string(what) + " face " + std::to_string(f) + " corner " + std::to_string(c) + ": " +
                                 element + " " + std::to_string(corners[c]) + " is not in " + targets + " (" +
                                 std::to_string(count) + " rows)");
            face.push_back(static_cast<int>(corners[c]));
        }
        add_face(face);
    };
    if (py::isinstance<py::array>(F) && py::array(F).ndim() == 2) {
        const py::array array(F);
        const char kind = array.dtype().kind();
        if (kind == 'i' || kind == 'u') {
            const auto faces = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(F);
            if (!faces) throw InputError(std::string(what) + " must be an array of integer indices");
            const auto f = faces.unchecked<2>();
            for (py::ssize_t i = 0; i < faces.shape(0); ++i) {
                corners.assign(f.data(i, 0), f.data(i, 0) + faces.shape(1));
                add(static_cast<size_t>(i));
            }
            return;
        }
        // Any other dtype (floats, bools, strings, objects): index by index, as a sequence.
    }
    size_t i = 0;
    for (const py::handle row : F) {
        corners.clear();
        for (const py::handle index : row) corners.push_back(vertex_index(index, i, corners.size()));
        add(i++);
    }
}

/// A mesh from V (n x 3, any real dtype) and F (an m x k integer array, or a sequence of
/// index sequences). @throws InputError naming the face and corner of an index out of range,
/// or a non-finite coordinate.
PolyMesh mesh_from(const py::object& V_given, const py::object& F) {
    const py::array_t<double, py::array::c_style | py::array::forcecast> V = positions_of(V_given);
    if (V.ndim() != 2 || V.shape(1) != 3) {
        std::string shape;
        for (py::ssize_t d = 0; d < V.ndim(); ++d) {
            if (d > 0) shape += ", ";
            shape += std::to_string(V.shape(d));
        }
        throw InputError("V must be an n x 3 array of positions (got shape (" + shape + "))");
    }
    PolyMesh mesh;
    const auto v = V.unchecked<2>();
    mesh.positions.resize(V.shape(0));
    for (py::ssize_t i = 0; i < V.shape(0); ++i) {
        mesh.positions[i] = Vec3(v(i, 0), v(i, 1), v(i, 2));
        if (!mesh.positions[i].allFinite()) throw InputError("V row " + std::to_string(i) + " is not finite");
    }
    // Indices are checked as read (any integer width), before they become the mesh's ints.
    read_faces(F, mesh.num_vertices(), "F", "vertex", "V", [&](const std::vector<int>& face) { mesh.add_face(face); });
    return mesh;
}

/// `mesh` with the face-varying channel of UV (n x d values, d >= 1, any real dtype) and FUV
/// (its faces: one index into UV per corner of the matching face of F).
/// @throws InputError for values that are not finite real numbers, or an FUV whose faces do not
///         match F's in number and size, or an index out of range.
void add_channel(PolyMesh& mesh, const py::object& UV_given, const py::object& FUV) {
    const auto UV = positions_of(UV_given);  // the same checks as V: real numbers, converted to float64
    if (UV.ndim() != 2 || UV.shape(1) < 1) throw InputError("UV must be an n x d array of values (d >= 1)");
    FaceVaryingChannel ch;
    ch.dimension = static_cast<int>(UV.shape(1));
    const auto u = UV.unchecked<2>();
    for (py::ssize_t i = 0; i < UV.shape(0); ++i)
        for (py::ssize_t k = 0; k < UV.shape(1); ++k) {
            if (!std::isfinite(u(i, k))) throw InputError("UV row " + std::to_string(i) + " is not finite");
            ch.values.push_back(u(i, k));
        }
    int f = 0;
    read_faces(FUV, UV.shape(0), "FUV", "texture coordinate", "UV", [&](const std::vector<int>& face) {
        if (f >= mesh.num_faces() || mesh.face_size(f) != static_cast<int>(face.size()))
            throw InputError("FUV face " + std::to_string(f) + " has " + std::to_string(face.size()) + " corners where F " +
                             (f >= mesh.num_faces() ? std::string("has no such face")
                                                    : "face " + std::to_string(f) + " has " + std::to_string(mesh.face_size(f))));
        ch.corner_values.insert(ch.corner_values.end(), face.begin(), face.end());
        ++f;
    });
    if (f != mesh.num_faces())
        throw InputError("FUV has " + std::to_string(f) + " faces where F has " + std::to_string(mesh.num_faces()));
    mesh.face_varying = {std::move(ch)};
}

/// `mesh` given the channel of UV and FUV when they are given (both or neither), and the rule
/// it is refined under: `fvar` (a FaceVaryingRule name). Nothing without UV.
/// @throws InputError as add_channel, for one of UV and FUV alone, an unknown rule, or a scheme
///         without face-varying rules.
std::optional<FaceVaryingRule> with_channel(PolyMesh& mesh, Scheme scheme, const py::object& UV, const py::object& FUV,
                                            const std::string& fvar) {
    if (UV.is_none() != FUV.is_none()) throw InputError("UV and FUV go together: give both or neither");
    if (UV.is_none()) return std::nullopt;
    add_channel(mesh, UV, FUV);
    std::vector<std::string> notes;
    const std::optional<FaceVaryingRule> rule = face_varying_rule(scheme, fvar, mesh, notes);
    if (!rule) throw InputError(notes.empty() ? "no face-varying rule" : notes.front());
    return rule;
}

/// (UV, FUV) of a mesh's first channel: UV an n x d float64 array, FUV shaped as faces_object
/// shapes F.
py::tuple channel_tuple(PolyMesh& mesh) {
    FaceVaryingChannel& ch = mesh.face_varying.at(0);
    const py::ssize_t n = ch.num_values(), d = ch.dimension;
    PolyMesh faces;  // the channel's corners in the faces' shape
    faces.face_start = mesh.face_start;
    faces.face_vertices = std::move(ch.corner_values);
    return py::make_tuple(owning_array(std::move(ch.values), {n, d}), faces_object(faces));
}

RefineRequest request_for(const std::string& scheme_name, int levels, const std::optional<std::string>& weights,
                          const std::optional<std::string>& boundary) {
    RefineRequest req;
    req.scheme = scheme_from_string(scheme_name);
    if (levels < 0 || levels > 12) throw InputError("levels must be in 0..12 (got " + std::to_string(levels) + ")");
    req.levels = levels;
    req.rule = rule_from_boundary_name(req.scheme, boundary.value_or(""));
    if (weights) {
        if (req.scheme != Scheme::Loop) throw InputError("weights name a Loop weight family; " + scheme_name + " has none");
        req.rule.loop.weights = loop_weights_from_string(*weights);
    }
    return req;
}

py::object json_to_python(const nlohmann::json& j) {
    return py::module_::import("json").attr("loads")(json_text(j));
}

/// A Python function subject(V, F) -> (V, F) refining one level of `scheme`, as an
/// implementation: level k is k calls. It runs in the harness's forked child like any
/// implementation, so an exception, a crash or a hang there is the run's outcome, not the caller's.
std::unique_ptr<Implementation> python_subject(const std::string& name, Scheme scheme, py::object subject) {
    RefineFunction refine = [subject](const PolyMesh& mesh, const RefineRequest& request) {
        PolyMesh copy = mesh;
        py::object V = positions_array(std::move(copy.positions));
        py::object F = faces_object(copy);
        for (int l = 0; l < request.levels; ++l) {
            py::object result = subject(V, F);
            py::tuple pair = result.cast<py::tuple>();
            if (pair.size() != 2) throw InputError("the subject must return (V, F)");
            V = pair[0];
            F = pair[1];
        }
        return mesh_from(V, F);
    };
    return make_callback_implementation(name, {scheme}, std::move(refine));
}

/// Whether the thread forking for run_isolated holds the interpreter's lock: only then does the
/// child run Python (a subject) and need the interpreter made whole again; a library reference
/// forks with the lock released and its child never touches Python.
thread_local bool forking_with_python = false;

void before_fork() {
    forking_with_python = PyGILState_Check() != 0;
    if (forking_with_python) PyOS_BeforeFork();
}
void after_fork_in_parent() {
    if (forking_with_python) PyOS_AfterFork_Parent();
}
void after_fork_in_child() {
    if (forking_with_python) {
        PyOS_AfterFork_Child();
        return;
    }
    // A library's child never runs Python: its crash is the outcome, told by the signal, not a
    // "Fatal Python error" from the interpreter's fault handler on the caller's terminal.
    for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(sig, SIG_DFL);
}

}  // namespace

PYBIND11_MODULE(crossdiv, m) {
    set_fork_hooks({before_fork, after_fork_in_parent, after_fork_in_child});
    m.doc() = "crossdiv: subdivision and curves, with the references side by side (numpy in and out).";
    py::register_exception<InputError>(m, "InputError", PyExc_ValueError);

    m.def("read_mesh", [](const std::string& path) { return mesh_tuple(read_mesh(path)); }, py::arg("path"),
          "Reads OBJ, OFF or PLY: (V, F), V an n x 3 float64 array, F an m x k int32 array (a list of "
          "arrays when face sizes differ). Raises crossdiv.InputError naming the file and line.");
    m.def("write_mesh", [](const std::string& path, const py::object& V,
                           const py::object& F) { write_mesh(path, mesh_from(V, F)); },
          py::arg("path"), py::arg("V"), py::arg("F"), "Writes OBJ, OFF or PLY by the extension.");
    m.def("read_curves", [](const std::string& path) {
              const CurveFile file = read_curve_file(path);
              py::list curves;
              for (const CurveRecord& r : file.curves) {
                  std::vector<Vec3> control = r.control;
                  py::dict d;
                  d["name"] = r.name;
                  d["keyword"] = r.keyword;
                  d["type"] = std::string(to_string(r.type));
                  d["dim"] = r.dim;
                  d["steps"] = r.steps;
                  d["control"] = positions_array(std::move(control));
                  curves.append(d);
              }
              return curves;
          },
          py::arg("path"),
          "Reads SWP or BZC: a list of dicts {name, keyword ('bez2', 'bsp3', ...), type, dim, steps, control "
          "(n x 3)}.");
    m.def("write_curves", [](const std::string& path, const py::list& curves) {
              CurveFile file;
              for (const py::handle h : curves) {
                  const py::dict d = h.cast<py::dict>();
                  const std::string keyword = d["keyword"].cast<std::string>();
                  // The type and dimension come from the keyword, as the reader derives them.
                  CurveRecord r;
                  const std::optional<SplineKeyword> spline = spline_keyword(keyword);
                  if (!spline)
                      throw InputError("write_curves: keyword '" + keyword + "' is not a spline record (bez2, bsp3, crm2, ...)");
                  r.keyword = keyword;
                  r.type = spline->type;
                  r.dim = spline->dim;
                  r.name = d.contains("name") ? d["name"].cast<std::string>() : "";
                  r.steps = d.contains("steps") ? d["steps"].cast<int>() : 16;
                  const auto control = d["control"].cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
                  if (control.ndim() != 2 || (control.shape(1) != 2 && control.shape(1) != 3))
                      throw InputError("write_curves: '" + r.name + "' control must be an n x 2 or n x 3 array");
                  const auto c = control.unchecked<2>();
                  for (py::ssize_t i = 0; i < control.shape(0); ++i)
                      r.control.emplace_back(c(i, 0), c(i, 1), control.shape(1) == 3 ? c(i, 2) : 0.0);
                  file.curves.push_back(std::move(r));
              }
              write_swp(path, file);
          },
          py::arg("path"), py::arg("curves"),
          "Writes curves (dicts as read_curves gives, keyword and control required) as SWP.");
    m.def("subdivide",
          [](const py::object& V, const py::object& F,
             const std::string& scheme, int levels, std::optional<std::string> weights, std::optional<std::string> boundary,
             const std::string& impl, long long max_faces, double timeout, const py::object& UV, const py::object& FUV,
             const std::string& fvar, int threads) -> py::tuple {
              RefineRequest req = request_for(scheme, levels, weights, boundary);
              const Implementation& implementation = find_implementation(impl);
              if (threads < 1) throw InputError("threads must be >= 1, got " + std::to_string(threads));
              PolyMesh mesh = mesh_from(V, F);
              req.face_varying = with_channel(mesh, req.scheme, UV, FUV, fvar);
              require_refined_size(mesh, req.scheme, levels, max_faces, "subdivide", "max_faces");
              PolyMesh out;
              {
                  py::gil_scoped_release unlocked;  // core and the references are C++ and do not touch Python
                  // Core's Loop on a manifold triangle mesh without tags or texture coordinates:
                  // the streaming driver, on `threads` (as crossdiv subdivide); otherwise the
                  // implementation's refinement, on one.
                  bool streamed = false;
                  if (impl == "core" && req.scheme == Scheme::Loop && !req.face_varying && mesh.creases.empty() &&
                      mesh.all_triangles()) {
                      try {
                          out = to_poly_mesh(loop_subdivide_streaming(to_tri_mesh(mesh, "Loop subdivision"), req.rule.loop,
                                                                      levels, threads));
                          streamed = true;
                      } catch (const NonManifoldInput&) {
                      }
                  } else if (impl == "core" && req.scheme == Scheme::CatmullClark && !req.face_varying) {
                      // A mesh it cannot stream it refines by the stencil driver (on one thread).
                      out = catmull_clark_subdivide_streaming(mesh, req.rule.catmull_clark, levels, threads);
                      streamed = true;
                  }
                  if (!streamed) out = refine_last_or_throw(implementation, mesh, req, "the mesh", timeout);
              }
              if (UV.is_none()) return mesh_tuple(std::move(out));
              if (out.face_varying.empty()) throw InputError(impl + " does not refine texture coordinates");
              py::tuple channel = channel_tuple(out);
              py::tuple vf = mesh_tuple(std::move(out));
              return py::make_tuple(vf[0], vf[1], channel[0], channel[1]);
          },
          py::arg("V"), py::arg("F"), py::arg("scheme") = "loop", py::arg("levels") = 1, py::arg("weights") = py::none(),
          py::arg("boundary") = py::none(), py::arg("impl") = "core", py::arg("max_faces") = kMaxRefinedFaces,
          py::arg("timeout") = 120.0, py::arg("UV") = py::none(), py::arg("FUV") = py::none(), py::arg("fvar") = "all",
          py::arg("threads") = 1,
          "Subdivides (V, F) by `levels` levels of `scheme` (loop, catmull-clark, doo-sabin, sqrt3, butterfly, "
          "modified-butterfly, bilinear, midpoint) with core or a reference (impl: core, opensubdiv, openmesh, cgal, ...), which applies "
          "the closest rule it has. Returns (V, F) in that implementation's numbering. A result of more than "
          "`max_faces` faces is refused before any work (crossdiv subdivide's --max-faces). A reference runs in a "
          "child process with `timeout` seconds: its crash, hang or refusal raises crossdiv.InputError naming it. "
          "With UV (n x d values) and FUV (one index into UV per corner of F, shaped as F): a face-varying channel "
          "(texture coordinates), refined under `fvar` (none, corners-only, corners-plus1, corners-plus2, boundaries, "
          "all) by loop, catmull-clark or bilinear; returns (V, F, UV, FUV). `threads`: core's Loop and "
          "Catmull-Clark on a manifold mesh without tags or texture coordinates run on that many (the same result, bit for bit, on any "
          "number); everything else runs on one.");
    m.def("subdivision_matrix",
          [](const py::object& V, const py::object& F,
             const std::string& weights, const std::string& boundary) {
              const PolyMesh mesh = mesh_from(V, F);
              const LoopOptions options{loop_weights_from_string(weights), loop_boundary_from_string(boundary)};
              Eigen::SparseMatrix<double, Eigen::RowMajor> S = loop_subdivision_matrix(to_tri_mesh(mesh, "subdivision_matrix"), options);
              S.makeCompressed();
              std::vector<double> data(S.valuePtr(), S.valuePtr() + S.nonZeros());
              std::vector<int> indices(S.innerIndexPtr(), S.innerIndexPtr() + S.nonZeros());
              std::vector<int> indptr(S.outerIndexPtr(), S.outerIndexPtr() + S.rows() + 1);
              const py::ssize_t nnz = S.nonZeros(), rows = S.rows(), cols = S.cols();
              return py::module_::import("scipy.sparse").attr("csr_matrix")(
                  py::make_tuple(owning_array(std::move(data), {nnz}), owning_array(std::move(indices), {nnz}),
                                 owning_array(std::move(indptr), {rows + 1})),
                  py::arg("shape") = py::make_tuple(rows, cols));
          },
          py::arg("V"), py::arg("F"), py::arg("weights") = "loop", py::arg("boundary") = "edge-only",
          "Loop's one-level subdivision matrix S (V1 = S @ V0; rows in core's output order: old vertices, then "
          "one per edge) as a scipy.sparse.csr_matrix.");
    m.def("compare",
          [](const py::object& V, const py::object& F, int levels,
             std::optional<std::string> weights, std::optional<std::string> boundary, std::vector<std::string> references,
             const std::string& tier, double tolerance, py::object subject, const std::string& subject_name,
             double timeout, const std::string& scheme, const py::object& UV, const py::object& FUV, const std::string& fvar) {
              if (levels < 1 || levels > 12) throw InputError("levels must be in 1..12 (got " + std::to_string(levels) + ")");
              const RefineRequest asked = request_for(scheme, levels, weights, boundary);
              RefinementRequest req;
              req.scheme = asked.scheme;
              req.rule = asked.rule;
              req.levels = levels;
              req.references = std::move(references);
              req.tier = tier_from_string(tier);
              req.tolerance = tolerance;
              req.timeout_seconds = timeout;
              std::unique_ptr<Implementation> under_test;
              if (!subject.is_none()) {
                  if (!PyCallable_Check(subject.ptr())) throw InputError("subject must be callable: subject(V, F) -> (V, F)");
                  under_test = python_subject(subject_name, req.scheme, subject);
                  req.subject = under_test.get();
              }
              PolyMesh mesh = mesh_from(V, F);
              req.face_varying = with_channel(mesh, req.scheme, UV, FUV, fvar);
              if (traits(req.scheme).triangles) (void)to_tri_mesh(mesh, "compare");  // a polygon is refused by name
              return json_to_python(to_json(compare_refinement(mesh, "python", req)));
          },
          py::arg("V"), py::arg("F"), py::arg("levels") = 2, py::arg("weights") = py::none(), py::arg("boundary") = py::none(),
          py::arg("references") = std::vector<std::string>{}, py::arg("tier") = "weak", py::arg("tolerance") = 1e-12,
          py::arg("subject") = py::none(), py::arg("subject_name") = "python", py::arg("timeout") = 120.0,
          py::arg("scheme") = "loop", py::arg("UV") = py::none(), py::arg("FUV") = py::none(), py::arg("fvar") = "all",
          "Compares `scheme` (loop, catmull-clark, doo-sabin, sqrt3, butterfly, modified-butterfly, bilinear, midpoint; "
          "weights for Loop, boundary as crossdiv compare names them, each the scheme's default when None) of "
          "(V, F) by core (or `subject`, a function of that scheme) with each reference that has it (all built when empty): "
          "the same record as `crossdiv compare --json` (runs, verdicts, divergence classes, worst vertex; with a "
          "subject, the named rule it follows). subject(V, F) -> (V, F) refines one level; it runs in a child "
          "process with `timeout` seconds, so its exception, crash or hang is recorded, not raised. With UV and "
          "FUV (as subdivide takes them), each run's texture coordinates are compared per face corner under `fvar` "
          "(the record's runs[i]['uv']).");

    m.def("invariance",
          [](const py::object& V, const py::object& F, const std::string& scheme, int levels, std::optional<std::string> weights,
             std::optional<std::string> boundary, std::vector<std::string> impls, std::vector<std::string> transforms,
             std::uint64_t seed, double tolerance, py::object subject, const std::string& subject_name, double timeout) {
              if (levels < 1 || levels > 12) throw InputError("levels must be in 1..12 (got " + std::to_string(levels) + ")");
              const RefineRequest request = request_for(scheme, levels, weights, boundary);
              std::vector<InputTransformation> ts;
              for (const std::string& t : transforms) ts.push_back(input_transformation_from_string(t));
              if (ts.empty()) ts.assign(kInputTransformations.begin(), kInputTransformations.end());
              std::unique_ptr<Implementation> under_test;
              std::vector<const Implementation*> checked;
              if (!subject.is_none()) {
                  if (!impls.empty()) throw InputError("impls and subject exclude each other");
                  if (!PyCallable_Check(subject.ptr())) throw InputError("subject must be callable: subject(V, F) -> (V, F)");
                  under_test = python_subject(subject_name, request.scheme, subject);
                  checked.push_back(under_test.get());
              } else if (!impls.empty()) {
                  for (const std::string& name : impls) checked.push_back(&find_implementation(name));
              } else {
                  checked.push_back(&core_implementation());
                  for (const Implementation* r : references_for(request.scheme)) checked.push_back(r);
              }
              for (const Implementation* impl : checked)
                  if (!impl->support(request.scheme))
                      throw InputError(impl->name() + " has no " + std::string(to_string(request.scheme)) + " refinement");
              PolyMesh mesh = mesh_from(V, F);
              if (traits(request.scheme).triangles) (void)to_tri_mesh(mesh, "invariance");  // a polygon is refused by name
              nlohmann::json rows = nlohmann::json::array();
              for (const Implementation* impl : checked) {
                  const InvarianceReport r = check_invariance(*impl, mesh, request, ts, seed, tolerance, timeout, true);
                  const std::vector<std::optional<InvarianceCause>> causes =
                      causes_of(*impl, mesh, request, r, seed, tolerance, timeout);
                  for (size_t i = 0; i < r.checks.size(); ++i) {
                      nlohmann::json row = to_json(r.checks[i]);
                      row["implementation"] = impl->name();
                      if (const std::optional<InvarianceCause>& why = causes[i])
                          row["cause"] = {{"class", to_string(why->cls)}, {"why", why->why}};
                      rows.push_back(std::move(row));
                  }
              }
              return json_to_python(rows);
          },
          py::arg("V"), py::arg("F"), py::arg("scheme") = "loop", py::arg("levels") = 2, py::arg("weights") = py::none(),
          py::arg("boundary") = py::none(), py::arg("impls") = std::vector<std::string>{},
          py::arg("transforms") = std::vector<std::string>{}, py::arg("seed") = 1, py::arg("tolerance") = 1e-12,
          py::arg("subject") = py::none(), py::arg("subject_name") = "python", py::arg("timeout") = 120.0,
          "Whether each implementation's refinement of (V, F) depends on how the input is written, as `crossdiv "
          "invariance` checks it: core and every reference of `scheme` (or `impls`, or `subject`, a function "
          "subject(V, F) -> (V, F) refining one level, run in a child process) refine the mesh and the mesh with its "
          "corners rotated, faces reordered, vertices relabelled, orientation reversed, moved, scaled, mirrored, "
          "rotated, its connected components refined apart, its levels run one at a time, and run again (`transforms`: their names; all when empty). One dict per implementation and "
          "transformation: result (invariant, not-invariant, nondeterministic, not-compared), exact, bit_identical, "
          "max_rel, the worst vertex, the explanation, and for a finding its measured cause {class, why}.");
}
