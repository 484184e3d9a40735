"""The report's sections, each built once from results.json (and bench.json) as data."""
from collections import Counter

from . import figures
from .model import Figure, Interactive, Section, Table, Text, html_table
from .records import fmt, outcome, short_input, vec


def outcomes_section(summary):
    return Section("Outcomes").add(
        Table(["outcome", "runs"], sorted(summary["outcomes"].items())),
        Text("Failures (JUnit) are `ours-failed` and `diverge (unexplained)`; every other outcome is a measured, "
             "classified difference."))


def catalogue_rows(mesh_cases, check_cases):
    """Every run that is not plain agreement, with the case's worst vertex for comparisons."""
    rows = []
    for c in mesh_cases:
        w = c.get("worst_vertex")
        for r in c["runs"]:
            if r["verdict"] == "agree":
                continue
            diverges = w and r["verdict"] == "diverge"
            values = "-"
            if diverges:
                values = f"core {vec(w['core'])}; " + "; ".join(f"{n} {vec(p)}" for n, p in sorted(w["references"].items()))
            rows.append({"case": c["id"], "reference": r["reference"], "outcome": outcome(c, r),
                         "class": r.get("divergence_class") or r["verdict"],
                         "max_rel": r.get("positions", {}).get("max_rel"),
                         "worst": f"v{w['ours_index']} valence {w['valence']} {'boundary' if w['boundary'] else 'interior'}"
                         if diverges else "-", "values": values, "explanation": r.get("explanation", "")})
    for c in check_cases:
        for r in c["runs"]:
            if r["verdict"] == "agree":
                continue
            rows.append({"case": c["id"], "reference": r["reference"], "outcome": outcome(c, r),
                         "class": r.get("divergence_class") or r["verdict"], "max_rel": r["measured"],
                         "worst": r["subject"],
                         "values": f"{r['check']}: {fmt(r['measured'])} > {fmt(r['tolerance'])} {r['unit']}",
                         "explanation": r.get("explanation", "")})
    for c in mesh_cases + check_cases:
        if not c["runs"]:
            rows.append({"case": c["id"], "reference": "core", "outcome": outcome(c), "class": outcome(c), "max_rel": None,
                         "worst": "-", "values": "-", "explanation": c.get("core_error", "")})
    return rows


def subject_section(mesh_cases):
    """The implementations under test in core's place (manifest `subject`): per case, how it ran,
    how its vertices were matched, and the named rule it follows per vertex class. None when
    every case tested core."""
    cases = [c for c in mesh_cases if "subject" in c]
    if not cases:
        return None
    rows = []
    for c in cases:
        s = c["subject"]
        rules = s.get("rules") or {}
        unfit = [f"{k['class']}{' ' + str(k['valence']) if k['valence'] else ''}"
                 for k in rules.get("classes", []) if not any(f["fits"] for f in k["fits"])]
        rows.append((c["id"], s["name"], s["status"] if s["status"] != "ok" else s.get("match", {}).get("method", "-"),
                     rules.get("rule") or ("no named rule" if rules else "-"),
                     ", ".join(unfit) if unfit else "-", s.get("status_message") or s.get("unmatched") or ""))
    return Section("Implementations under test").add(
        Text("Each case whose implementation under test is a subject (a program or result files in core's place): "
             "its run or match, the named rule that fits every vertex at every compared level, and the vertex "
             "classes no named rule fits (results.json `subject.rules` has the distance to every rule per class)."),
        Table(["case", "subject", "run / match", "rule", "classes no rule fits", "message"], rows))


def catalogue_section(rows):
    """Every run that is not agreement: in index.html a collapsed table, in report.md a pointer
    to results.csv (the overview has one row per class with its representative)."""
    table = Table(["case", "reference", "outcome", "max rel", "worst vertex", "values at the worst vertex", "explanation"],
                  [(r["case"], r["reference"], r["outcome"], fmt(r["max_rel"]), r["worst"], r["values"], r["explanation"])
                   for r in rows])
    return Section("Divergence catalogue").add(
        Interactive(f"<details><summary>Every run that is not agreement ({len(rows)}), with the case's worst vertex "
                    "(where some reference parts most from core) and each implementation's value there</summary>"
                    f"{html_table(table)}</details>",
                    f"{len(rows)} runs are not agreement; results.csv lists every run, index.html every one of these "
                    "with the case's worst vertex and each implementation's value there."))


def mesh_sections(results, mesh_cases, folder, figdir):
    """The summary matrix, the error figures and the pictures of where surfaces part."""
    if not mesh_cases:
        return [], []
    refs = [r["name"] for r in results.get("references", [])]
    matrix = Section("Summary matrix").add(Figure(figures.summary_matrix(mesh_cases, refs, figdir), "summary"))
    errors = Section("Error by level and its distribution").add(
        Figure(figures.error_by_level(mesh_cases, figdir), "convergence"),
        Figure(figures.error_histogram(mesh_cases, figdir), "histogram"))
    pictures = figures.error_pictures(mesh_cases, folder, figdir)
    parts = Section("Where surfaces part")
    parts.add(*[Figure(p, p.split("/")[-1]) for p in pictures] or [Text("No divergence small enough to draw.")])
    return [matrix], [errors, parts]


def curve_section(curve_cases, bench, figdir):
    if not curve_cases and not (bench and bench.get("curves")):
        return None
    s = Section("Curves")
    rows = []
    for c in curve_cases:
        runs = c["runs"]
        failed = [r for r in runs if r["verdict"] != "agree"]
        worst = max(runs, key=lambda r: (r["measured"] / r["tolerance"]) if r["tolerance"] else
                    (0 if r["measured"] == 0 else float("inf")), default=None)
        eigen = max((r["measured"] for r in runs if r["reference"] == "eigen"), default=None)
        rows.append((c["input"].split("/")[-1].rsplit(".", 1)[0] if "/" in c["input"] else c["input"],
                     len(c.get("subjects", [])), len(runs), len(failed), fmt(eigen),
                     f"{worst['subject']} {worst['check']} ({fmt(worst['measured'])} of {fmt(worst['tolerance'])} "
                     f"{worst['unit']})" if worst else c.get("core_error", "-")))
    if rows:
        s.add(Text("Each check is measured <= tolerance (tolerances.h names and justifies each); Eigen is "
                   "`unsupported/Eigen/Splines` (Cox-de Boor), compared in position, first and second derivative."),
              Table(["input", "curves", "checks", "failed", "Eigen max rel", "closest to its tolerance"], rows))
    for c in curve_cases:
        t = c.get("tables", {})
        if "frames" in t:
            fr = t["frames"]
            s.add(Text(f"Frames on a helix ({fr['curve']}) against its exact rotation-minimizing frame:"),
                  Figure(figures.curve_frames(fr, figdir), "frames"),
                  Table(["steps", "h", "recursive (rad)", "double reflection (rad)"],
                        [(r["steps"], fmt(r["h"]), fmt(r["recursive_error_rad"]), fmt(r["rmf_error_rad"])) for r in fr["rows"]]))
        if "degrees" in t:
            s.add(Figure(figures.curve_degrees(t["degrees"], figdir), "degrees"))
    tess = (bench or {}).get("curves") or [row for c in curve_cases for row in c.get("tables", {}).get("tessellation", [])]
    if tess:
        s.add(Text("Tessellation: edges each mode needs for a distance tolerance, with the measured maximum deviation "
                   "(uniform: fewest equal steps per segment found by measuring; angle: largest angle tolerance that "
                   "meets it; distance: the guaranteed adaptive mode; Wang: the guaranteed uniform count per segment; "
                   "N*: the integral of sqrt(kappa / (8 tol)) ds, about the fewest edges any polyline on the curve "
                   "needs)" + (" from `crossdiv bench`" if (bench or {}).get("curves") else "") + ":"),
              Table(["curve", "tol", "uniform edges (dev)", "angle edges (dev, tol deg)", "distance edges (dev)",
                     "Wang edges (dev)", "N*", "distance / N*"],
                    [(r["curve"], fmt(r["tol"]), f"{r['uniform_edges']} ({fmt(r['uniform_dev'])})",
                      f"{r['angle_edges']} ({fmt(r['angle_dev'])}, {fmt(r['angle_tol_deg'])})" if r["angle_reached"]
                      else f"{r['angle_edges']} (cap: {fmt(r['angle_dev'])})",
                      f"{r['distance_edges']} ({fmt(r['distance_dev'])})",
                      f"{r['wang_edges']} ({fmt(r['wang_dev'])})" if r.get("wang_edges") is not None else "-",
                      fmt(r.get("optimal_edges"), ".1f"),
                      fmt(r["distance_edges"] / r["optimal_edges"], ".2f") if r.get("optimal_edges") else "-")
                     for r in tess]))
        goal = (bench or {}).get("flattening_goal")
        if goal and any("tol_relative" in r for r in tess):
            s.add(Text(f"Goal: the distance mode within {goal['target_ratio']} N* at every tolerance of at most 1e-3 of "
                       f"the curve's size, and never more edges than the fewest equal steps: largest "
                       f"{fmt(goal['largest_ratio'], '.3f')} ({goal['largest_at']}), {goal['rows_above_uniform']} row(s) "
                       f"above the uniform count - {'met' if goal['met'] else 'NOT met'}."),
                  Figure(figures.flattening(tess, goal["target_ratio"], figdir), "flattening"))
    for i, c in enumerate(curve_cases):
        shapes = c.get("tables", {}).get("shapes")
        if shapes:
            s.add(Text(f"{c['input']}: Kochanek-Bartels (tension, continuity, bias per key) and Bessel-Overhauser "
                       "(chord-length knots) curves:"),
                  Figure(figures.interpolating_splines(shapes, figdir, f"interpolating_splines_{i}.png"), c["input"]))
    for i, c in enumerate(curve_cases):
        for j, row in enumerate(c.get("tables", {}).get("orientations", [])):
            s.add(Text(f"{c['input']} {row['curve']}: positions a cubic Bezier chain, orientations the quaternion "
                       "Bezier chain of its control quaternions (de Casteljau with slerp), drawn as the rotation's "
                       "columns:"),
                  Figure(figures.orientation_frames(row, figdir, f"orientation_frames_{i}_{j}.png"), row["curve"]))
    for i, c in enumerate(curve_cases):
        kappa = c.get("tables", {}).get("kappa")
        if not kappa:
            continue
        s.add(Text(f"{c['input']}: closed kappa-curves (Yan et al. 2017), one quadratic piece per point, run until the "
                   "middle points are estimated within 1e-13 of the diagonal from the iteration's fixed point. "
                   "Measured on the result: the point on its piece, the distance from the point to where the piece "
                   "is slowest (its |curvature| maximum), the angle between the tangents at a joint (G1), the "
                   "relative jump of |curvature| there (G2; the sign flips at inflections), and the largest "
                   "|curvature| times the diagonal (a cusp at a point shows as a large value):"),
              Table(["curve", "points", "iterations", "contraction", "est. distance", "on piece", "at max |kappa|",
                     "G1 angle", "|kappa| jump", "inflections", "max |kappa| diag"],
                    [(r["curve"], len(r["points"]), r["iterations"], fmt(r["contraction"], ".3f"),
                      fmt(r["error_estimate"]), fmt(r["measures"]["interpolation"]),
                      fmt(r["measures"]["curvature_maximum"]), fmt(r["measures"]["tangent_angle"]),
                      fmt(r["measures"]["curvature_jump"]), r["measures"]["inflections"],
                      fmt(r["measures"]["sharpest"])) for r in kappa]),
              Figure(figures.kappa_convergence(kappa, figdir, f"kappa_convergence_{i}.png"), "kappa convergence"))
        for j, row in enumerate(kappa):
            s.add(Figure(figures.kappa_curve(row, figdir, f"kappa_curve_{i}_{j}.png"), row["curve"]))
    hard = [row for c in curve_cases for row in c.get("tables", {}).get("kappa_hard_cases", [])]
    if hard:
        s.add(Text("The kappa-curve iteration on hard cases: a spike (4 points) narrowing to 1 degree, points "
                   "closer and closer to a line, and spikes whose back point is close, where the iteration "
                   "contracts by about 0.99 per step. \"converged, ill-conditioned\": the estimate was met but "
                   "the curvature maximum is off by more than 1e-9 (the fixed point is that sensitive); "
                   "\"not converged\": the iteration gave up after its cap, and `crossdiv` refuses such a record:"),
              Table(["family", "case", "iterations", "outcome", "last move", "est. distance", "contraction",
                     "at max |kappa|", "|kappa| jump"],
                    [(r["family"], r["case"], r["iterations"], r["outcome"], fmt(r["residual"]),
                      fmt(r["error_estimate"]), fmt(r["contraction"], ".3f"), fmt(r["measures"]["curvature_maximum"]),
                      fmt(r["measures"]["curvature_jump"])) for r in hard]))
    spline_types = ("catmull-rom", "tcb", "bessel-overhauser")
    continuity = [row for c in curve_cases for row in c.get("tables", {}).get("continuity", [])
                  if row["type"].startswith(spline_types)]
    if continuity:
        s.add(Text("Continuity of the interpolating splines: the largest jump of position, first and second "
                   "derivative (in the chain's parameter, one unit per segment) at a joint, over the curve's size. "
                   "Catmull-Rom is C1; TCB jumps in the first derivative by (1-t) c ((1+b)(p_i - p_{i-1}) - (1-b)"
                   "(p_{i+1} - p_i)) (checked against that formula), so it is C1 where c = 0; Bessel-Overhauser is C1 "
                   "in the chord-length parameter (checked there), so its jump here is the chords' speed change:"),
              Table(["curve", "type", "joints", "C0 gap", "C1 jump", "C2 jump"],
                    [(r["curve"], r["type"], r["joints"], fmt(r["c0_gap_rel"]), fmt(r["c1_jump_rel"]),
                      fmt(r["c2_jump_rel"])) for r in continuity]))
    closure = [row for c in curve_cases for row in c.get("tables", {}).get("closure", [])]
    if closure:
        s.add(Text("Frame mismatch after one lap of each closed curve (before and after distributing it):"),
              Table(["curve", "method", "mismatch (deg)", "after (deg)"],
                    [(r["curve"], r["method"], fmt(r["mismatch_deg"]), fmt(r["after_distribution_deg"])) for r in closure]))
    return s


def surface_section(surface_cases, bench, figdir):
    sweep = (bench or {}).get("adaptive_sweep")
    if not surface_cases and not sweep:
        return None
    s = Section("Surfaces")
    built = [r for c in surface_cases for r in c.get("tables", {}).get("surfaces", [])]
    if built:
        s.add(Text("Every surface built; closed ones must be watertight, manifold and outward (our checks and CGAL's)."),
              Table(["surface", "kind", "faces", "closed", "boundary edges", "signed volume", "CGAL outward", "fold faces"],
                    [(r["surface"], r.get("kind", ""), r["faces"], "yes" if r["closed"] else "no", r["boundary_edges"],
                      fmt(r["signed_volume"]), ("yes" if r["cgal"]["outward"] else "NO") if "cgal" in r else "-",
                      r.get("fold", {}).get("faces", 0)) for r in built]))
    cornered = [r for r in built if r.get("corners")]
    if cornered:
        s.add(Text("Generalized cylinders along sweeps with corners: at each corner the frames turn by the corner's "
                   "smallest rotation and the ring lies in the mitre plane; the largest departure of a corner ring "
                   "point from either tube's wall, over the profile radius:"),
              Table(["surface", "corners", "wall thickness error", "signed volume"],
                    [(r["surface"], r["corners"], fmt(r.get("corner_thickness_rel")), fmt(r["signed_volume"]))
                     for r in cornered]))
        for i, r in enumerate(x for x in cornered if x.get("mesh")):
            s.add(Figure(figures.surface_mesh(r["mesh"], r["surface"], figdir, f"cornered_sweep_{i}.png"), r["surface"]))
    for c in surface_cases:
        t = c.get("tables", {})
        if "sphere" in t or "torus" in t:
            s.add(Figure(figures.surface_convergence(t, figdir), "surfaces against exact surfaces"),
                  Table(["surface", "fitted order"], [(r["surface"], fmt(r["fitted_order"])) for key in ("sphere", "torus")
                                                      for r in t.get(key, []) if "fitted_order" in r]))
        if "bfr" in t:
            s.add(Text("Catmull-Clark limit of regular grids: our bicubic Bezier form against OpenSubdiv's Bfr."),
                  Table(["grid", "faces", "regular (Bfr)", "samples", "position rel", "derivatives rel"],
                        [(r["grid"], r["faces"], r["regular"], r["samples"], fmt(r["max_position_rel"]),
                          fmt(r["max_derivative_rel"])) for r in t["bfr"]]))
    if sweep:
        u, a, seed = sweep["uniform"], sweep["adaptive"], sweep["seed"]
        s.add(Text(f"Adaptive sweep ({sweep['input']}): uniform / adaptive faces {sweep['ratio']:.2f}, the seed's "
                   f"{seed['uniform_faces']} / {seed['adaptive_faces']} = {seed['ratio']:.2f} - "
                   f"{'beats' if sweep.get('beats_seed') else 'does NOT beat'} the seed's ratio at equal measured deviation "
                   f"(the profile takes, at each radius, the tolerance the slices leave there)."),
              Table(["wineglass", "faces", "slices", "profile samples", "deviation"],
                    [("uniform (the record's steps)", u["faces"], u["slices"], u["profile_samples"], fmt(u["deviation"])),
                     ("adaptive, equal measured deviation", a["faces"], a["slices"], a["profile_samples"],
                      fmt(a["deviation"]))]))
    return s


def schemes_section(cases):
    """Every scheme other than Loop against every reference that has it, per input: how many
    inputs end in each verdict and class, per requested rule and the rule the reference applies."""
    if not cases:
        return None
    counts = Counter()
    for c in cases:
        if not c["runs"]:
            counts[(c["operation"], c["levels"], c["options"]["boundary"], "core", "-", outcome(c))] += 1
        for r in c["runs"]:
            counts[(c["operation"], c["levels"], c["options"]["boundary"], r["reference"], r.get("rule", "-"),
                    outcome(c, r))] += 1
    return Section("Every scheme against its references").add(
        Text("Each scheme's cases, one per input: core against every reference that has the scheme. A divergence's "
             "class is measured (core re-run with the reference's rule agrees, or only the vertices a named cause "
             "reaches differ); `diverge (unexplained)` fails the suite."),
        Table(["scheme", "levels", "requested rule", "reference", "its rule", "outcome", "inputs"],
              [k + (n,) for k, n in sorted(counts.items(), key=lambda kv: tuple(map(str, kv[0])))]))


def studies_section(study_cases, figdir):
    """Schemes and limit behaviour, from the study operations' tables."""
    if not study_cases:
        return None
    tables = {}
    for c in study_cases:
        for k, v in c.get("tables", {}).items():
            tables.setdefault(k, []).extend(v)
    s = Section("Schemes and limit behaviour")
    if tables.get("vertex_age"):
        rows = tables["vertex_age"]
        s.add(Text("Vertex age: the vertices core's levels add, by the level they were born at (its numbering keeps "
                   "old vertices first), against the count the level before's topology dictates: V, then one per "
                   "edge (Loop, Butterflies), per edge and face (Catmull-Clark), per face (sqrt3); Doo-Sabin, dual, "
                   "replaces every vertex:"),
              Table(["scheme", "input", "levels", "vertices per level", "born at each level", "expected"],
                    [(r["scheme"], r["input"], r["levels"], " / ".join(map(str, r["vertex_counts"])),
                      " / ".join(map(str, r["born"])), " / ".join(map(str, r["expected"]))) for r in rows]))
        pictured = [r for r in rows if r.get("mesh")]
        if pictured:
            s.add(Figure(figures.vertex_age(pictured, figdir), "vertex age"))
    if tables.get("curvature_convergence"):
        rows = tables["curvature_convergence"]
        s.add(Text("Discrete curvature (core: cotangent Laplacian, mixed Voronoi areas, angle defect, Meyer et al. "
                   "2002; CGAL: Monge_via_jet_fitting, a degree-2 jet over the 2-ring) against the exact unit sphere "
                   "and torus (R 1, r 0.4) as the meshes are refined; errors are the largest over the vertices:"),
              Table(["surface", "estimator", "vertices", "h", "max |H err|", "max |K err|", "max direction err (rad)"],
                    [(r["surface"], r["estimator"], r["vertices"], fmt(r["h"]), fmt(r["mean_max"]), fmt(r["gauss_max"]),
                      fmt(r["direction_max"]) if r["surface"] != "sphere" else "umbilic") for r in rows]),
              Figure(figures.curvature_convergence(rows, figdir), "curvature convergence"))
    if tables.get("curvature_figure"):
        s.add(Figure(figures.curvature_mesh(tables["curvature_figure"], figdir), "curvature colouring"))
    if tables.get("gauss_bonnet"):
        rows = tables["gauss_bonnet"]
        held = [r for r in rows if "refused" not in r]
        refused = [r for r in rows if "refused" in r]
        s.add(Text(f"Discrete Gauss-Bonnet: the angle defects (turning angles on a boundary) sum to 2 pi chi on "
                   f"{len(held)} manifold meshes; {len(refused)} meshes are refused (the operators need a manifold "
                   f"triangle mesh). Largest error: {fmt(max((r['error'] for r in held), default=0))} rad."),
              Table(["mesh", "V", "F", "boundary vertices", "chi", "sum of defects", "|error|", "bound"],
                    [(r["mesh"], r["vertices"], r["faces"], r["boundary_vertices"], r["chi"], fmt(r["total_defect"]),
                      fmt(r["error"]), fmt(r["bound"])) for r in held]))
        if refused:
            s.add(Table(["refused mesh", "why"], [(r["mesh"], r["refused"]) for r in refused]))
    if tables.get("loop_curvature_growth"):
        rows = tables["loop_curvature_growth"]
        s.add(Text("Loop's Gaussian curvature at a vertex of valence n, on the limit points of its ring, level after "
                   "level: it changes by (nu / lambda^2)^2 per level, lambda = 3/8 + cos(2 pi / n) / 4 and nu the larger "
                   "of 3/8 + cos(4 pi / n) / 4 and 1/8. It grows without bound at valence 3 and above 6, stays at 6 and "
                   "tends to 0 at 4 and 5 (a flat spot)."),
              Table(["valence", "lambda", "nu", "predicted ratio", "measured ratio (last level)", "K level 0",
                     "K last level"],
                    [(r["valence"], fmt(r["lambda"]), fmt(r["nu"]), fmt(r["predicted_ratio"]), fmt(r["ratio"][-1]),
                      fmt(r["gaussian"][0]), fmt(r["gaussian"][-1])) for r in rows]),
              Figure(figures.loop_curvature_growth(rows, figdir), "Loop curvature growth"))
    if tables.get("isosurface_convergence"):
        rows = tables["isosurface_convergence"]
        s.add(Text("Marching cubes with the asymptotic decider (one shared vertex per crossed grid edge, each cube's "
                   "polygons traced face by face) on implicit surfaces sampled at growing resolutions: the largest "
                   "distance of a vertex to the exact surface (the signed distance itself for the sphere and torus, a "
                   "Newton projection along the gradient otherwise), the Euler characteristic, edges of one triangle "
                   "and mesh errors (non-manifold, orientation), the enclosed volume against the exact one. The gyroid "
                   "is cut by its box: its boundary edges are the cut."),
              Table(["surface", "samples", "h", "V", "F", "max distance", "chi (exact)", "boundary edges", "mesh errors",
                     "volume error"],
                    [(r["surface"], " x ".join(map(str, r["grid"])), fmt(r["h"]), r["vertices"], r["faces"],
                      fmt(r["max_distance"]), f"{r['euler']} ({r['expected_euler']})" if "expected_euler" in r else r["euler"],
                      r["boundary_edges"], r["mesh_errors"], fmt(r["volume_error"]) if "volume_error" in r else "")
                     for r in rows]),
              Figure(figures.isosurface_convergence(rows, figdir), "isosurface convergence"))
    if tables.get("isosurface_ambiguity"):
        rows = tables["isosurface_ambiguity"]

        def facts(r):
            return "failed: " + r["failed"] if "failed" in r else f"{r['boundary_edges']} / {r['mesh_errors']} / {r['euler']}"
        s.add(Text("A field whose faces are ambiguous by construction (pseudo-random samples inside an outside shell). "
                   "The asymptotic decider joins a face's inside corners when the bilinear saddle is inside: decided by "
                   "the face alone, so the two cubes of a face agree and the surface is closed. The minority rule (how "
                   "Lorensen and Cline's table with complementary cases folded together resolves a face) lets two cubes "
                   "decide one face differently: holes. scikit-image's MC33 (Lewiner) and 1987 tables on the same "
                   "samples. Each cell: boundary edges / mesh errors / Euler characteristic."),
              Table(["samples", "ambiguous faces", "decider", "minority", "skimage MC33", "skimage 1987"],
                    [(f"{r['samples']}^3", r["decider"]["ambiguous_faces"], facts(r["decider"]), facts(r["minority"]),
                      facts(r["skimage_lewiner"]), facts(r["skimage_lorensen"])) for r in rows]))
    if tables.get("isosurface_reference"):
        def compared(r):
            if "agreement" not in r:  # scikit-image did not run: its status and words
                return (r["subject"], r["status"], "", "", "", "", r.get("explanation", ""))
            return (r["subject"], r["status"], r["agreement"], fmt(r["max_vertex_distance"]), fmt(r["tolerance"]),
                    f"{r['faces_only_ours']} / {r['faces_only_theirs']}", f"{r['ours']['euler']} / {r['theirs']['euler']}")
        s.add(Text("scikit-image's marching cubes (Lewiner's MC33 table, on the samples rounded to float32) against "
                   "ours: vertices matched to float32 rounding, triangles compared through the match. The same crossings "
                   "triangulated otherwise is `triangulation`; another Euler characteristic or boundary is `topology` "
                   "(MC33 also tests the cube's interior, and adds a vertex inside some cubes)."),
              Table(["samples", "status", "agreement", "max vertex distance", "tolerance", "triangles only ours / theirs",
                     "chi ours / theirs"], [compared(r) for r in tables["isosurface_reference"]]))
    if tables.get("isosurface_figure"):
        s.add(Figure(figures.isosurface_meshes(tables["isosurface_figure"], figdir), "isosurfaces"))
    if tables.get("fitting_recovery"):
        rows = tables["fitting_recovery"]
        solved = [r for r in rows if "error" in r]
        singular = [r for r in rows if "singular" in r]
        s.add(Text("Subdivision surface fitting. The limit surface sampled at the vertices of level 2 is A X, A the "
                   "levels' subdivision matrices composed with the limit masks; samples of a known control mesh's own "
                   "limit surface give it back by least squares. Recovered on "
                   f"{len(solved)} mesh x scheme pairs of the catalog; largest error "
                   f"{fmt(max((r['error'] for r in solved), default=0))} of the diagonal. Singular: "
                   + (", ".join(f"{r['mesh']} ({r['scheme']}, predicted: {'yes' if r['predicted_singular'] else 'no'})"
                                for r in singular) or "none")
                   + ". Catmull-Clark's stencils are linearly dependent on a closed mesh of valence-3 vertices whose "
                   "graph is bipartite: signs alternating over the vertices vanish after one level."))
    if tables.get("fitting_iterations"):
        rows = [r for r in tables["fitting_iterations"] if "steps" in r]

        def h(r, k):
            return fmt(r["steps"][k]["hausdorff"]) if "hausdorff" in r["steps"][k] else ""
        s.add(Text("Fitting by closest-point iterations (Hoppe et al. 1994): the control mesh is CGAL's edge collapse of "
                   "the target; each iteration finds each sample's closest point on the target and each target vertex's "
                   "closest point on the sampled surface, then solves the least-squares control points. The distance "
                   "energy never increases; the two-sided Hausdorff distance (CGAL's approximate_Hausdorff_distance, "
                   "relative to the target's diagonal) is the largest distance, which least squares does not minimize: "
                   "it may rise at an iteration."),
              Table(["target", "scheme", "control V", "samples", "Hausdorff start", "Hausdorff end", "rises",
                     "rms target->surface start", "end"],
                    [(r["target"], r["scheme"], r["control_vertices"], r["samples"], h(r, 0), h(r, -1),
                      r.get("hausdorff_rises", ""), fmt(r["steps"][0]["rms_target_to_surface"]),
                      fmt(r["steps"][-1]["rms_target_to_surface"])) for r in rows]))
        failed = [r for r in tables["fitting_iterations"] if "steps" not in r]
        if failed:
            s.add(Table(["target", "edge budget", "why not fitted"], [(r["target"], r.get("edge_budget", ""), r["error"])
                                                                      for r in failed]))
        if rows:
            s.add(Figure(figures.fitting_convergence(rows, figdir), "fitting convergence"))
    if tables.get("fitting_figure"):
        s.add(Figure(figures.shaded_meshes(tables["fitting_figure"], figdir, "fitting_meshes.png", vertical_axis="y"),
                     "fitting the bunny"))
    if tables.get("multiresolution"):
        rows = tables["multiresolution"]
        done = [r for r in rows if "round_trip" in r]
        s.add(Text("Multiresolution editing (Zorin, Schroeder and Sweldens 1997), Loop, 3 levels: each bundled mesh "
                   "subdivided and moved along its normals by a detail, decomposed level by level (least-squares coarser "
                   "level, details in frames of the smooth prediction) and recomposed; the same after a rigid motion; base "
                   "vertex 0 moved by a fifth of the diagonal. The reach is the subdivision support grown by one ring per "
                   "level (the frames of the support's neighbours turn); with zero details exactly the support moves."),
              Table(["mesh", "finest V", "round trip", "rigid motion", "moved", "reach", "support", "outside reach",
                     "zero details: moved", "vs support"],
                    [(r["mesh"], r["finest_vertices"], fmt(r["round_trip"]), fmt(r["rigid_motion"]), r["moved"], r["reach"],
                      r["support"], r["outside_reach"], r["smooth_moved"], r["smooth_mismatch"]) for r in done]))
        failed = [r for r in rows if "error" in r]
        if failed:
            s.add(Table(["mesh", "not decomposed"], [(r["mesh"], r["error"]) for r in failed]))
    if tables.get("multiresolution_figure"):
        s.add(Figure(figures.shaded_meshes(tables["multiresolution_figure"], figdir, "multiresolution.png"),
                     "multiresolution edit"))
    if tables.get("butterfly_properties"):
        rows = []
        for scheme in sorted({r["scheme"] for r in tables["butterfly_properties"]}):
            sel = [r for r in tables["butterfly_properties"] if r["scheme"] == scheme]
            rows.append((scheme, len(sel), fmt(max(r["max_interpolation_move"] for r in sel)),
                         fmt(max(r["max_plane_residual"] for r in sel)),
                         f'{sum(r["regular_edges_published"] for r in sel)} / {sum(r["regular_edges"] for r in sel)}'))
        s.add(Text("Butterfly properties, 2 levels on the bundled triangle meshes (the classic scheme has no reference "
                   "library):"),
              Table(["scheme", "meshes", "max move of an old vertex", "max plane residual (rel)",
                     "regular edges with the published stencil"], rows))
    if tables.get("limit"):
        rows = []
        for key in sorted({(r["scheme"], r["rule"], r["levels"]) for r in tables["limit"]}):
            sel = [r for r in tables["limit"] if (r["scheme"], r["rule"], r["levels"]) == key]
            pos = [r["max_rel_position"] for r in sel if r["max_rel_position"] is not None]
            ang = [r["max_normal_angle"] for r in sel if r["max_normal_angle"] is not None]
            rows.append(key + (len(sel), len([r for r in sel if r["verdict"] == "agree"]), fmt(max(pos) if pos else None),
                               fmt(max(ang) if ang else None)))
        s.add(Text("Limit positions and interior limit normals against OpenSubdiv's `PrimvarRefiner::Limit`:"),
              Table(["scheme", "rule", "levels", "meshes", "agree", "max position rel", "max normal angle (rad)"], rows))
    if tables.get("bfr"):
        rows = []
        for scheme in sorted({r["scheme"] for r in tables["bfr"]}):
            sel = [r for r in tables["bfr"] if r["scheme"] == scheme and not r["error"]]
            rows.append((scheme, len(sel), sum(r["regular_faces"] for r in sel), sum(r["irregular_faces"] for r in sel),
                         fmt(max(r["max_regular"] for r in sel)), fmt(max(r["max_irregular_corner"] for r in sel)),
                         fmt(max(r["max_irregular_inner"] for r in sel))))
        s.add(Text("OpenSubdiv's Bfr at (u, v) against core's exact limit at the dyadic points of level 1 (corners, edge "
                   "midpoints, quad centres), relative to the diagonal:"),
              Table(["scheme", "meshes", "regular faces", "irregular faces", "max on regular", "max at irregular corners",
                     "max at irregular midpoints/centres"], rows))
    if tables.get("creases"):
        rows = []
        for key in sorted({(r["scheme"], r["method"]) for r in tables["creases"]}):
            sel = [r for r in tables["creases"] if (r["scheme"], r["method"]) == key]
            dist = [d for r in sel for d in r["max_rel_per_level"] if d is not None]
            effect = [r["effect_of_tags"] for r in sel if r["effect_of_tags"] is not None]
            rows.append(key + (len(sel), len([r for r in sel if r["verdict"] == "agree"]), fmt(max(dist) if dist else None),
                               fmt(min(effect) if effect else None), fmt(max(effect) if effect else None)))
        s.add(Text("Creases (OpenSubdiv's semi-sharp rules) against OpenSubdiv, the only reference with crease rules, "
                   "3 levels on the crease-tagged meshes; the last columns say how far the tags move the surface, so "
                   "the agreement tests the sharp rules:"),
              Table(["scheme", "decay", "meshes", "agree", "max rel (any level)", "tags move the surface by, min", "max"],
                    rows))
    if tables.get("crease_cube"):
        s.add(Text("What happens to sharp features (the seed's question): the cube refined three times without tags "
                   "(it shrinks to a rounded blob), with its top edges infinitely sharp (the top face stays flat inside a "
                   "sharp rim; the rim is the cubic B-spline of the four top corners, since a vertex with two sharp edges "
                   "is a crease, not a corner -- a corner tag would keep them), and with every edge of sharpness 2 (two "
                   "sharp levels, then smooth: a box with rounded edges)."),
              Figure(figures.crease_cube(tables["crease_cube"], figdir), "crease cube"))
    if tables.get("spectrum"):
        s.add(Text("Eigen table: the local subdivision matrix of an interior vertex of valence n, taken from core's S, "
                   "against the published spectrum."),
              Table(["scheme", "n", "lambda_1", "multiplicity", "next", "vertex eigenvalue", "|core - closed form|", "regular"],
                    [(r["scheme"], r["valence"], fmt(r["subdominant"], ".6f"), r["subdominant_multiplicity"],
                      fmt(r["next"], ".6f"), fmt(r["vertex_rate"], ".6f"), fmt(r["max_difference"]),
                      "yes" if r["regular_characteristic_map"] else "NO") for r in tables["spectrum"]]))
    if tables.get("convergence"):
        s.add(Text("Convergence table: the centre of a fan refined k = 1..8 times against its limit position. A vertex "
                   "converges at the largest rotation-invariant eigenvalue below 1 (the subdominant pair is not rotation "
                   "invariant and vanishes at the centre)."),
              Figure(figures.limit_convergence(tables["convergence"], figdir), "convergence"),
              Table(["scheme", "n", "d_1", "d_8", "fitted rate", "vertex eigenvalue", "lambda_1"],
                    [(r["scheme"], r["valence"], fmt(r["distance"][0]), fmt(r["distance"][-1]), fmt(r["fitted_rate"], ".6f"),
                      fmt(r["vertex_rate"], ".6f"), fmt(r["subdominant"], ".6f")) for r in tables["convergence"]]))
    return s


def halfedge_section(cases):
    """One row per mesh: the edit sequences and the normals checks, failures first named."""
    if not cases:
        return None
    by_input = {}
    for c in cases:
        by_input.setdefault(c["input"], {})[c["operation"]] = c
    rows = []
    for name, ops in by_input.items():
        edits = ops.get("edits", {}).get("runs", [])
        normals = ops.get("normals", {}).get("runs", [])
        failed = [r for r in edits + normals if r["outcome"] == "diverge (unexplained)"]
        worst_angle = max((r["measured"] for r in normals if r["unit"] == "rad" and r["verdict"] == "agree"), default=None)
        classified = [r for r in normals if r["outcome"].startswith("diverge (") and r not in failed]
        rows.append((short_input(name), f"{sum(r['verdict'] == 'agree' for r in edits)} of {len(edits)}",
                     f"{sum(r['verdict'] == 'agree' for r in normals)} of {len(normals)}", fmt(worst_angle),
                     ", ".join(f"{r['reference']} {r['outcome']}" for r in classified) or "-",
                     "; ".join(f"{r['subject']} {r['check']} vs {r['reference']}: {r.get('explanation', '')}" for r in failed)
                     or "-"))
    rows.sort(key=lambda r: r[-1] == "-")
    return Section("Half-edge edits and vertex normals").add(
        Text("`edits`: seeded sequences of flips and splits applied to ours and, in lockstep, to OpenMesh and CGAL, "
             "each side valid and the faces equal after every operation (a failure is shrunk to a minimal sequence). "
             "`normals`: each weighting against the library call that implements it (OpenMesh's "
             "calc_vertex_normal_correct: area, update_vertex_normals: uniform), CGAL's most visible normal classified, "
             "and the angle weighting against the angle-weighted sum written out."),
        Table(["mesh", "edit sequences equal", "normals checks agreeing", "worst agreeing angle (rad)", "classified",
               "failures"], rows))


def timing_section(bench, figdir):
    s = Section("Timing")
    records = (bench or {}).get("records") or []
    valence = ((bench or {}).get("valence") or {}).get("rows") or []
    stencils = ((bench or {}).get("stencils") or {}).get("rows") or []
    if not records and not valence and not stencils:
        return s.add(Text("No bench.json in this folder: run `crossdiv bench --out DIR` to add the timing section."))
    if records:
        def key(r):
            return r.get("scheme", "loop"), r["input"], r["levels"], r.get("memory", "warm")
        core = {key(r): r["median_ms"] for r in records if r["impl"] == "core"}
        s.add(Text(f"`crossdiv bench`: median of {bench.get('repeats', '?')} runs, single thread, ratio = time / core time on "
                   f"the same input in the same memory regime (above 1: slower than core); warm keeps freed memory between "
                   f"repeats, cold returns it to the kernel (page faults paid). {bench.get('note', '')}"),
              Figure(figures.timing(records, figdir), "timing"),
              Table(["scheme", "input", "levels", "memory", "impl", "input faces", "output faces", "median ms",
                     "ratio to core", "peak RSS MB"],
                    [(r.get("scheme", "loop"), r["input"], r["levels"], r.get("memory", "warm"), r["impl"], r["input_faces"],
                      r["output_faces"],
                      fmt(r["median_ms"], ".2f"), fmt(r["median_ms"] / core[key(r)], ".2f") if core.get(key(r)) else "-",
                      fmt(r.get("peak_rss_mb"), ".0f")) for r in records]))
        goals = bench.get("goals") or []
        if goals:
            bw = bench.get("bandwidth") or {}
            s.add(Text(f"Goals, for Loop and Catmull-Clark at every input of at least 300000 output faces: warm, core "
                       f"at least 4x faster than the fastest reference; cold, Loop at least 4x faster, Catmull-Clark no "
                       f"slower. The floor is the output's bytes "
                       f"(24 per vertex, 12 per triangle or 16 per quad) written at the write bandwidth measured in the "
                       f"same run ({fmt(bw.get('write_gbs'), '.1f')} GB/s; copy {fmt(bw.get('copy_gbs'), '.1f')} GB/s)."),
                  Table(["scheme", "input", "levels", "memory", "output faces", "core ms", "fastest reference", "its ms",
                         "ratio", "target", "floor ms", "core / floor", "goal"],
                        [(g.get("scheme", "loop"), g["input"], g["levels"], g["memory"], g["output_faces"], fmt(g["core_ms"], ".2f"),
                          g["fastest_reference"], fmt(g["fastest_reference_ms"], ".2f"), fmt(g["ratio"], ".2f"),
                          fmt(g["target_ratio"], ".0f"), fmt(g.get("floor_ms"), ".2f"), fmt(g.get("core_over_floor"), ".1f"),
                          "met" if g["met"] else "NOT met") for g in goals]))
        core_goals = bench.get("core_goals") or []
        if core_goals:
            s.add(Text("Core Loop's goals on its own figures at the same inputs: warm, at most 1.5x the floor above; "
                       "cold, at most 2x its warm time on the same input."),
                  Table(["goal", "scheme", "input", "levels", "output faces", "core ms", "against ms", "ratio",
                         "target (at most)", "goal met"],
                        [(g["goal"], g["scheme"], g["input"], g["levels"], g["output_faces"], fmt(g["core_ms"], ".2f"),
                          fmt(g["base_ms"], ".2f"), fmt(g["ratio"], ".2f"), fmt(g["target_ratio"], ".1f"),
                          "met" if g["met"] else "NOT met") for g in core_goals]))
    if stencils:
        goal = bench["stencils"]["goal_ratio"]
        met = all(r["level_ratio"] >= goal for r in stencils)
        s.add(Text("Fixed topology (the animation use): the topology refined once, then a moved frame of the base "
                   "vertices re-evaluated through core's composed stencils (one table, S = S_L ... S_1), core's level "
                   "stencils (one table per level, weights shared by rows that repeat them), OpenSubdiv's stencil "
                   "table (double) and its PrimvarRefiner level by level; ratio = OpenSubdiv's stencil time / core's. "
                   "Distances to core's level-by-level refinement over the bounding-box diagonal. Goal: core's level "
                   f"stencils' ratio >= {goal} on every torus - {'met' if met else 'NOT met'}."),
              Figure(figures.stencil_times(stencils, figdir), "stencil times"),
              Table(["input", "levels", "vertices", "composed terms", "level terms", "OpenSubdiv terms", "composed ms",
                     "level ms", "OpenSubdiv stencils ms", "OpenSubdiv levels ms", "ratio composed", "ratio level",
                     "composed vs levels", "level vs levels", "composed vs OpenSubdiv"],
                    [(r["input"], r["levels"], r["output_vertices"], r["core_terms"], r["level_terms"],
                      r["opensubdiv_terms"], fmt(r["core_ms"], ".2f"), fmt(r["core_levels_ms"], ".2f"),
                      fmt(r["opensubdiv_stencils_ms"], ".2f"), fmt(r["opensubdiv_levels_ms"], ".2f"),
                      fmt(r["ratio"], ".2f"), fmt(r["level_ratio"], ".2f"), fmt(r["core_vs_levels"], ".1e"),
                      fmt(r["level_stencils_vs_levels"], ".1e"), fmt(r["core_vs_opensubdiv"], ".1e"))
                     for r in stencils]))
    if valence:
        worst = max(valence, key=lambda r: r["ratio"])
        goal = bench["valence"]["goal_ratio"]
        s.add(Text("Valence: each command on a vertex of valence k (a bicone's two poles, a disc fan's centre) or on "
                   "one polygon of k sides, against a regular mesh of as many corners; ratio of the times per unit of "
                   f"size (check: input corners; a scheme: output vertices + faces). Goal: every ratio <= {goal}; largest "
                   f"{fmt(worst['ratio'], '.2f')} ({worst['command']} on the {worst['shape']} of k = {worst['valence']})"
                   f" - {'met' if worst['ratio'] <= goal else 'NOT met'}."),
              Figure(figures.valence_times(valence, figdir), "valence times"),
              Table(["shape", "k", "command", "size", "ms", "regular size", "regular ms", "ratio"],
                    [(r["shape"], r["valence"], r["command"], r["size"], fmt(r["ms"], ".2f"), r["regular_size"],
                      fmt(r["regular_ms"], ".2f"), fmt(r["ratio"], ".2f")) for r in valence]))
    return s
