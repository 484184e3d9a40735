"""Reading results.json: which cases belong to which section, and small formatters.

The outcome of every run is written by crossdiv itself (run["outcome"], case["outcome"] for a
case without runs); nothing here derives it again.
"""
import math
import os


# Outcome categories of the summary matrix, in legend order, with their colours.
CATEGORIES = [
    ("agree", "#4caf50"),
    ("diverge (classified)", "#ffb300"),
    ("diverge (unexplained)", "#e53935"),
    ("ref-crashed", "#212121"),
    ("ref-invalid-output", "#6d4c41"),
    ("ref-nondeterministic", "#f06292"),
    ("ref-rejected", "#9e9e9e"),
    ("ref-unavailable", "#cfd8dc"),
    ("ours-rejected", "#42a5f5"),
    ("ours-failed", "#8e24aa"),
    ("not-compared", "#e0e0e0"),
    ("not run", "#ffffff"),
]


# The results.json this script reads (verification/include/crossdiv/verification/suite/report.h).
SCHEMA_VERSION = 5


def outcome(case, run=None):
    """The outcome crossdiv counted the run under (or the case, when it has no runs)."""
    return (run or case)["outcome"]


def category(case, run=None):
    """The summary matrix's category of an outcome."""
    o = outcome(case, run)
    if o == "diverge (unexplained)":
        return o
    if o.startswith("diverge"):
        return "diverge (classified)"
    if o.startswith("ours-rejected"):
        return "ours-rejected"
    if o.startswith("ref-nondeterministic"):
        return "ref-nondeterministic"
    if o not in dict(CATEGORIES):
        raise ValueError(f"unknown outcome '{o}' in {case.get('id')}")
    return o


def is_mesh_case(case):
    return case.get("operation") == "loop"


# The operations that check the half-edge work of a mesh.
HALFEDGE = ("edits", "normals")


def split_cases(results):
    """(Loop comparisons, curve checks, surface checks, studies, the other schemes' comparisons)
    of a results.json, by the kind crossdiv lists for each operation (results.json "operations"):
    a new study or scheme needs no change here."""
    kinds = {o["name"]: o for o in results["operations"]}
    cases = results["cases"]
    pick = lambda keep: [c for c in cases if c.get("operation") in kinds and keep(kinds[c["operation"]])]  # noqa: E731
    loop = pick(lambda o: o["kind"] == "comparison" and o.get("scheme") == "loop")
    schemes = pick(lambda o: o["kind"] == "comparison" and o.get("scheme") != "loop")
    studies = pick(lambda o: o["kind"] == "study")
    return loop, pick(lambda o: o["name"] == "curves"), pick(lambda o: o["name"] == "surfaces"), studies, schemes


def halfedge_cases(cases):
    """The edits and normals records of a results.json."""
    return [c for c in cases if c.get("operation") in HALFEDGE]


def entry_label(case):
    """"loop loop/edge-only L3 weak": a Loop case's rules, for figure columns."""
    o = case.get("options", {})
    return f"{case.get('operation', '')} {o.get('weights', '')}/{o.get('boundary', '')} L{case.get('levels', '')} {case.get('tier', '')}"


def short_input(name):
    return os.path.splitext(os.path.basename(name))[0] if "/" in name else name


def fmt(x, spec=".3g"):
    return "-" if x is None or (isinstance(x, float) and math.isnan(x)) else format(x, spec)


def vec(v):
    return "-" if v is None else "(" + ", ".join(f"{c:.9g}" for c in v) + ")"
