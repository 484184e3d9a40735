#!/usr/bin/python3
"""Render a crossdiv suite folder into report.md, index.html and figures/*.png.

Usage: make_report.py DIR
Reads DIR/results.json (crossdiv suite / merge; schema in reports/results-schema.md) and,
when present, DIR/bench.json (crossdiv bench). Figures are drawn with matplotlib (Debian's
python3-matplotlib) and saved as PNG; nothing is hand-drawn.
"""
import html
import json
import math
import os
import sys
from collections import Counter, defaultdict

import matplotlib

matplotlib.use("Agg")  # no display on a build machine
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

# Outcome categories of the summary matrix, in legend order, with their colours.
CATEGORIES = [
    ("agree", "#4caf50"),
    ("diverge (classified)", "#ffb300"),
    ("diverge (unexplained)", "#e53935"),
    ("ref-crashed", "#212121"),
    ("ref-rejected", "#9e9e9e"),
    ("ours-rejected", "#42a5f5"),
    ("ours-failed", "#8e24aa"),
    ("not run", "#ffffff"),
]
MAX_ERROR_PICTURES = 12


def outcome(case, run):
    """The outcome string of one run, as crossdiv's run_outcome()."""
    if case.get("ours_failed"):
        return "ours-failed"
    verdict, cls = run.get("verdict", ""), run.get("divergence_class", "")
    if verdict in ("diverge", "ours-rejected") and cls:
        return f"{verdict} ({cls})"
    return verdict


def category(case, run):
    o = outcome(case, run)
    if o == "diverge (unexplained)":
        return "diverge (unexplained)"
    if o.startswith("diverge"):
        return "diverge (classified)"
    if o.startswith("ours-rejected"):
        return "ours-rejected"
    return o if o in dict(CATEGORIES) else "ref-crashed"


def entry_label(case):
    o = case["options"]
    label = f"{case.get('scheme', 'loop')} {o['weights']}/{o['boundary']} L{case['levels']} {case.get('tier', '')}"
    return label


def short_input(name):
    return os.path.splitext(os.path.basename(name))[0] if "/" in name else name


def fmt(x, spec=".3g"):
    return "-" if x is None or (isinstance(x, float) and math.isnan(x)) else format(x, spec)


def vec(v):
    return "-" if v is None else "(" + ", ".join(f"{c:.9g}" for c in v) + ")"


def save(fig, figdir, name):
    """Lays out, writes figures/NAME and frees the figure; returns the path."""
    fig.tight_layout()
    path = os.path.join(figdir, name)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def summary_matrix(results, figdir):
    cases = results["cases"]
    refs = [r["name"] for r in results.get("references", [])] or sorted(
        {r["reference"] for c in cases for r in c["runs"]})
    inputs = list(dict.fromkeys(c["input"] for c in cases))
    entries = list(dict.fromkeys(entry_label(c) for c in cases))
    columns = [(e, r) for e in entries for r in refs]
    index = {name: i for i, (name, _) in enumerate(CATEGORIES)}
    grid = [[index["not run"]] * len(columns) for _ in inputs]
    for c in cases:
        row = inputs.index(c["input"])
        for r in c["runs"]:
            grid[row][columns.index((entry_label(c), r["reference"]))] = index[category(c, r)]
        if not c["runs"]:
            cat = "ours-failed" if c.get("ours_failed") else "ours-rejected"
            for ref in refs:
                grid[row][columns.index((entry_label(c), ref))] = index[cat]
    fig, ax = plt.subplots(figsize=(2.5 + 0.32 * len(columns), 1.5 + 0.19 * len(inputs)))
    cmap = ListedColormap([colour for _, colour in CATEGORIES])
    ax.imshow(grid, cmap=cmap, vmin=-0.5, vmax=len(CATEGORIES) - 0.5, aspect="auto", interpolation="nearest")
    ax.set_yticks(range(len(inputs)), [short_input(i) for i in inputs], fontsize=6)
    ax.set_xticks(range(len(columns)), [f"{r}  |  {e}" for e, r in columns], rotation=90, fontsize=6)
    for k in range(1, len(entries)):
        ax.axvline(k * len(refs) - 0.5, color="black", linewidth=0.8)
    handles = [plt.Rectangle((0, 0), 1, 1, facecolor=colour, edgecolor="black") for _, colour in CATEGORIES]
    ax.legend(handles, [n for n, _ in CATEGORIES], loc="upper left", bbox_to_anchor=(1.01, 1), fontsize=7)
    ax.set_title("Outcome per input (rows) and case x reference (columns)", fontsize=9)
    return save(fig, figdir, "summary_matrix.png")


def error_histogram(results, figdir):
    groups = defaultdict(list)
    for c in results["cases"]:
        for r in c["runs"]:
            m = r.get("positions", {}).get("max_rel")
            if m is not None:
                groups["agree" if r["verdict"] == "agree" else r.get("divergence_class") or r["verdict"]].append(
                    math.log10(max(m, 1e-20)))
    fig, ax = plt.subplots(figsize=(8, 4))
    bins = [x / 2 for x in range(-40, 2)]
    ax.hist(list(groups.values()), bins=bins, stacked=True, label=list(groups.keys()))
    ax.axvline(math.log10(1e-12), color="red", linestyle="--", label="weak tolerance 1e-12")
    ax.set_xlabel("log10(max distance / bounding-box diagonal); exact agreement drawn at -20")
    ax.set_ylabel("reference runs")
    ax.legend(fontsize=7)
    ax.set_title("Distribution of the largest vertex error per run", fontsize=9)
    return save(fig, figdir, "error_histogram.png")


def convergence(results, figdir):
    """Per-level error of every run with two or more levels, coloured by class."""
    fig, ax = plt.subplots(figsize=(8, 4.5))
    colours = {}
    palette = plt.get_cmap("tab10")
    for c in results["cases"]:
        for r in c["runs"]:
            levels = r.get("positions", {}).get("level_max_rel") or []
            if len(levels) < 2 or any(v is None for v in levels):
                continue
            key = r.get("divergence_class") or "agree"
            if key not in colours:
                colours[key] = palette(len(colours) % 10)
            ax.plot(range(1, len(levels) + 1), [max(v, 1e-20) for v in levels], color=colours[key], alpha=0.35,
                    linewidth=0.8, marker=".")
    for key, colour in colours.items():
        ax.plot([], [], color=colour, label=key)
    ax.set_yscale("log")
    ax.set_xlabel("subdivision level")
    ax.set_ylabel("max distance / diagonal (1e-20 = exact)")
    ax.set_title("Error by level: rounding stays flat near 1e-16, rule differences persist", fontsize=9)
    ax.legend(fontsize=7)
    return save(fig, figdir, "convergence.png")


def error_pictures(results, folder, figdir):
    """Meshes coloured by per-vertex distance to the reference, one per divergence class and
    reference (the first few), so a reader sees where two surfaces part."""
    pictures, seen = [], set()
    for c in results["cases"]:
        for r in c["runs"]:
            if "error_field" not in r or len(pictures) >= MAX_ERROR_PICTURES:
                continue
            key = (r.get("divergence_class"), r["reference"], c["options"]["boundary"])
            if key in seen:
                continue
            seen.add(key)
            with open(os.path.join(folder, r["error_field"])) as f:
                field = json.load(f)
            pts, faces = field["positions"], field["faces"]
            dist = [d if d is not None else float("nan") for d in field["distance"]]
            face_err = [max(dist[v] for v in face) for face in faces]
            fig = plt.figure(figsize=(5, 4.4))
            ax = fig.add_subplot(projection="3d")
            polys = [[pts[v] for v in face] for face in faces]
            top = max([e for e in face_err if not math.isnan(e)] + [1e-300])
            coll = Poly3DCollection(polys, cmap="inferno", edgecolor=(0, 0, 0, 0.15), linewidths=0.1)
            coll.set_array([0 if math.isnan(e) else e for e in face_err])
            coll.set_clim(0, top)
            ax.add_collection3d(coll)
            xs, ys, zs = zip(*pts)
            for setter, values in ((ax.set_xlim, xs), (ax.set_ylim, ys), (ax.set_zlim, zs)):
                mid, half = (max(values) + min(values)) / 2, (max(max(xs) - min(xs), max(ys) - min(ys),
                                                                  max(zs) - min(zs)) / 2 or 1)
                setter(mid - half, mid + half)
            ax.set_axis_off()
            fig.colorbar(coll, ax=ax, shrink=0.6, label="distance to reference")
            ax.set_title(f"{short_input(c['input'])} vs {r['reference']}, level {field['level']}\n"
                         f"{r.get('divergence_class')}, {entry_label(c)}", fontsize=8)
            name = f"error_job{c['job']}_{r['reference']}.png"
            fig.savefig(os.path.join(figdir, name), dpi=100)
            plt.close(fig)
            pictures.append((name, c, r))
    return pictures


def timing(bench, figdir):
    """Log-log time against output size for every implementation, and the ratio table."""
    records = bench.get("records", [])
    if not records:
        return None, []
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for impl in dict.fromkeys(r["impl"] for r in records):
        rows = sorted((r for r in records if r["impl"] == impl), key=lambda r: r["output_faces"])
        ax.plot([r["output_faces"] for r in rows], [r["median_ms"] for r in rows], marker="o", label=impl)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("output faces")
    ax.set_ylabel("median time (ms)")
    ax.set_title("Loop subdivision time against output size (single thread)", fontsize=9)
    ax.legend()
    ax.grid(True, which="both", alpha=0.3)
    path = save(fig, figdir, "timing.png")
    core = {(r["input"], r["levels"]): r["median_ms"] for r in records if r["impl"] == "core"}
    rows = []
    for r in records:
        base = core.get((r["input"], r["levels"]))
        rows.append(dict(r, ratio=(r["median_ms"] / base) if base else None))
    return path, rows


def surface_section(surface_cases, bench, figdir):
    """The surface checks: (markdown lines, html parts). Empty when the suite ran no surfaces."""
    sweep = (bench or {}).get("adaptive_sweep")
    if not surface_cases and not sweep:
        return [], []
    md, body = ["", "## Surfaces", ""], ["<h2>Surfaces</h2>"]
    built = [r for c in surface_cases for r in c.get("tables", {}).get("surfaces", [])]
    if built:
        header = ["surface", "kind", "faces", "closed", "boundary edges", "signed volume", "CGAL outward", "fold faces"]
        rows = [(r["surface"], r.get("kind", ""), r["faces"], "yes" if r["closed"] else "no", r["boundary_edges"],
                 fmt(r["signed_volume"]), ("yes" if r["cgal"]["outward"] else "NO") if "cgal" in r else "-",
                 r.get("fold", {}).get("faces", 0)) for r in built]
        md += ["Every surface built; closed ones must be watertight, manifold and outward (our checks and CGAL's).", "",
               *md_table(header, rows)]
        body.append(table_html(header, rows))
    for c in surface_cases:
        t = c.get("tables", {})
        if "sphere" in t or "torus" in t:
            fig, ax = plt.subplots(figsize=(5, 3.6))
            for key, err in (("sphere", "radial_error"), ("torus", "distance_error")):
                series = {}
                for r in t.get(key, []):
                    if err in r:
                        series.setdefault(r["surface"], []).append((r["faces"], r[err]))
                for name, pts in series.items():
                    ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker="o", label=name)
            ax.set_xlabel("faces")
            ax.set_ylabel("max distance to the exact surface")
            ax.set_title("Swept surfaces against exact ones")
            ax.legend(fontsize=7)
            save(fig, figdir, "surface_convergence.png")
            md += ["", "![surfaces against exact surfaces](figures/surface_convergence.png)", ""]
            body.append('<img src="figures/surface_convergence.png">')
            orders = [(r["surface"], fmt(r["fitted_order"])) for key in ("sphere", "torus") for r in t.get(key, []) if "fitted_order" in r]
            md += ["| surface | fitted order |", "|---|---|"] + [f"| {a} | {b} |" for a, b in orders]
            body.append(table_html(["surface", "fitted order"], orders))
        if "bfr" in t:
            rows = [(r["grid"], r["faces"], r["regular"], r["samples"], fmt(r["max_position_rel"]), fmt(r["max_derivative_rel"]))
                    for r in t["bfr"]]
            header = ["grid", "faces", "regular (Bfr)", "samples", "position rel", "derivatives rel"]
            md += ["", "Catmull-Clark limit of regular grids: our bicubic Bezier form against OpenSubdiv's Bfr.", "",
                   *md_table(header, rows)]
            body.append(table_html(header, rows))
    if sweep:
        u, a, seed = sweep["uniform"], sweep["adaptive"], sweep["seed"]
        rows = [("uniform (the record's steps)", u["faces"], u["slices"], u["profile_samples"], fmt(u["deviation"])),
                ("adaptive, equal measured deviation", a["faces"], a["slices"], a["profile_samples"], fmt(a["deviation"]))]
        header = ["wineglass", "faces", "slices", "profile samples", "deviation"]
        md += ["", f"Adaptive sweep ({sweep['input']}): uniform / adaptive faces {sweep['ratio']:.2f}, the seed's "
               f"{seed['uniform_faces']} / {seed['adaptive_faces']} = {seed['ratio']:.2f}.", "",
               *md_table(header, rows)]
        body.append(table_html(header, rows))
    return md, body


def limits_section(limit_cases, figdir):
    """Schemes and limit behaviour: scheme verdicts, Butterfly properties, limit agreement, eigen and convergence tables."""
    if not limit_cases:
        return [], []
    md, body = ["", "## Schemes and limit behaviour", ""], ["<h2>Schemes and limit behaviour</h2>"]
    tables = {}
    for c in limit_cases:
        for k, v in c.get("tables", {}).items():
            tables.setdefault(k, []).extend(v)
    comparisons = tables.get("catmull_clark", []) + tables.get("schemes", [])
    if comparisons:
        verdicts = Counter()
        for comp in comparisons:
            for r in comp["runs"]:
                verdicts[(comp["scheme"], comp["levels"], comp["rule"], r["reference"], r["rule"], r["verdict"],
                          r.get("divergence_class") or "")] += 1
        header = ["scheme", "levels", "requested rule", "reference", "its rule", "verdict", "class", "inputs"]
        rows = [k + (n,) for k, n in sorted(verdicts.items())]
        md += ["Every polygon scheme against every reference that has it, on the bundled and polygon meshes "
               "(a divergence's class is measured: core re-run with the reference's rule agrees).", "",
               *md_table(header, rows)]
        body.append(table_html(header, rows))
    if tables.get("butterfly_properties"):
        rows = []
        for scheme in sorted({r["scheme"] for r in tables["butterfly_properties"]}):
            sel = [r for r in tables["butterfly_properties"] if r["scheme"] == scheme]
            rows.append((scheme, len(sel), fmt(max(r["max_interpolation_move"] for r in sel)),
                         fmt(max(r["max_plane_residual"] for r in sel)),
                         f'{sum(r["regular_edges_published"] for r in sel)} / {sum(r["regular_edges"] for r in sel)}'))
        header = ["scheme", "meshes", "max move of an old vertex", "max plane residual (rel)",
                  "regular edges with the published stencil"]
        md += ["", "Butterfly properties, 2 levels on the bundled triangle meshes (the classic scheme has no "
               "reference library):", "", *md_table(header, rows)]
        body.append(table_html(header, rows))
    if tables.get("limit"):
        rows = []
        for key in sorted({(r["scheme"], r["rule"], r["levels"]) for r in tables["limit"]}):
            sel = [r for r in tables["limit"] if (r["scheme"], r["rule"], r["levels"]) == key]
            ok = [r for r in sel if r["verdict"] == "agree"]
            pos = [r["max_rel_position"] for r in sel if r["max_rel_position"] is not None]
            ang = [r["max_normal_angle"] for r in sel if r["max_normal_angle"] is not None]
            rows.append(key + (len(sel), len(ok), fmt(max(pos) if pos else None), fmt(max(ang) if ang else None)))
        header = ["scheme", "rule", "levels", "meshes", "agree", "max position rel", "max normal angle (rad)"]
        md += ["", "Limit positions and interior limit normals against OpenSubdiv's `PrimvarRefiner::Limit`:", "",
               *md_table(header, rows)]
        body.append(table_html(header, rows))
    if tables.get("bfr"):
        rows = []
        for scheme in sorted({r["scheme"] for r in tables["bfr"]}):
            sel = [r for r in tables["bfr"] if r["scheme"] == scheme and not r["error"]]
            rows.append((scheme, len(sel), sum(r["regular_faces"] for r in sel), sum(r["irregular_faces"] for r in sel),
                         fmt(max(r["max_regular"] for r in sel)), fmt(max(r["max_irregular_corner"] for r in sel)),
                         fmt(max(r["max_irregular_inner"] for r in sel))))
        header = ["scheme", "meshes", "regular faces", "irregular faces", "max on regular", "max at irregular corners",
                  "max at irregular midpoints/centres"]
        md += ["", "OpenSubdiv's Bfr at (u, v) against core's exact limit at the dyadic points of level 1 (corners, "
               "edge midpoints, quad centres), relative to the diagonal:", "",
               *md_table(header, rows)]
        body.append(table_html(header, rows))
    if tables.get("creases"):
        rows = []
        for key in sorted({(r["scheme"], r["method"]) for r in tables["creases"]}):
            sel = [r for r in tables["creases"] if (r["scheme"], r["method"]) == key]
            ok = [r for r in sel if r["verdict"] == "agree"]
            dist = [d for r in sel for d in r["max_rel_per_level"] if d is not None]
            effect = [r["effect_of_tags"] for r in sel if r["effect_of_tags"] is not None]
            rows.append(key + (len(sel), len(ok), fmt(max(dist) if dist else None),
                               fmt(min(effect) if effect else None), fmt(max(effect) if effect else None)))
        header = ["scheme", "decay", "meshes", "agree", "max rel (any level)", "tags move the surface by, min",
                  "max"]
        md += ["", "Creases (OpenSubdiv's semi-sharp rules) against OpenSubdiv, the only reference with crease rules, "
               "3 levels on the crease-tagged meshes; the last columns say how far the tags move the surface, so "
               "the agreement tests the sharp rules:", "", *md_table(header, rows)]
        body.append(table_html(header, rows))
    if tables.get("crease_cube"):
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection
        cubes = tables["crease_cube"]
        fig = plt.figure(figsize=(3.2 * len(cubes), 3.4))
        for i, m in enumerate(cubes):
            ax = fig.add_subplot(1, len(cubes), i + 1, projection="3d")
            pts = m["positions"]
            polys = [[pts[v] for v in f] for f in m["faces"]]
            ax.add_collection3d(Poly3DCollection(polys, facecolor="#9ecae1", edgecolor="#3182bd", linewidths=0.2))
            ax.set_xlim(-1, 1)
            ax.set_ylim(-1, 1)
            ax.set_zlim(-1, 1)
            ax.set_box_aspect((1, 1, 1))
            ax.view_init(elev=25, azim=-60)
            ax.set_axis_off()
            ax.set_title(m["name"], fontsize=8)
        fig.suptitle("The cube after 3 Catmull-Clark levels: what creases keep", fontsize=9)
        save(fig, figdir, "crease_cube.png")
        md += ["", "What happens to sharp features (the seed's question): the cube refined three times without tags "
               "(it shrinks to a rounded blob), with its top edges infinitely sharp (the top face stays flat inside a "
               "sharp rim; the rim is the cubic B-spline of the four top corners, since a vertex with two sharp "
               "edges is a crease, not a corner -- a corner tag would keep them), and with every edge of sharpness "
               "2 (two sharp levels, then smooth: a box with rounded edges).", "", "![crease cube](figures/crease_cube.png)"]
        body.append('<img src="figures/crease_cube.png">')
    if tables.get("spectrum"):
        header = ["scheme", "n", "lambda_1", "multiplicity", "next", "vertex eigenvalue", "|core - closed form|", "regular"]
        rows = [(r["scheme"], r["valence"], fmt(r["subdominant"], ".6f"), r["subdominant_multiplicity"], fmt(r["next"], ".6f"),
                 fmt(r["vertex_rate"], ".6f"), fmt(r["max_difference"]), "yes" if r["regular_characteristic_map"] else "NO")
                for r in tables["spectrum"]]
        md += ["", "Eigen table: the local subdivision matrix of an interior vertex of valence n, taken from core's S, "
               "against the published spectrum.", "", *md_table(header, rows)]
        body.append(table_html(header, rows))
    if tables.get("convergence"):
        fig, ax = plt.subplots(figsize=(5, 3.6))
        for r in tables["convergence"]:
            if r["valence"] in (3, 5, 8, 12):
                ax.semilogy(range(1, len(r["distance"]) + 1), r["distance"], marker=".", label=f"{r['scheme']} n={r['valence']}")
        ax.set_xlabel("level k")
        ax.set_ylabel("|v_k - v_limit| / diagonal")
        ax.set_title("Convergence of an extraordinary vertex")
        ax.legend(fontsize=6)
        save(fig, figdir, "limit_convergence.png")
        header = ["scheme", "n", "d_1", "d_8", "fitted rate", "vertex eigenvalue", "lambda_1"]
        rows = [(r["scheme"], r["valence"], fmt(r["distance"][0]), fmt(r["distance"][-1]), fmt(r["fitted_rate"], ".6f"),
                 fmt(r["vertex_rate"], ".6f"), fmt(r["subdominant"], ".6f")) for r in tables["convergence"]]
        md += ["", "Convergence table: the centre of a fan refined k = 1..8 times against its limit position. A vertex "
               "converges at the largest rotation-invariant eigenvalue below 1 (the subdominant pair is not "
               "rotation invariant and vanishes at the centre).", "",
               "![convergence](figures/limit_convergence.png)", "",
               *md_table(header, rows)]
        body += ['<img src="figures/limit_convergence.png">', table_html(header, rows)]
    return md, body


def curve_section(curve_cases, bench, figdir):
    """The curve checks: (markdown lines, html parts). Empty when the suite ran no curves."""
    if not curve_cases and not (bench and bench.get("curves")):
        return [], []
    md, body = ["", "## Curves", ""], ["<h2>Curves</h2>"]
    rows = []
    for c in curve_cases:
        runs = c["runs"]
        failed = [r for r in runs if r["verdict"] != "agree"]
        worst = max(runs, key=lambda r: (r["measured"] / r["tolerance"]) if r["tolerance"] > 0 else
                    (0 if r["measured"] == 0 else float("inf")), default=None)
        eigen = max((r["measured"] for r in runs if r["reference"] == "eigen"), default=None)
        rows.append((short_input(c["input"]), len(c.get("curves", [])), len(runs), len(failed), fmt(eigen),
                     f"{worst['curve']} {worst['check']} ({fmt(worst['measured'])} of {fmt(worst['tolerance'])} "
                     f"{worst['unit']})" if worst else c.get("core_error", "-")))
    header = ["input", "curves", "checks", "failed", "Eigen max rel", "closest to its tolerance"]
    if rows:
        md += ["Each check is measured <= tolerance (tolerances.h names and justifies each); Eigen is "
               "`unsupported/Eigen/Splines` (Cox-de Boor), compared in position, first and second derivative.", "",
               *md_table(header, rows)]
        body.append(table_html(header, rows))
    for c in curve_cases:
        t = c.get("tables", {})
        if "frames" in t:
            fr = t["frames"]
            fig, ax = plt.subplots(figsize=(5, 3.6))
            h = [r["h"] for r in fr["rows"]]
            ax.loglog(h, [r["recursive_error_rad"] for r in fr["rows"]], marker="o",
                      label=f"recursive (seed), order {fr['recursive_order']:.2f}")
            ax.loglog(h, [r["rmf_error_rad"] for r in fr["rows"]], marker="s",
                      label=f"double reflection, order {fr['rmf_order']:.2f}")
            ax.set_xlabel("parameter step h")
            ax.set_ylabel("max angle to exact RMF (rad)")
            ax.set_title("Helix frames")
            ax.legend(fontsize=8)
            save(fig, figdir, "curve_frames.png")
            md += ["", f"Frames on a helix ({fr['curve']}) against its exact rotation-minimizing frame:", "",
                   "![frames](figures/curve_frames.png)", "", "| steps | h | recursive (rad) | double reflection (rad) |",
                   "|---|---|---|---|"]
            md += [f"| {r['steps']} | {fmt(r['h'])} | {fmt(r['recursive_error_rad'])} | {fmt(r['rmf_error_rad'])} |"
                   for r in fr["rows"]]
            body += ["<img src='figures/curve_frames.png'>",
                     table_html(["steps", "h", "recursive (rad)", "double reflection (rad)"],
                                [(r["steps"], fmt(r["h"]), fmt(r["recursive_error_rad"]), fmt(r["rmf_error_rad"]))
                                 for r in fr["rows"]])]
        if "degrees" in t:
            d = t["degrees"]
            fig, ax = plt.subplots(figsize=(5, 3.6))
            deg = [r["degree"] for r in d]
            ax.semilogy(deg, [max(r.get("bernstein-sum", 0), 1e-18) for r in d], marker="o", label="vs Bernstein sum")
            ed = [r for r in d if "eigen_position" in r]
            for key, name in (("eigen_position", "vs Eigen, position"), ("eigen_d1", "vs Eigen, d1"),
                              ("eigen_d2", "vs Eigen, d2")):
                ax.semilogy([r["degree"] for r in ed], [max(r[key], 1e-18) for r in ed], marker=".", label=name)
            ax.semilogy(deg, [r["bound_position"] for r in d], "k--", label="position tolerance")
            ax.set_xlabel("degree")
            ax.set_ylabel("max error / control diagonal")
            ax.set_title("de Casteljau against two other algorithms")
            ax.legend(fontsize=7)
            save(fig, figdir, "curve_degrees.png")
            md += ["", "![degrees](figures/curve_degrees.png)"]
            body.append("<img src='figures/curve_degrees.png'>")
    tess = [row for c in curve_cases for row in c.get("tables", {}).get("tessellation", [])]
    bench_rows = (bench or {}).get("curves", [])
    if bench_rows:
        tess = bench_rows
    if tess:
        header = ["curve", "tol", "uniform edges (dev)", "angle edges (dev, tol deg)", "distance edges (dev)",
                  "Wang edges (dev)"]
        rows = [(r["curve"], fmt(r["tol"]), f"{r['uniform_edges']} ({fmt(r['uniform_dev'])})",
                 f"{r['angle_edges']} ({fmt(r['angle_dev'])}, {fmt(r['angle_tol_deg'])})" if r["angle_reached"]
                 else f"{r['angle_edges']} (cap: {fmt(r['angle_dev'])})",
                 f"{r['distance_edges']} ({fmt(r['distance_dev'])})", f"{r['wang_edges']} ({fmt(r['wang_dev'])})")
                for r in tess]
        md += ["", "Tessellation: edges each mode needs for a distance tolerance, with the measured maximum deviation "
               "(uniform: fewest equal steps per segment found by measuring; angle: largest angle tolerance that "
               "meets it; distance: the guaranteed adaptive mode; Wang: the guaranteed uniform count per segment)"
               + (" from `crossdiv bench`" if bench_rows else "") + ":", "",
               *md_table(header, rows)]
        body.append(table_html(header, rows))
    closure = [row for c in curve_cases for row in c.get("tables", {}).get("closure", [])]
    if closure:
        md += ["", "Frame mismatch after one lap of each closed curve (before and after distributing it):", "",
               "| curve | method | mismatch (deg) | after (deg) |", "|---|---|---|---|"]
        md += [f"| {r['curve']} | {r['method']} | {fmt(r['mismatch_deg'])} | {fmt(r['after_distribution_deg'])} |"
               for r in closure]
    return md, body


def md_table(header, rows):
    """A Markdown table: the header line, the rule, one line per row."""
    return (["| " + " | ".join(header) + " |", "|" + "---|" * len(header)] +
            ["| " + " | ".join(str(v) for v in r) + " |" for r in rows])


def table_html(header, rows):
    out = ["<table><tr>" + "".join(f"<th>{html.escape(h)}</th>" for h in header) + "</tr>"]
    out += ["<tr>" + "".join(f"<td>{html.escape(str(v))}</td>" for v in row) + "</tr>" for row in rows]
    return "\n".join(out + ["</table>"])


def main(folder):
    with open(os.path.join(folder, "results.json")) as f:
        results = json.load(f)
    bench = None
    if os.path.exists(os.path.join(folder, "bench.json")):
        with open(os.path.join(folder, "bench.json")) as f:
            bench = json.load(f)
    figdir = os.path.join(folder, "figures")
    os.makedirs(figdir, exist_ok=True)

    if not results["cases"]:
        sys.exit(f"{folder}/results.json holds no cases: nothing to report")
    # Curve records have their own section; every mesh figure and table below reads `results`
    # with the mesh cases only.
    curve_cases = [c for c in results["cases"] if c.get("scheme") == "curves"]
    surface_cases = [c for c in results["cases"] if c.get("scheme") == "surfaces"]
    limit_cases = [c for c in results["cases"] if c.get("scheme") == "limits"]
    results = dict(results, cases=[c for c in results["cases"] if c.get("scheme") not in ("curves", "surfaces", "limits")])
    curve_failures = [(c, r) for c in curve_cases + surface_cases + limit_cases for r in c["runs"] if r["verdict"] != "agree"]
    has_mesh = bool(results["cases"])
    if has_mesh:
        summary_matrix(results, figdir)
        error_histogram(results, figdir)
        convergence(results, figdir)
    pictures = error_pictures(results, folder, figdir) if has_mesh else []
    timing_fig, timing_rows = timing(bench, figdir) if bench else (None, [])

    # --- The divergence catalogue: every run that is not plain agreement. ---
    catalogue = []
    for c in results["cases"]:
        w = c.get("worst_vertex")
        for r in c["runs"]:
            if r["verdict"] == "agree":
                continue
            values = "-"
            if w and r["verdict"] == "diverge":
                values = f"core {vec(w['core'])}; " + "; ".join(
                    f"{name} {vec(p)}" for name, p in sorted(w["references"].items()))
            pos = r.get("positions", {})
            catalogue.append({
                "case": c["id"], "reference": r["reference"], "outcome": outcome(c, r),
                "class": r.get("divergence_class") or r["verdict"], "max_rel": pos.get("max_rel"),
                "worst": (f"v{w['ours_index']} valence {w['valence']} {'boundary' if w['boundary'] else 'interior'}"
                          if w and r["verdict"] == "diverge" else "-"),
                "values": values, "explanation": r.get("explanation", "")})
        if not c["runs"]:
            catalogue.append({"case": c["id"], "reference": "core", "outcome": outcome(c, {}),
                              "class": "ours-failed" if c.get("ours_failed") else "ours-rejected", "max_rel": None,
                              "worst": "-", "values": "-", "explanation": c.get("core_error", "")})
    for c, r in curve_failures:
        catalogue.append({"case": c["id"], "reference": r["reference"], "outcome": outcome(c, r),
                          "class": r.get("divergence_class", "unexplained"), "max_rel": r["measured"], "worst": r["curve"],
                          "values": f"{r['check']}: {fmt(r['measured'])} > {fmt(r['tolerance'])} {r['unit']}",
                          "explanation": r.get("explanation", "")})
    for c in curve_cases + surface_cases + limit_cases:
        if not c["runs"]:
            catalogue.append({"case": c["id"], "reference": "core", "outcome": outcome(c, {}),
                              "class": "ours-failed" if c.get("ours_failed") else "ours-rejected", "max_rel": None,
                              "worst": "-", "values": "-", "explanation": c.get("core_error", "")})
    class_counts = Counter((row["class"], row["reference"]) for row in catalogue)
    curve_md, curve_html = curve_section(curve_cases, bench, figdir)
    surface_md, surface_html = surface_section(surface_cases, bench, figdir)
    limits_md, limits_html = limits_section(limit_cases, figdir)
    curve_md, curve_html = curve_md + surface_md + limits_md, curve_html + surface_html + limits_html

    s = results["summary"]
    refs = ", ".join(f"{r['name']} ({r['version']})" for r in results.get("references", []))
    md = [f"# crossdiv conformance report: suite `{results.get('suite')}`", "",
          f"- manifest: `{results.get('manifest')}`, shard {results.get('shard')}, "
          f"{s['cases']} cases, {s['runs']} reference runs, {s['failures']} failure(s), "
          f"{fmt(results.get('seconds'), '.1f')} s with {results.get('workers', 1)} worker(s)",
          f"- references: {refs}", "",
          "## Outcomes", "", "| outcome | runs |", "|---|---|"]
    md += [f"| {k} | {v} |" for k, v in sorted(s["outcomes"].items())]
    md += ["", "Failures (JUnit) are `ours-failed` and `diverge (unexplained)`; every other outcome is a measured, "
           "classified difference.", ""]
    if has_mesh:
        md += ["## Summary matrix", "", "![summary](figures/summary_matrix.png)", ""]
    md += ["## Divergence catalogue", "", "Classes by reference:", "", "| class | reference | runs |", "|---|---|---|"]
    md += [f"| {cls} | {ref} | {n} |" for (cls, ref), n in sorted(class_counts.items())]
    md += ["", "Every run that is not agreement, with the case's worst vertex (the vertex where some reference "
           "parts most from core) and each implementation's value there:", "",
           "| case | reference | outcome | max rel | worst vertex | values at the worst vertex | explanation |",
           "|---|---|---|---|---|---|---|"]
    md += [f"| {r['case']} | {r['reference']} | {r['outcome']} | {fmt(r['max_rel'])} | {r['worst']} | "
           f"{r['values']} | {r['explanation'].replace('|', '/')} |" for r in catalogue]
    if has_mesh:
        md += ["", "## Error by level and its distribution", "", "![convergence](figures/convergence.png)", "",
               "![histogram](figures/error_histogram.png)", "", "## Where surfaces part", ""]
        md += [f"![{n}](figures/{n})" for n, _, _ in pictures] or ["No divergence small enough to draw."]
    md += curve_md
    md += ["", "## Timing", ""]
    if timing_fig:
        md += [f"`crossdiv bench`: median of {bench.get('repeats', '?')} runs, single thread, ratio = time / core "
               f"time on the same input (above 1: slower than core). {bench.get('note', '')}", "",
               "![timing](figures/timing.png)", "",
               "| input | levels | impl | input faces | output faces | median ms | ratio to core | peak RSS MB |",
               "|---|---|---|---|---|---|---|---|"]
        md += [f"| {r['input']} | {r['levels']} | {r['impl']} | {r['input_faces']} | {r['output_faces']} | "
               f"{fmt(r['median_ms'], '.2f')} | {fmt(r['ratio'], '.2f')} | {fmt(r.get('peak_rss_mb'), '.0f')} |"
               for r in timing_rows]
        if bench.get("goal"):
            g = bench["goal"]
            md += ["", f"Goal: core at least {g['target_ratio']}x faster than the fastest reference on "
                   f"{g['input']} at {g['levels']} levels: measured {fmt(g['ratio'], '.2f')}x "
                   f"(fastest reference {g['fastest_reference']}) - {'met' if g['met'] else 'NOT met'}."]
    else:
        md += ["No bench.json in this folder: run `crossdiv bench --out DIR` to add the timing section."]
    with open(os.path.join(folder, "report.md"), "w") as f:
        f.write("\n".join(md) + "\n")

    # --- index.html: the same content for a browser. ---
    def table(header, rows):
        out = ["<table><tr>" + "".join(f"<th>{html.escape(h)}</th>" for h in header) + "</tr>"]
        out += ["<tr>" + "".join(f"<td>{html.escape(str(v))}</td>" for v in row) + "</tr>" for row in rows]
        return "\n".join(out + ["</table>"])

    body = [f"<h1>crossdiv conformance report: suite {html.escape(str(results.get('suite')))}</h1>",
            f"<p>{s['cases']} cases, {s['runs']} reference runs, {s['failures']} failure(s). References: "
            f"{html.escape(refs)}.</p>",
            "<h2>Outcomes</h2>", table(["outcome", "runs"], sorted(s["outcomes"].items())),
            "<h2>Summary matrix</h2><img src='figures/summary_matrix.png'>" if has_mesh else "",
            "<h2>Divergence catalogue</h2>",
            table(["class", "reference", "runs"], [(c, r, n) for (c, r), n in sorted(class_counts.items())]),
            "<p></p>",
            table(["case", "reference", "outcome", "max rel", "worst vertex", "values at the worst vertex", "explanation"],
                  [(r["case"], r["reference"], r["outcome"], fmt(r["max_rel"]), r["worst"], r["values"],
                    r["explanation"]) for r in catalogue]),
            "<h2>Error by level and its distribution</h2><img src='figures/convergence.png'>"
            "<img src='figures/error_histogram.png'><h2>Where surfaces part</h2>" if has_mesh else ""]
    body += [f"<img src='figures/{n}'>" for n, _, _ in pictures]
    body += curve_html
    body += ["<h2>Timing</h2>"]
    if timing_fig:
        body += ["<img src='figures/timing.png'>",
                 table(["input", "levels", "impl", "input faces", "output faces", "median ms", "ratio to core",
                        "peak RSS MB"],
                       [(r["input"], r["levels"], r["impl"], r["input_faces"], r["output_faces"],
                         fmt(r["median_ms"], ".2f"), fmt(r["ratio"], ".2f"), fmt(r.get("peak_rss_mb"), ".0f"))
                        for r in timing_rows])]
    else:
        body += ["<p>No bench.json in this folder.</p>"]
    style = ("body{font-family:sans-serif;max-width:1400px;margin:auto}table{border-collapse:collapse;font-size:12px}"
             "td,th{border:1px solid #ccc;padding:2px 6px;text-align:left}img{max-width:100%}")
    with open(os.path.join(folder, "index.html"), "w") as f:
        f.write(f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>crossdiv report</title>"
                f"<style>{style}</style></head><body>\n" + "\n".join(body) + "\n</body></html>\n")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: make_report.py DIR")
    main(sys.argv[1])
