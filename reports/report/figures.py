"""The report's figures, drawn with matplotlib (Debian's python3-matplotlib) and saved as PNG
under figures/; each function returns the path relative to the report folder."""
import math
import os
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")  # no display on a build machine
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

from .records import CATEGORIES, category, entry_label, short_input  # noqa: E402
from .viewer import first_parting_level, read_view  # noqa: E402

MAX_ERROR_PICTURES = 12
# Larger meshes are left to the 3D viewer: matplotlib's 3D collections stay fast up to about this.
MAX_ERROR_PICTURE_FACES = 20000


def save(fig, figdir, name):
    """Lays out, writes figures/NAME and frees the figure; returns the relative path."""
    fig.tight_layout()
    fig.savefig(os.path.join(figdir, name), dpi=110)
    plt.close(fig)
    return f"figures/{name}"


def summary_matrix(mesh_cases, references, figdir):
    refs = references or sorted({r["reference"] for c in mesh_cases for r in c["runs"]})
    inputs = list(dict.fromkeys(c["input"] for c in mesh_cases))
    entries = list(dict.fromkeys(entry_label(c) for c in mesh_cases))
    columns = [(e, r) for e in entries for r in refs]
    index = {name: i for i, (name, _) in enumerate(CATEGORIES)}
    grid = [[index["not run"]] * len(columns) for _ in inputs]
    for c in mesh_cases:
        row = inputs.index(c["input"])
        for r in c["runs"]:
            if (entry_label(c), r["reference"]) in columns:
                grid[row][columns.index((entry_label(c), r["reference"]))] = index[category(c, r)]
        if not c["runs"]:
            for ref in refs:
                grid[row][columns.index((entry_label(c), ref))] = index[category(c)]
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


def error_histogram(mesh_cases, figdir):
    groups = defaultdict(list)
    for c in mesh_cases:
        for r in c["runs"]:
            m = r.get("positions", {}).get("max_rel")
            if m is not None:
                groups["agree" if r["verdict"] == "agree" else r.get("divergence_class") or r["verdict"]].append(
                    math.log10(max(m, 1e-20)))
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.hist(list(groups.values()), bins=[x / 2 for x in range(-40, 2)], stacked=True, label=list(groups.keys()))
    ax.axvline(math.log10(1e-12), color="red", linestyle="--", label="weak tolerance 1e-12")
    ax.set_xlabel("log10(max distance / bounding-box diagonal); exact agreement drawn at -20")
    ax.set_ylabel("reference runs")
    ax.legend(fontsize=7)
    ax.set_title("Distribution of the largest vertex error per run", fontsize=9)
    return save(fig, figdir, "error_histogram.png")


def error_by_level(mesh_cases, figdir):
    """Per-level error of every run with two or more levels, coloured by class."""
    fig, ax = plt.subplots(figsize=(8, 4.5))
    colours, palette = {}, plt.get_cmap("tab10")
    for c in mesh_cases:
        for r in c["runs"]:
            levels = r.get("positions", {}).get("level_max_rel") or []
            if len(levels) < 2 or any(v is None for v in levels):
                continue
            key = r.get("divergence_class") or "agree"
            colours.setdefault(key, palette(len(colours) % 10))
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


def _draw_mesh(ax, pts, faces, **style):
    ax.add_collection3d(Poly3DCollection([[pts[v] for v in f] for f in faces], **style))


def _equal_scales(ax, pts):
    """Sets the three axes to one cube round the points (matplotlib scales each axis to its own
    range otherwise); returns the cube's side."""
    xs, ys, zs = zip(*pts)
    span = max(max(xs) - min(xs), max(ys) - min(ys), max(zs) - min(zs)) or 1.0
    for setter, values in ((ax.set_xlim, xs), (ax.set_ylim, ys), (ax.set_zlim, zs)):
        middle = (max(values) + min(values)) / 2
        setter(middle - span / 2, middle + span / 2)
    return span


def _light_shades(polygons, light):
    """For each polygon (its first three corners), |cos| of the angle between its normal and the
    unit vector `light`: 1 facing the light, 0 edge-on."""
    shades = []
    for poly in polygons:
        a, b, c = poly[:3]
        u = [b[k] - a[k] for k in range(3)]
        v = [c[k] - a[k] for k in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        length = math.sqrt(sum(x * x for x in n)) or 1.0
        shades.append(abs(sum(n[k] * light[k] for k in range(3))) / length)
    return shades


def error_pictures(mesh_cases, folder, figdir):
    """Meshes coloured by per-vertex distance to the reference, one per divergence class,
    reference and boundary rule (the first few), so a reader sees where two surfaces part: our
    mesh at the first level where they part by more than the case's tolerance, read from the
    case's 3D view."""
    pictures, seen = [], set()
    for c in mesh_cases:
        if "view" not in c:
            continue
        view = None
        for r in c["runs"]:
            if r["verdict"] != "diverge" or len(pictures) >= MAX_ERROR_PICTURES:
                continue
            key = (r.get("divergence_class"), r["reference"], c.get("options", {}).get("boundary"))
            if key in seen:
                continue
            view = view or read_view(folder, c["view"])
            parting = first_parting_level(view, r["reference"], c.get("tolerance_rel") or 0)
            if parting is None or len(view["levels"][parting[0]]["triangles"]) > MAX_ERROR_PICTURE_FACES:
                continue
            seen.add(key)
            level, dist = parting
            pts, faces = view["levels"][level]["positions"], view["levels"][level]["triangles"]
            face_err = [max(dist[v] for v in face) for face in faces]
            fig = plt.figure(figsize=(5, 4.4))
            ax = fig.add_subplot(projection="3d")
            top = max([e for e in face_err if not math.isnan(e)] + [1e-300])
            coll = Poly3DCollection([[pts[v] for v in face] for face in faces], cmap="inferno",
                                    edgecolor=(0, 0, 0, 0.15), linewidths=0.1)
            coll.set_array([0 if math.isnan(e) else e for e in face_err])
            coll.set_clim(0, top)
            ax.add_collection3d(coll)
            _equal_scales(ax, pts)
            ax.set_axis_off()
            fig.colorbar(coll, ax=ax, shrink=0.6, label="distance to reference")
            ax.set_title(f"{short_input(c['input'])} vs {r['reference']}, level {level}\n"
                         f"{r.get('divergence_class')}, {entry_label(c)}", fontsize=8)
            name = f"error_job{c['job']}_{r['reference']}.png"
            fig.savefig(os.path.join(figdir, name), dpi=100)
            plt.close(fig)
            pictures.append(f"figures/{name}")
    return pictures


def timing(records, figdir):
    """Log-log time against output size for every implementation, one panel per scheme, warm
    solid and cold dashed (the same colour per implementation)."""
    schemes = list(dict.fromkeys(r.get("scheme", "loop") for r in records))
    fig, axes = plt.subplots(1, len(schemes), figsize=(7 * len(schemes), 4.5), squeeze=False)
    impls = list(dict.fromkeys(r["impl"] for r in records))
    for ax, scheme in zip(axes[0], schemes):
        for i, impl in enumerate(impls):
            for memory, style in (("warm", "-"), ("cold", "--")):
                rows = sorted((r for r in records if r["impl"] == impl and r.get("scheme", "loop") == scheme
                               and r.get("memory", "warm") == memory and r.get("status", "ok") == "ok"),
                              key=lambda r: r["output_faces"])
                if rows:
                    ax.plot([r["output_faces"] for r in rows], [r["median_ms"] for r in rows], style, marker="o",
                            color=f"C{i}", label=f"{impl} ({memory})")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("output faces")
        ax.set_ylabel("median time (ms)")
        ax.set_title(f"{scheme} subdivision time against output size (single thread)", fontsize=9)
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
    return save(fig, figdir, "timing.png")


def flattening(rows, target, figdir):
    """The distance mode's edges over N* against the tolerance relative to each curve's size,
    one line per curve, with the goal and N* itself."""
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for curve in dict.fromkeys(r["curve"] for r in rows):
        pts = sorted((r["tol_relative"], r["distance_edges"] / r["optimal_edges"]) for r in rows
                     if r["curve"] == curve and r.get("optimal_edges") and "tol_relative" in r)
        if pts:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", lw=0.8, ms=3, alpha=0.7)
    ax.axhline(target, color="red", ls="--", lw=1, label=f"goal {target} N* (tol <= 1e-3)")
    ax.axhline(1.0, color="black", lw=0.8, label="N*")
    ax.axvline(1e-3, color="grey", ls=":", lw=0.8)
    ax.set_xscale("log")
    ax.invert_xaxis()
    ax.set_xlabel("distance tolerance / curve size")
    ax.set_ylabel("distance-mode edges / N*")
    ax.set_title("Distance-adaptive flattening against N* = integral of sqrt(kappa / (8 tol)) ds, every bundled curve",
                 fontsize=8)
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    return save(fig, figdir, "flattening.png")


def stencil_times(rows, figdir):
    """Log-log time per frame against refined vertices, one line per implementation."""
    fig, ax = plt.subplots(figsize=(6, 4))
    rows = sorted(rows, key=lambda r: r["output_vertices"])
    for key, label in (("core_ms", "core composed stencils"), ("core_levels_ms", "core level stencils"),
                       ("opensubdiv_stencils_ms", "OpenSubdiv stencil table"),
                       ("opensubdiv_levels_ms", "OpenSubdiv PrimvarRefiner levels")):
        ax.loglog([r["output_vertices"] for r in rows], [r[key] for r in rows], marker="o", label=label)
    ax.set_xlabel("refined vertices")
    ax.set_ylabel("median time per frame (ms)")
    ax.set_title("Re-evaluation at fixed topology (Loop, tori)", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    return save(fig, figdir, "stencil_times.png")


def valence_times(rows, figdir):
    """Log-log time against k on each shape, one line per command, the regular mesh dashed."""
    shapes = list(dict.fromkeys(r["shape"] for r in rows))
    fig, axes = plt.subplots(1, len(shapes), figsize=(4.2 * len(shapes), 3.8), squeeze=False)
    for ax, shape in zip(axes[0], shapes):
        for i, command in enumerate(dict.fromkeys(r["command"] for r in rows if r["shape"] == shape)):
            pts = sorted((r["valence"], r["ms"], r["regular_ms"]) for r in rows
                         if r["shape"] == shape and r["command"] == command)
            color = f"C{i}"
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker="o", color=color, label=command)
            ax.loglog([p[0] for p in pts], [p[2] for p in pts], linestyle="--", color=color, alpha=0.6)
        ax.set_xlabel("valence k (polygon: sides)")
        ax.set_ylabel("median time (ms)")
        ax.set_title(f"{shape} (solid) and its regular mesh (dashed)", fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=6)
    return save(fig, figdir, "valence_times.png")


def surface_convergence(tables, figdir):
    fig, ax = plt.subplots(figsize=(5, 3.6))
    for key, err in (("sphere", "radial_error"), ("torus", "distance_error")):
        series = {}
        for r in tables.get(key, []):
            if err in r:
                series.setdefault(r["surface"], []).append((r["faces"], r[err]))
        for name, pts in series.items():
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker="o", label=name)
    ax.set_xlabel("faces")
    ax.set_ylabel("max distance to the exact surface")
    ax.set_title("Swept surfaces against exact ones")
    ax.legend(fontsize=7)
    return save(fig, figdir, "surface_convergence.png")


def crease_cube(cubes, figdir):
    fig = plt.figure(figsize=(3.2 * len(cubes), 3.4))
    for i, m in enumerate(cubes):
        ax = fig.add_subplot(1, len(cubes), i + 1, projection="3d")
        _draw_mesh(ax, m["positions"], m["faces"], facecolor="#9ecae1", edgecolor="#3182bd", linewidths=0.2)
        ax.set_xlim(-1, 1)
        ax.set_ylim(-1, 1)
        ax.set_zlim(-1, 1)
        ax.set_box_aspect((1, 1, 1))
        ax.view_init(elev=25, azim=-60)
        ax.set_axis_off()
        ax.set_title(m["name"], fontsize=8)
    fig.suptitle("The cube after 3 Catmull-Clark levels: what creases keep", fontsize=9)
    return save(fig, figdir, "crease_cube.png")


def vertex_age(rows, figdir):
    """Each mesh after its levels with every vertex coloured by the level it was born at (viridis,
    as `crossdiv subdivide --color age` writes them); the faces grey, only the front half drawn."""
    fig = plt.figure(figsize=(3.6 * len(rows), 3.8))
    for i, row in enumerate(rows):
        ax = fig.add_subplot(1, len(rows), i + 1, projection="3d")
        m = row["mesh"]
        pts = m["positions"]
        # The half facing the viewer (x + y > 0 for the view below): the back would show through.
        front = [f for f in m["faces"] if sum(pts[v][0] + pts[v][1] for v in f) > 0]
        _draw_mesh(ax, pts, front, facecolor="0.85", edgecolor="0.55", linewidths=0.2)
        shown = sorted({v for f in front for v in f})
        xs, ys, zs = zip(*(pts[v] for v in shown))
        ax.scatter(xs, ys, zs, c=[row["ages"][v] for v in shown], cmap="viridis", vmin=0, vmax=row["levels"], s=7,
                   depthshade=False)
        span = max(max(abs(c) for p in pts for c in p), 1e-9)
        for setter in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
            setter(-span, span)
        ax.set_box_aspect((1, 1, 1), zoom=1.35)
        ax.view_init(elev=20, azim=45)
        ax.set_axis_off()
        ax.set_title(f"{row['scheme']}, {row['levels']} levels: age 0 dark blue .. {row['levels']} yellow", fontsize=8)
    return save(fig, figdir, "vertex_age.png")


def curvature_convergence(rows, figdir):
    """Largest error of the mean and Gaussian curvature against the exact sphere and torus as the
    mean edge length h halves, one line per estimator (log-log: a slope of 2 is second order)."""
    surfaces = sorted({r["surface"] for r in rows})
    fig, axes = plt.subplots(1, 2 * len(surfaces), figsize=(3.4 * 2 * len(surfaces), 3.2), squeeze=False)
    col = 0
    for surface in surfaces:
        for key, label in (("mean_max", "H"), ("gauss_max", "K")):
            ax = axes[0][col]
            col += 1
            for est in sorted({r["estimator"] for r in rows if r["surface"] == surface}):
                sel = sorted((r for r in rows if r["surface"] == surface and r["estimator"] == est), key=lambda r: r["h"])
                ax.loglog([r["h"] for r in sel], [max(r[key], 1e-300) for r in sel], marker="o", label=est)
            ax.set_xlabel("mean edge length h")
            ax.set_title(f"{surface}: max |{label} error|", fontsize=8)
            ax.legend(fontsize=7)
    return save(fig, figdir, "curvature_convergence.png")


def curvature_mesh(rows, figdir):
    """Each mesh with every face coloured by the mean Gaussian curvature of its vertices where it
    was estimated (diverging map centred at 0: red positive, blue negative, scaled to the 95th
    percentile of |K| as `crossdiv curvature --color gaussian` does; grey: no estimate)."""
    fig = plt.figure(figsize=(4.6 * len(rows), 3.8))
    cmap = plt.get_cmap("coolwarm")
    for i, row in enumerate(rows):
        m = row["mesh"]
        pts, faces, k = m["positions"], m["faces"], row["gaussian"]
        known = row.get("estimated", [1] * len(k))
        magnitudes = sorted(abs(k[v]) for v in range(len(k)) if known[v])
        bound = max(magnitudes[int(0.95 * (len(magnitudes) - 1))] if magnitudes else 0.0, 1e-12)
        colors = []
        for f in faces:
            vals = [k[v] for v in f if known[v]]
            colors.append(cmap(0.5 + 0.5 * max(-1.0, min(1.0, sum(vals) / len(vals) / bound))) if vals else "0.7")
        ax = fig.add_subplot(1, len(rows), i + 1, projection="3d")
        ax.add_collection3d(Poly3DCollection([[pts[v] for v in f] for f in faces], facecolors=colors, edgecolors="0.3",
                                             linewidths=0.05))
        _equal_scales(ax, pts)
        ax.set_box_aspect((1, 1, 1), zoom=1.3)
        ax.view_init(elev=35, azim=-60)
        ax.set_axis_off()
        ax.set_title(f"{row['surface']}: K, blue {-bound:.3g} .. red {bound:.3g}", fontsize=8)
    return save(fig, figdir, "curvature_mesh.png")


def isosurface_convergence(rows, figdir):
    """Marching cubes against the exact implicit surfaces as the cell size h halves: the largest
    distance of a vertex to the surface, and the relative error of the enclosed volume (log-log:
    a slope of 2 is second order)."""
    fig, axes = plt.subplots(1, 2, figsize=(8.4, 3.4))
    for surface in sorted({r["surface"] for r in rows}):
        sel = sorted((r for r in rows if r["surface"] == surface), key=lambda r: r["h"])
        axes[0].loglog([r["h"] for r in sel], [max(r["max_distance"], 1e-300) for r in sel], marker="o", label=surface)
        vol = [r for r in sel if "volume_error" in r]
        if vol:
            axes[1].loglog([r["h"] for r in vol], [max(r["volume_error"], 1e-300) for r in vol], marker="o", label=surface)
    axes[0].set_title("largest vertex distance to the surface", fontsize=8)
    axes[1].set_title("relative error of the enclosed volume", fontsize=8)
    for ax in axes:
        ax.set_xlabel("cell size h")
        ax.legend(fontsize=7)
    return save(fig, figdir, "isosurface_convergence.png")


def isosurface_meshes(rows, figdir):
    """Each isosurface shaded by the angle of its faces to a light, the edges of one triangle (holes,
    or the grid's boundary) in red."""
    return shaded_meshes(rows, figdir, "isosurface_meshes.png")


def shaded_meshes(rows, figdir, name, vertical_axis="z"):
    """Meshes side by side, each shaded by the angle of its faces to a light, with the edges of one
    face (holes, borders) in red; a row with "wire" also draws every edge."""
    fig = plt.figure(figsize=(4.4 * len(rows), 4.0))
    for i, row in enumerate(rows):
        pts, faces = row["mesh"]["positions"], row["mesh"]["faces"]
        polygons = [[pts[v] for v in f] for f in faces]
        shades = [str(0.25 + 0.7 * s) for s in _light_shades(polygons, (0.4, -0.5, 0.77))]
        uses = defaultdict(int)
        for f in faces:
            for j in range(len(f)):
                uses[tuple(sorted((f[j], f[(j + 1) % len(f)])))] += 1
        ax = fig.add_subplot(1, len(rows), i + 1, projection="3d")
        ax.add_collection3d(Poly3DCollection(polygons, facecolors=shades,
                                             edgecolors="0.15" if row.get("wire") else "none", linewidths=0.3))
        for (a, b), n in uses.items():
            if n == 1:
                ax.plot(*zip(pts[a], pts[b]), color="red", linewidth=1.6, zorder=10)
        _equal_scales(ax, pts)
        ax.set_box_aspect((1, 1, 1), zoom=1.3)
        ax.view_init(elev=35 if vertical_axis == "z" else 20, azim=-60 if vertical_axis == "z" else 30,
                     vertical_axis=vertical_axis)
        ax.set_axis_off()
        ax.set_title(row["title"], fontsize=8)
    return save(fig, figdir, name)


def fitting_convergence(rows, figdir):
    """Fitting a limit surface by closest-point iterations: the two-sided Hausdorff distance
    (relative to the target's diagonal) at each iteration, one line per target, solid for the
    larger control mesh and dashed for the smaller; one panel per scheme."""
    schemes = sorted({r["scheme"] for r in rows if "steps" in r})
    fig, axes = plt.subplots(1, len(schemes), figsize=(4.6 * len(schemes), 3.8), squeeze=False)
    colours = {t: plt.cm.tab10(i % 10) for i, t in enumerate(dict.fromkeys(r["target"] for r in rows))}
    for ax, scheme in zip(axes[0], schemes):
        sel = [r for r in rows if r.get("scheme") == scheme and "steps" in r and "hausdorff" in r["steps"][0]]
        largest = {}
        for r in sel:
            largest[r["target"]] = max(largest.get(r["target"], 0), r["control_vertices"])
        for r in sel:
            big = r["control_vertices"] == largest[r["target"]]
            ax.semilogy(range(len(r["steps"])), [s["hausdorff"] for s in r["steps"]], color=colours[r["target"]],
                        linestyle="-" if big else "--", marker="o", markersize=2.5,
                        label=r["target"] if big else None)
        ax.set_title(f"{scheme}: Hausdorff distance / diagonal", fontsize=8)
        ax.set_xlabel("iteration")
        ax.legend(fontsize=6)
    return save(fig, figdir, "fitting_convergence.png")


def loop_curvature_growth(rows, figdir):
    """|Gaussian curvature| of Loop's limit surface at a vertex of valence n, measured on the limit
    points of its ring at each level (log scale), with the growth its eigenvalues predict (dashed)."""
    fig, ax = plt.subplots(figsize=(5.6, 3.6))
    for r in sorted(rows, key=lambda r: r["valence"]):
        g = [abs(x) for x in r["gaussian"]]
        line, = ax.semilogy(range(len(g)), g, marker=".", label=f"n = {r['valence']}")
        ax.semilogy(range(len(g)), [g[-1] * r["predicted_ratio"] ** (l - len(g) + 1) for l in range(len(g))],
                    linestyle="--", color=line.get_color(), linewidth=0.7)
    ax.set_xlabel("level")
    ax.set_ylabel("|K| at the extraordinary vertex")
    ax.set_title("Loop: Gaussian curvature at valence n (dashed: (nu / lambda^2)^2 per level)", fontsize=8)
    ax.legend(fontsize=6, ncol=3)
    return save(fig, figdir, "loop_curvature_growth.png")


def limit_convergence(rows, figdir):
    fig, ax = plt.subplots(figsize=(5, 3.6))
    for r in rows:
        if r["valence"] in (3, 5, 8, 12):
            ax.semilogy(range(1, len(r["distance"]) + 1), r["distance"], marker=".", label=f"{r['scheme']} n={r['valence']}")
    ax.set_xlabel("level k")
    ax.set_ylabel("|v_k - v_limit| / diagonal")
    ax.set_title("Convergence of an extraordinary vertex")
    ax.legend(fontsize=6)
    return save(fig, figdir, "limit_convergence.png")


def curve_frames(fr, figdir):
    fig, ax = plt.subplots(figsize=(5, 3.6))
    h = [r["h"] for r in fr["rows"]]
    ax.loglog(h, [r["recursive_error_rad"] for r in fr["rows"]], marker="o",
              label=f"recursive (seed), order {fr['recursive_order']:.2f}")
    ax.loglog(h, [r["rmf_error_rad"] for r in fr["rows"]], marker="s", label=f"double reflection, order {fr['rmf_order']:.2f}")
    ax.set_xlabel("parameter step h")
    ax.set_ylabel("max angle to exact RMF (rad)")
    ax.set_title("Helix frames")
    ax.legend(fontsize=8)
    return save(fig, figdir, "curve_frames.png")


def curve_degrees(d, figdir):
    fig, ax = plt.subplots(figsize=(5, 3.6))
    deg = [r["degree"] for r in d]
    ax.semilogy(deg, [max(r.get("bernstein-sum", 0), 1e-18) for r in d], marker="o", label="vs Bernstein sum")
    ed = [r for r in d if "eigen_position" in r]
    for key, name in (("eigen_position", "vs Eigen, position"), ("eigen_d1", "vs Eigen, d1"), ("eigen_d2", "vs Eigen, d2")):
        ax.semilogy([r["degree"] for r in ed], [max(r[key], 1e-18) for r in ed], marker=".", label=name)
    ax.semilogy(deg, [r["bound_position"] for r in d], "k--", label="position tolerance")
    ax.set_xlabel("degree")
    ax.set_ylabel("max error / control diagonal")
    ax.set_title("de Casteljau against two other algorithms")
    ax.legend(fontsize=7)
    return save(fig, figdir, "curve_degrees.png")


def interpolating_splines(shapes, figdir, name):
    """The keys and uniform tessellations of the TCB and Bessel-Overhauser curves of one input,
    all on one axes (the TCB family shares its keys)."""
    fig, ax = plt.subplots(figsize=(6.4, 4))
    for row in shapes:
        xs, ys = zip(*row["points"])
        ax.plot(xs, ys, lw=1.2, label=f"{row['curve']} ({row['type']})")
        kx, ky = zip(*row["keys"])
        ax.plot(kx, ky, "ko", ms=3)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_title("Interpolating splines through their keys (black)")
    ax.legend(fontsize=7, loc="best")
    return save(fig, figdir, name)


def kappa_curve(row, figdir, name):
    """A kappa-curve beside its signed curvature along the parameter: the points (black) sit where
    each quadratic piece is slowest, so every point is at a peak of |kappa| (dotted lines)."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(9, 3.8), gridspec_kw={"width_ratios": [1, 1.3]})
    cx, cy = zip(*row["control"])
    left.plot(cx, cy, "--", color="0.7", lw=0.8, label="quadratic pieces' control points")
    xs, ys = zip(*row["curve_points"])
    left.plot(xs, ys, lw=1.4, label="curve")
    px, py = zip(*row["points"])
    left.plot(px, py, "ko", ms=3.5, label="points")
    left.set_aspect("equal", adjustable="datalim")
    left.legend(fontsize=6, loc="best")
    left.set_title(row["curve"])
    u, k = zip(*row["curvature"])
    right.plot(u, k, lw=1.2)
    for at in row["point_params"]:
        right.axvline(at, color="k", ls=":", lw=0.8)
    # Near a cusp at a point (a star's tips) the curvature spans decades: then linear up to the
    # typical value and logarithmic beyond.
    magnitudes = sorted(abs(v) for v in k)
    typical = magnitudes[len(magnitudes) // 2]
    if typical > 0 and magnitudes[-1] > 100 * typical:
        right.set_yscale("symlog", linthresh=typical)
    right.set_xlabel("parameter (piece i on [i, i + 1]); dotted: the points")
    right.set_ylabel("signed curvature")
    right.set_title(f"{row['iterations']} iterations; |kappa| max at the points")
    return save(fig, figdir, name)


def kappa_convergence(rows, figdir, name):
    """The kappa-curve iteration's residual (largest middle-point move over the diagonal) per
    iteration, one line per curve."""
    fig, ax = plt.subplots(figsize=(6, 3.8))
    for row in rows:
        r = row["residuals"]
        ax.semilogy(range(1, len(r) + 1), [max(x, 1e-18) for x in r], lw=1.2, label=row["curve"])
    ax.set_xlabel("iteration")
    ax.set_ylabel("largest middle-point move / diagonal")
    ax.set_title("kappa-curve iteration: residual per iteration")
    ax.legend(fontsize=7)
    return save(fig, figdir, name)


def orientation_frames(row, figdir, name):
    """A camera path with the frame of its quaternion curve at every few samples (T red, N green,
    B blue, the columns of the rotation)."""
    fig = plt.figure(figsize=(6, 4.4))
    ax = fig.add_subplot(projection="3d")
    pts = row["points"]
    ax.plot(*zip(*pts), "k-", lw=1)
    length = 0.08 * _equal_scales(ax, pts)
    every = max(1, len(pts) // 16)
    for p, f in list(zip(pts, row["frames"]))[::every]:
        for axis, colour in zip(f, ("tab:red", "tab:green", "tab:blue")):
            ax.quiver(p[0], p[1], p[2], axis[0], axis[1], axis[2], length=length, color=colour, lw=1)
    ax.set_title(f"{row['curve']}: orientation frames (T red, N green, B blue)")
    return save(fig, figdir, name)


def surface_mesh(mesh, title, figdir, name):
    """A small triangle mesh, shaded by the facing of each triangle to a light from the viewer's
    upper left, axes at equal scales."""
    fig = plt.figure(figsize=(6, 4.6))
    ax = fig.add_subplot(projection="3d")
    p = mesh["positions"]
    tris = [[p[i] for i in t] for t in mesh["triangles"]]
    shades = [0.35 + 0.6 * s for s in _light_shades(tris, (-0.4, -0.5, 0.77))]
    ax.add_collection3d(Poly3DCollection(tris, facecolors=[(0.3 * s, 0.55 * s, 0.85 * s) for s in shades],
                                         edgecolors=(0, 0, 0, 0.15), linewidths=0.2))
    _equal_scales(ax, p)
    ax.set_title(title)
    return save(fig, figdir, name)

