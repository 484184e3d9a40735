"""The robustness table: per scheme and implementation, how the suite's comparison cases
ended, in the style of Thingi10K's statistics: for core, the inputs it refined and those it
refused (its refusals by reason); for each reference, its runs agreeing, differing for a named
reason, unexplained, rejected, crashed, hung, with an invalid result. Read from the outcomes
crossdiv recorded; nothing is derived again."""
from collections import Counter

from .model import Link, Section, Table, Text

# A run's status (results-schema.md) -> the column it is counted in, for the runs that made no
# usable result; every other run is counted by its outcome.
FAILED_RUN = {"crashed": "crashed", "threw": "crashed", "exit-status": "crashed", "no-output": "crashed",
              "timeout": "hung", "non-finite-output": "invalid", "wrong-count": "invalid",
              "not-triangles": "invalid", "unreadable-output": "invalid", "rejected": "rejected",
              "unavailable": "not compared"}

HEADER = ["scheme", "implementation", "inputs / runs", "refined / agree", "named differences", "unexplained",
          "rejected", "crashed", "hung", "invalid result", "not compared"]


def reference_column(run):
    """The column a reference run is counted in."""
    o = run["outcome"]
    if o == "agree":
        return "agree"
    if o == "diverge (unexplained)":
        return "unexplained"
    if o.startswith("diverge") or o.startswith("ref-nondeterministic"):
        return "named"
    if o.startswith("ours-rejected"):
        return "core refused"
    if o == "not-compared":
        return "not compared"
    if run.get("status") in FAILED_RUN:
        return FAILED_RUN[run["status"]]
    if o == "ref-crashed":
        return "crashed"
    # Every run is counted in a column that is shown: an outcome this table does not know is an
    # error of the report, never a run left out of its row.
    raise ValueError(f"unknown outcome '{o}' (status '{run.get('status')}') of {run.get('reference')}")


def named(counter):
    """"57 boundary-rule, 7 non-manifold-handling": the classes of the named differences."""
    return ", ".join(f"{n} {c}" for c, n in counter.most_common()) or "0"


def robustness_section(results):
    """The table over every case of a comparison operation (a scheme against its references,
    refused by core or not); None when the suite has none."""
    scheme_of = {o["name"]: o.get("scheme") for o in results["operations"] if o["kind"] == "comparison"}
    comparisons = [c for c in results["cases"] if c.get("operation") in scheme_of and not c.get("subject")]
    if not comparisons:
        return None
    core, refs = {}, {}
    for c in comparisons:
        s = scheme_of[c["operation"]]
        k = core.setdefault(s, {"inputs": 0, "refined": 0, "refused": Counter()})
        k["inputs"] += 1
        if c.get("core_error"):
            k["refused"][c.get("refusal_class") or "unexplained"] += 1
        else:
            k["refined"] += 1
        for r in c.get("runs", []):
            t = refs.setdefault((s, r["reference"]), {"runs": 0, "columns": Counter(), "classes": Counter()})
            t["runs"] += 1
            column = reference_column(r)
            t["columns"][column] += 1
            if column == "named":
                t["classes"][r.get("divergence_class") or r["outcome"]] += 1
    rows = []
    for s in sorted(core):
        k = core[s]
        rows.append([s, "core", k["inputs"], k["refined"], "-", "-", named(k["refused"]), "-", "-", "-", "-"])
        for (scheme, ref), t in sorted(refs.items()):
            if scheme != s:
                continue
            col = t["columns"]
            rows.append([s, ref, t["runs"], col["agree"], named(t["classes"]), col["unexplained"], col["rejected"],
                         col["crashed"], col["hung"], col["invalid"], col["not compared"] + col["core refused"]])
    section = Section("Robustness per implementation").add(
        Table(HEADER, rows),
        Text("Core's row counts the inputs and those it refined; its refusals by reason (declared in the case, "
             "or unexplained). A reference's row counts its runs (a second run for texture coordinates where the "
             "input has them): agreeing with core, differing for a named reason (by class), unexplained, "
             "refusing the input, crashing, hanging (killed at the time limit), making an invalid result "
             "(non-finite, a wrong count, not triangles, unreadable), and not compared (core refused the input, "
             "nothing could be matched, or the reference is not on this machine)."))
    shrunk = shrunk_failures(comparisons, scheme_of)
    if shrunk:
        section.add(Text("Each failure of a library reference (a crash, an exception, an invalid result, a divergence "
                         "no class explains), shrunk after the cases with that reference alone until removing any "
                         "face makes the failure go away (delta debugging; at most a minute each: 'cut short' when "
                         "the minute ended first). The last column runs it again on the minimal mesh, which is in "
                         "the results folder; 'comes and goes' marks a failure that did not show on its last run."),
                    Table(SHRUNK_HEADER, shrunk))
    statistics = corpus_statistics(comparisons)
    if statistics:
        section.add(Text("The inputs themselves (each counted once, from core's reading: mesh_statistics.h), by "
                         "source: how many have each feature that breaks a rule somewhere, their face sizes, and the "
                         "genus where every edge and vertex is manifold and oriented (else 'none')."),
                    Table(STATISTICS_HEADER, statistics))
    return section


SHRUNK_HEADER = ["scheme", "reference", "input", "failure", "minimal mesh", "reproduce"]


def shrunk_failures(cases, scheme_of):
    """One row per reference failure the suite shrank or said why it did not, in case order."""
    rows = []
    for c in cases:
        for r in c.get("runs", []):
            m = r.get("minimal")
            if not isinstance(m, dict):
                continue
            if m.get("mesh"):
                size = f"{m['faces']} faces, {m['vertices']} vertices"
                if m.get("cut_short"):
                    size += " (cut short)"
                if not m.get("reproduces", True):
                    size += " (comes and goes)"
                if m.get("same_as"):
                    size += " (shrunk once with " + m["same_as"] + ")"
                rows.append([scheme_of[c["operation"]], r["reference"], c["input"], m.get("symptom", ""),
                             Link(size, m["mesh"]), m.get("reproduce", "")])
            else:
                rows.append([scheme_of[c["operation"]], r["reference"], c["input"],
                             r.get("explanation") or r["outcome"], m.get("note", ""), "-"])
    return rows


STATISTICS_HEADER = ["source", "inputs", "faces (median)", "non-manifold edges", "non-manifold vertices",
                     "inconsistent orientation", "isolated vertices", "degenerate faces", "with boundary",
                     "several components", "triangles only", "quads only", "mixed", "genus 0 / 1 / more / none"]


# The corpora crossdiv installs or reads, by a folder their files' paths hold.
CORPUS_FOLDERS = [("/assimp/models/", "assimp"), ("/corpus/sweethome3d/", "sweethome3d"), ("/datasets/cgal/", "cgal"),
                  ("/shared/data/", "course")]


def source_of(name):
    """'bundled', 'edgecase', ... for 'bundled:torus'; a corpus's name for one of its files; else
    the file's folder."""
    if ":" in name and not name.startswith("/"):
        return name.split(":")[0]
    for folder, corpus in CORPUS_FOLDERS:
        if folder in name:
            return corpus
    parts = name.rstrip("/").split("/")
    return "/".join(parts[-2:-1]) or "files"


def corpus_statistics(cases):
    """One row per source and one for all, over the distinct inputs with statistics."""
    inputs = {}
    for c in cases:
        if c.get("input_statistics") and c["input"] not in inputs:
            inputs[c["input"]] = c["input_statistics"]
    if not inputs:
        return []
    groups = {}
    for name, s in inputs.items():
        groups.setdefault(source_of(name), []).append(s)
    if len(groups) > 1:
        groups["all"] = list(inputs.values())

    def row(source, stats):
        def having(key):
            return sum(1 for s in stats if s.get(key, 0) > 0)
        faces = sorted(s["faces"] for s in stats)
        genus = Counter("none" if s.get("genus") is None else min(int(s["genus"]), 2) for s in stats)
        mixed = sum(1 for s in stats if s["faces"] and s["triangles"] != s["faces"] and s["quads"] != s["faces"])
        return [source, len(stats), faces[len(faces) // 2], having("non_manifold_edges"), having("non_manifold_vertices"),
                having("inconsistent_edges"), having("isolated_vertices"), having("degenerate_faces"),
                having("boundary_edges"), sum(1 for s in stats if s["components"] > 1),
                sum(1 for s in stats if s["faces"] and s["triangles"] == s["faces"]),
                sum(1 for s in stats if s["faces"] and s["quads"] == s["faces"]), mixed,
                f"{genus[0]} / {genus[1]} / {genus[2]} / {genus['none']}"]
    return [row(src, stats) for src, stats in sorted(groups.items(), key=lambda kv: (kv[0] == "all", kv[0]))]
