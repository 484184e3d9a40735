"""The report's interactive parts: the first screen's matrix of outcomes, the failures and the
classes with a representative each, and the 3D divergence viewer (reports/viewer/viewer.js)
over the cases `crossdiv suite` wrote a view for (views/jobN.js)."""
import base64
import json
import math
import os
import shutil
from array import array
from collections import Counter, defaultdict

from .model import Interactive, Link, Section, Table, Tally, Text
from .records import category, outcome

# three.js from Debian's libjs-three (release 111, its classic scripts: a page opened from disk
# may run these but not import ES modules), copied beside the report so it opens offline.
THREE_FILES = ("/usr/share/javascript/three/build/three.min.js",
               "/usr/share/javascript/three/examples/js/controls/OrbitControls.js")
VIEWER_JS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "viewer", "viewer.js")

# The outcomes the suite counts as failures (Outcome::is_failure): ours failed, and a divergence
# or a refusal of core's that no test explains.
FAILURE = ("ours-failed", "diverge (unexplained)", "ours-rejected (unexplained)")

# The pages the suite's pages study writes beside the results (pages_study.h), linked when there.
INTERACTIVE_PAGES = (
    ("curves/editor.html", "the bundled curves in the curve editor: drag control points, de Casteljau at a chosen t, "
                           "core's distance and angle tessellations with their measured deviation, frames along the curve"),
    ("levels/levels.html", "subdivision levels side by side for every scheme: control net, wireframe, flat or smooth shading"),
)


def read_view(folder, path):
    """A views/jobN.js file (divergence_view_file.h) as Python lists: {"levels": [{"positions":
    [(x, y, z)], "triangles": [(a, b, c)]}], "references": {name: [None | [(dx, dy, dz)]]}}."""
    with open(os.path.join(folder, path)) as f:
        text = f.read().strip()
    prefix, suffix = "crossdivView(", ");"
    if not (text.startswith(prefix) and text.endswith(suffix)):
        raise ValueError(f"{path}: not a crossdiv view file")
    data = json.loads(text[len(prefix):-len(suffix)])

    def decode(b64, code, width):
        values = array(code, base64.b64decode(b64))
        return [tuple(values[i:i + width]) for i in range(0, len(values), width)]

    return {"levels": [{"positions": decode(l["positions"], "d", 3), "triangles": decode(l["triangles"], "i", 3)}
                       for l in data["levels"]],
            "references": {name: [None if o is None else decode(o, "f", 3) for o in per_level]
                           for name, per_level in data["references"].items()}}


def first_parting_level(view, reference, tolerance_rel):
    """(level, per-vertex distances) of the first level where `reference` parts from ours by more
    than `tolerance_rel` of that level's diagonal, else its last level with a vertex map; None
    when it has no map at any level."""
    found = None
    for level, offsets in enumerate(view["references"].get(reference, [])):
        if offsets is None or level == 0:
            continue
        distance = [math.sqrt(sum(x * x for x in o)) for o in offsets]
        pts = view["levels"][level]["positions"]
        diagonal = math.dist([min(p[k] for p in pts) for k in range(3)], [max(p[k] for p in pts) for k in range(3)])
        found = (level, distance)
        if max((d for d in distance if not math.isnan(d)), default=0) > tolerance_rel * diagonal:
            return found
    return found


def _kind(case, run):
    """agree, classified (a measured, named difference, or a reference's own failure) or failure."""
    c = category(case, run)
    return "agree" if c == "agree" else "failure" if c in FAILURE or outcome(case, run) in FAILURE else "classified"


def _row_name(case):
    if case.get("operation") == "invariance":
        return f"invariance ({case.get('scheme', '?')})"
    return case.get("scheme") or case.get("operation") or "?"


def _library_of(case, run):
    """The library a run speaks of: its reference, or in an invariance case the implementation
    checked against itself."""
    return run.get("subject") if case.get("operation") == "invariance" else run["reference"]


def _invariance_entry(case):
    """An invariance case's view: the implementation on the input, and as its one reference
    its run on the input written otherwise, mapped back (invariance_view); the findings listed."""
    findings = [r for r in case["runs"] if r["verdict"] not in ("agree", "not-compared")]
    label = case.get("view_reference")
    return {"job": case["job"], "id": case["id"], "view": case["view"],
            "classes": sorted({r.get("divergence_class") or r["verdict"] for r in findings}),
            "failure": any(_kind(case, r) == "failure" for r in findings),
            "reference": label, "worst_vertex": case.get("view_worst_vertex", -1),
            "runs": [{"reference": f"{r['subject']} under {r['check']}", "check": "", "outcome": outcome(case, r),
                      "explanation": r.get("explanation", "")} for r in findings]}


def matrix_table(cases, libraries):
    """Per scheme (or study) x reference library: agree / classified / failure run counts; the
    checks against exact answers, oracles and second algorithms of ours share one column."""
    own = "exact answers and own checks"
    counts = defaultdict(Counter)
    for c in cases:
        for r in c.get("runs", []):
            column = _library_of(c, r) if _library_of(c, r) in libraries else own
            counts[_row_name(c)][(column, _kind(c, r))] += 1
        if not c.get("runs"):
            counts[_row_name(c)][(own, _kind(c, None))] += 1
    columns = list(libraries) + [own]
    rows = []
    for name in sorted(counts, key=lambda n: (n != "loop", n)):
        k = counts[name]
        rows.append([name] + [Tally(k[(col, 'agree')], k[(col, 'classified')], k[(col, 'failure')])
                              if any(k[(col, x)] for x in ("agree", "classified", "failure")) else "-" for col in columns])
    return Table(["scheme or study"] + columns, rows)


def view_entries(mesh_cases):
    """The cases with a 3D view (of every scheme), as the viewer lists them: failures first, then
    one per divergence class (its first case), then the rest in job order."""
    entries = []
    for c in mesh_cases:
        if "view" not in c:
            continue
        if c.get("operation") == "invariance":
            entries.append(_invariance_entry(c))
            continue
        diverging = [r for r in c["runs"] if r["verdict"] == "diverge"]
        worst = max(diverging, key=lambda r: r.get("positions", {}).get("max_rel") or 0, default=None)
        classes = sorted({r.get("divergence_class") or r["verdict"] for r in diverging})
        entries.append({"job": c["job"], "id": c["id"], "view": c["view"], "classes": classes,
                        "failure": any(_kind(c, r) == "failure" for r in c["runs"]),
                        "reference": worst["reference"] if worst else None,
                        "worst_vertex": (c.get("worst_vertex") or {}).get("ours_index", -1),
                        "runs": [{"reference": r["reference"], "check": r.get("check", ""), "outcome": outcome(c, r),
                                  "explanation": r.get("explanation", "")}
                                 for r in c["runs"]]})
    # Representatives: the first case of each class, the most frequent classes first.
    frequency = Counter(k for e in entries for k in e["classes"])
    seen, first, rest = set(), [], []
    for e in entries:
        new = [k for k in e["classes"] if k not in seen]
        seen.update(e["classes"])
        if e["failure"] or new:
            first.append(((not e["failure"], -max((frequency[k] for k in new), default=0)), e))
        else:
            rest.append(e)
    ordered = [e for _, e in sorted(first, key=lambda pair: pair[0])] + rest
    for e in ordered:
        e["label"] = ("FAILURE " if e["failure"] else "") + f"job {e['job']}: {e['id']} [{', '.join(e['classes'])}]"
    return ordered


def copy_viewer(folder):
    """three.js, OrbitControls and viewer.js into folder/viewer/. Raises SystemExit naming the
    package when Debian's three.js is missing."""
    target = os.path.join(folder, "viewer")
    os.makedirs(target, exist_ok=True)
    for src in THREE_FILES + (VIEWER_JS,):
        if not os.path.exists(src):
            raise SystemExit(f"{src} is missing: the 3D viewer needs Debian's libjs-three (apt-get install libjs-three)")
        shutil.copyfile(os.path.realpath(src), os.path.join(target, os.path.basename(src)))


def viewer_html(entries):
    # The case list is small (labels, runs); the meshes stay in views/jobN.js. "</" is
    # escaped so an id can never close the script element.
    data = json.dumps(entries).replace("</", "<\\/")
    return ("<div id='crossdiv-viewer'><div class='cv-controls'>case <select class='cv-case'></select> "
            "reference <select class='cv-reference'></select> <select class='cv-level'></select> "
            "<label><input type='checkbox' class='cv-net' checked> control net and ancestors</label> "
            "<label><input type='checkbox' class='cv-wire'> wireframe</label> "
            "<label><input type='checkbox' class='cv-flat'> flat shading</label> "
            "<label><input type='checkbox' class='cv-texture' checked> checkerboard through the texture coordinates "
            "(cases that compare them)</label></div>"
            "<canvas></canvas><div class='cv-side'><p class='cv-info'></p><div class='cv-picked'></div>"
            "<div class='cv-uv-box' style='display: none'><p class='cv-uv-text'></p>"
            "<canvas class='cv-uv' style='width: 300px; height: 300px'></canvas></div>"
            "<div class='cv-minimal'></div>"
            "<p>Drag to orbit, wheel to zoom, right-drag to pan, click to pick a vertex. Colour: distance to the chosen "
            "reference at the chosen level (light: equal, dark red: the largest at that level; grey: no matched vertex). Green: the "
            "selected vertex (the worst until a pick); blue: the input vertices it descends from, on the control net. "
            "Where texture coordinates are compared, the surface carries a checkerboard through them, coloured by each "
            "corner's distance to the reference's value at the last level, and a click picks a face corner: the side "
            "of a seam that was clicked.</p>"
            "</div></div>"
            f"<script>window.CROSSDIV_VIEWS = {data};</script>"
            "<script src='viewer/three.min.js'></script><script src='viewer/OrbitControls.js'></script>"
            "<script src='viewer/viewer.js'></script>")


def view_index(mesh_cases):
    """Each viewed case's place in the viewer's list, by job: what a link's data-view names."""
    return {e["job"]: i for i, e in enumerate(view_entries(mesh_cases))}


def first_screen(cases, mesh_cases, libraries, folder):
    """The section that answers the suite's question at once: the matrix, the failures, the
    classes with a representative each, and the viewer."""
    entries = view_entries(mesh_cases)
    index = {e["job"]: i for i, e in enumerate(entries)}

    def case_link(c):
        if c["job"] in index:
            return Link(c["id"], "#crossdiv-viewer", f" data-view='{index[c['job']]}'")
        return c["id"]

    s = Section("Overview").add(
        Text("Runs per scheme (or study) and reference: agree / classified (a measured difference with a named "
             "cause, or a reference's own failure) / failure (ours failed, or a divergence or a refusal of core's "
             "that no test explains)."),
        matrix_table(cases, libraries))
    failures = [(case_link(c), _library_of(c, r), outcome(c, r), r.get("explanation", "")) for c in cases
                for r in c.get("runs", []) if _kind(c, r) == "failure"]
    failures += [(case_link(c), "core", outcome(c), c.get("core_error", "")) for c in cases
                 if not c.get("runs") and _kind(c, None) == "failure"]
    s.add(Text(f"Failures: {len(failures)}." + ("" if failures else " Nothing failed.")))
    if failures:
        s.add(Table(["case", "reference", "outcome", "explanation"], failures))
    representatives, counts = {}, Counter()
    for c in cases:
        runs = [(outcome(c, r), _library_of(c, r)) for r in c.get("runs", []) if _kind(c, r) == "classified"]
        if not c.get("runs") and _kind(c, None) == "classified":
            runs = [(outcome(c), "core")]
        for key in runs:
            counts[key] += 1
            # A case with a 3D view represents its class when there is one.
            if key not in representatives or (c["job"] in index and representatives[key]["job"] not in index):
                representatives[key] = c
    s.add(Text("Each class of difference by reference, with one representative case (a link opens it in the 3D "
               "viewer below when it has a view; results.csv lists every run):"),
          Table(["outcome", "reference", "runs", "representative"],
                [(o, ref, counts[(o, ref)], case_link(representatives[(o, ref)])) for (o, ref) in sorted(counts)]))
    if entries:
        copy_viewer(folder)
        s.add(Text(f"3D views of {len(entries)} case(s) where a reference diverges (failures first, then one per "
                   "class, then the rest):"),
              Interactive(viewer_html(entries),
                          f"index.html shows {len(entries)} of these cases in an interactive 3D viewer (views/jobN.js)."))
    pages = [(href, what) for href, what in INTERACTIVE_PAGES if os.path.exists(os.path.join(folder, href))]
    if pages:
        s.add(Interactive("<p>Interactive pages: " + "; ".join(f"<a href='{href}'>{what}</a>" for href, what in pages) + ".</p>",
                          "Interactive pages: " + "; ".join(f"{what} (`{href}`)" for href, what in pages) + "."))
    return s
