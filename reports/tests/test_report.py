"""Tests of the report: the section model renders the same content to Markdown and HTML, a
table cell never breaks its row, and a small results.json becomes a report whose every
section, table and figure is there."""
import json
import math
import os
import re
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

import make_report  # noqa: E402
from report.model import Figure, Section, Table, Tally, Text, md_cell, render_html, render_markdown  # noqa: E402
from report.viewer import matrix_table  # noqa: E402
from report.records import category, split_cases  # noqa: E402
from report.robustness import SHRUNK_HEADER, corpus_statistics, robustness_section  # noqa: E402
from report.suite_time import suite_time_section  # noqa: E402
from report.sections import timing_section  # noqa: E402


def cells(line):
    """The cells of a Markdown table line, split at unescaped pipes."""
    return re.split(r"(?<!\\)\|", line.strip())[1:-1]


def tables_of(markdown):
    """Each Markdown table as a list of its lines' cell lists."""
    tables, current = [], None
    for line in markdown.split("\n"):
        if line.startswith("|"):
            current = current if current is not None else []
            current.append(cells(line))
        elif current is not None:
            tables.append(current)
            current = None
    return tables + ([current] if current else [])


def test_a_cell_with_a_pipe_or_a_newline_stays_in_its_row():
    assert md_cell("edgecase:valence-2 | loop") == "edgecase:valence-2 \\| loop"
    assert md_cell("two\nlines") == "two lines"
    md = render_markdown("t", [], [Section("s").add(Table(["a", "b"], [("x | y", "z\nw")]))])
    [table] = tables_of(md)
    assert [len(row) for row in table] == [2, 2, 2]
    assert table[2] == [" x \\| y ", " z w "]


def test_markdown_and_html_carry_the_same_blocks():
    body = [Section("One").add(Text("a `code` span"), Table(["h"], [(1,), (2,)]), Figure("figures/f.png", "f")),
            Section("Two").add(Table(["p", "q"], [("<b>", "&")]))]
    md, page = render_markdown("T", ["- intro"], body), render_html("T", ["- intro"], body)
    assert md.count("## ") == page.count("<h2>") == 2
    assert len(tables_of(md)) == page.count("<table>") == 2
    assert page.count("<tr>") == sum(len(t) - 1 for t in tables_of(md))  # the Markdown rule line has no <tr>
    assert "![f](figures/f.png)" in md and "src='figures/f.png'" in page
    assert "<code>code</code>" in page and "&lt;b&gt;" in page and "&amp;" in page


def results_fixture():
    """One Loop case with an agreement and a classified divergence (its id has a '|'), a case
    core refused, a curve check that fails, and a study; outcomes as crossdiv writes them."""
    worst = {"ours_index": 3, "valence": 4, "boundary": True, "core": [0, 0, 0], "references": {"cgal": [0, 0, 1e-3]}}
    loop = {"input": "bundled:open-patch", "operation": "loop", "scheme": "loop", "job": 0,
            "id": "bundled:open-patch | loop weights=loop boundary=edge-and-corner L2 weak tol=1e-12",
            "options": {"weights": "loop", "boundary": "edge-and-corner"}, "levels": 2, "tier": "weak",
            "tolerance_rel": 1e-12, "worst_vertex": worst, "runs": [
                {"reference": "opensubdiv", "verdict": "agree", "divergence_class": "", "outcome": "agree",
                 "explanation": "max relative error 1e-16", "positions": {"max_rel": 1e-16, "level_max_rel": [1e-16, 1e-16]}},
                {"reference": "cgal", "verdict": "diverge", "divergence_class": "corner-rule",
                 "outcome": "diverge (corner-rule)", "explanation": "cgal has no edge-and-corner | measured",
                 "positions": {"max_rel": 1e-3, "level_max_rel": [1e-3, 1e-3]}}]}
    refused = {"input": "edgecase:bowtie", "operation": "loop", "job": 1, "id": "edgecase:bowtie | loop",
               "options": {"weights": "loop", "boundary": "edge-only"}, "levels": 1, "tier": "weak",
               "core_error": "vertex 0 is a bowtie", "runs": [], "outcome": "ours-rejected"}
    curve = {"input": "curve:s", "operation": "curves", "job": 2, "id": "curve:s | curves", "subjects": ["s"],
             "tables": {}, "runs": [
                 {"reference": "eigen", "subject": "s", "check": "position", "measured": 2e-12, "tolerance": 1e-13,
                  "unit": "rel", "verdict": "diverge", "divergence_class": "unexplained",
                  "outcome": "diverge (unexplained)", "explanation": "vs Eigen"}]}
    study = {"input": "fans", "operation": "spectrum", "job": 3, "id": "fans | spectrum", "subjects": [],
             "tables": {"spectrum": [{"scheme": "loop", "valence": 3, "subdominant": 0.25, "subdominant_multiplicity": 2,
                                      "next": 0.1, "vertex_rate": 0.2, "max_difference": 1e-16,
                                      "regular_characteristic_map": True}]},
             "runs": [{"reference": "closed form", "subject": "loop n=3", "check": "spectrum", "measured": 1e-16,
                       "tolerance": 1e-12, "unit": "abs", "verdict": "agree", "outcome": "agree", "explanation": ""}]}
    # Every operation as crossdiv lists them (a study's kind is what makes it one).
    operations = ([{"name": s, "kind": "comparison", "scheme": s}
                   for s in ("loop", "catmull-clark", "doo-sabin", "sqrt3", "butterfly", "modified-butterfly")] +
                  [{"name": c, "kind": "checks"} for c in ("curves", "surfaces", "edits", "normals")] +
                  [{"name": s, "kind": "study"} for s in ("schemes", "creases", "limit-positions", "vertex-age", "curvature",
                                                          "isosurface", "fitting", "multiresolution", "pages", "spectrum",
                                                          "convergence")])
    return {"tool": "crossdiv suite", "schema_version": 5, "suite": "tiny", "operations": operations, "manifest": "tiny.suite", "shard": "1/1",
            "workers": 1, "seconds": 1.0, "references": [{"name": "opensubdiv", "version": "3.5"},
                                                          {"name": "cgal", "version": "5.5"}],
            "summary": {"cases": 4, "runs": 5, "failures": 1,
                        "outcomes": {"agree": 2, "diverge (corner-rule)": 1, "ours-rejected": 1,
                                     "diverge (unexplained)": 1}},
            "cases": [loop, refused, curve, study]}


def test_a_small_suite_folder_renders_every_section(tmp_path):
    results = results_fixture()
    (tmp_path / "results.json").write_text(json.dumps(results))
    make_report.main(str(tmp_path))
    md = (tmp_path / "report.md").read_text()
    page = (tmp_path / "index.html").read_text()
    for title in ("Overview", "Outcomes", "Summary matrix", "Divergence catalogue", "Error by level and its distribution",
                  "Curves", "Schemes and limit behaviour", "Timing"):
        assert f"## {title}" in md and f"<h2>{title}</h2>" in page
    assert md.index("## Overview") < md.index("## Outcomes")  # the first screen answers the question
    for table in tables_of(md):  # every row has its header's cells, ids with '|' included
        assert len({len(row) for row in table}) == 1, table
    header = lambda t: [h.strip() for h in t[0]]  # noqa: E731
    [matrix] = [t for t in tables_of(md) if header(t)[0] == "scheme or study"]
    assert header(matrix) == ["scheme or study", "opensubdiv", "cgal", "exact answers and own checks"]
    assert [c.strip() for c in matrix[2]] == ["loop", "1 / 0 / 0", "0 / 1 / 0", "0 / 1 / 0"]  # the bowtie core refused
    [failures] = [t for t in tables_of(md) if header(t) == ["case", "reference", "outcome", "explanation"]]
    assert [(r[1].strip(), r[2].strip()) for r in failures[2:]] == [("eigen", "diverge (unexplained)")]
    [classes] = [t for t in tables_of(md) if header(t) == ["outcome", "reference", "runs", "representative"]]
    assert sorted((r[0].strip(), r[1].strip(), r[2].strip()) for r in classes[2:]) == [
        ("diverge (corner-rule)", "cgal", "1"), ("ours-rejected", "core", "1")]
    # report.md is the summary (every run is in results.csv); index.html keeps the full list.
    assert "results.csv lists every run" in md and "v3 valence 4 boundary" not in md
    assert "v3 valence 4 boundary" in page and "<details>" in page
    for png in ("summary_matrix.png", "convergence.png", "error_histogram.png"):
        assert (tmp_path / "figures" / png).stat().st_size > 1000


def test_cases_are_split_by_operation_and_outcomes_read_not_derived():
    mesh, curves, surfaces, studies, schemes = split_cases(results_fixture())
    assert [len(mesh), len(curves), len(surfaces), len(studies), len(schemes)] == [2, 1, 0, 1, 0]
    assert category(mesh[0], mesh[0]["runs"][1]) == "diverge (classified)"
    assert category(curves[0], curves[0]["runs"][0]) == "diverge (unexplained)"
    assert category(mesh[1]) == "ours-rejected"


def test_a_scheme_case_is_told_by_its_kind_and_counted_per_rule_and_reference(tmp_path):
    results = results_fixture()
    cc = {"input": "bundled:open-patch", "operation": "catmull-clark", "job": 4,
          "id": "bundled:open-patch | catmull-clark boundary=default L2 weak tol=1e-12",
          "options": {"boundary": "edge-only"}, "levels": 2, "tier": "weak", "tolerance_rel": 1e-12, "runs": [
              {"reference": "opensubdiv", "rule": "edge-only", "status": "ok", "verdict": "agree", "divergence_class": "",
               "outcome": "agree", "positions": {"max_rel": 1e-16}, "explanation": ""},
              {"reference": "openmesh", "rule": "midpoint-average", "status": "ok", "verdict": "diverge",
               "divergence_class": "boundary-rule", "outcome": "diverge (boundary-rule)", "positions": {"max_rel": 0.02},
               "explanation": "openmesh applies the midpoint-average boundary rule"}]}
    results["cases"].append(cc)
    mesh, curves, surfaces, studies, schemes = split_cases(results)
    assert schemes == [cc] and cc not in mesh + studies
    (tmp_path / "results.json").write_text(json.dumps(results))
    make_report.main(str(tmp_path))
    md = (tmp_path / "report.md").read_text()
    assert "## Every scheme against its references" in md
    [table] = [t for t in tables_of(md) if [h.strip() for h in t[0]][:3] == ["scheme", "levels", "requested rule"]]
    assert sorted(tuple(c.strip() for c in row) for row in table[2:]) == [
        ("catmull-clark", "2", "edge-only", "openmesh", "midpoint-average", "diverge (boundary-rule)", "1"),
        ("catmull-clark", "2", "edge-only", "opensubdiv", "edge-only", "agree", "1")]


def test_the_overview_counts_what_the_suite_counts_and_colours_it():
    # A refusal of core's that no test explains is a failure of the suite (Outcome::is_failure),
    # as an unexplained divergence is; a declared refusal and a named divergence are classified.
    def case(job, outcome):
        return {"job": job, "id": f"case {job}", "scheme": "loop", "operation": "loop",
                "runs": [{"reference": "vtk", "outcome": outcome, "verdict": outcome.split(" ")[0]}]}
    cases = [case(0, "agree"), case(1, "diverge (corner-rule)"), case(2, "ours-rejected (non-manifold-handling)"),
             case(3, "ours-rejected (unexplained)"), case(4, "diverge (unexplained)")]
    table = matrix_table(cases, ["vtk"])
    tally = table.rows[0][1]
    assert (tally.agree, tally.classified, tally.failure) == (1, 2, 2)
    assert str(tally) == "1 / 2 / 2"  # report.md: as before
    html = render_html("t", [], [Section("Overview").add(table)])
    assert "<tr class='failing'>" in html and "<span class='failure nonzero'>2</span>" in html
    assert "<span class='agree'>1</span>" in html
    calm = render_html("t", [], [Section("Overview").add(Table(["x", "vtk"], [["loop", Tally(3, 1, 0)]]))])
    body = calm.split("</style>")[1]
    assert "nonzero" not in body and "failing" not in body
    # Its own stylesheet, inlined: the page needs no network.
    assert ".failure.nonzero" in html and "http" not in html.split("</style>")[0]


def test_the_robustness_table_counts_each_implementations_runs_by_how_they_ended():
    def run(ref, outcome, status="ok", cls=""):
        return {"reference": ref, "outcome": outcome, "status": status, "divergence_class": cls,
                "verdict": outcome.split(" ")[0]}
    results = {"operations": [{"name": "catmull-clark", "kind": "comparison", "scheme": "catmull-clark"},
                              {"name": "curvature", "kind": "study"}],
               "cases": [
                   {"operation": "catmull-clark", "runs": [run("opensubdiv", "agree"),
                                                           run("openmesh", "diverge (boundary-rule)", cls="boundary-rule")]},
                   {"operation": "catmull-clark", "runs": [run("opensubdiv", "agree"),
                                                           run("openmesh", "ref-crashed", "crashed")]},
                   {"operation": "catmull-clark", "runs": [run("opensubdiv", "diverge (unexplained)"),
                                                           run("openmesh", "ref-crashed", "timeout")]},
                   {"operation": "catmull-clark", "runs": [run("opensubdiv", "ref-invalid-output", "wrong-count"),
                                                           run("openmesh", "ref-rejected", "rejected")]},
                   {"operation": "catmull-clark", "core_error": "x.ac: Assimp could not read it", "runs": [],
                    "refusal_class": "invalid-input-handling", "outcome": "ours-rejected (invalid-input-handling)"},
                   {"operation": "curvature", "runs": [run("core", "agree")]}]}
    section = robustness_section(results)
    [table] = section.blocks[:1]
    rows = {tuple(r[:2]): r[2:] for r in table.rows}
    # core: 5 inputs, 4 refined, 1 refused by its reason; the study's case is not counted.
    assert rows[("catmull-clark", "core")] == [5, 4, "-", "-", "1 invalid-input-handling", "-", "-", "-", "-"]
    # runs, agree, named, unexplained, rejected, crashed, hung, invalid result, not compared
    assert rows[("catmull-clark", "opensubdiv")] == [4, 2, "0", 1, 0, 0, 0, 1, 0]
    assert rows[("catmull-clark", "openmesh")] == [4, 0, "1 boundary-rule", 0, 1, 1, 1, 0, 0]
    assert robustness_section({"operations": results["operations"], "cases": results["cases"][-1:]}) is None
    # Each run lands in a shown column: the counts of a row add up to its runs.
    for (scheme, impl), counts in rows.items():
        if impl != "core":
            named_runs = sum(int(part.split()[0]) for part in counts[2].split(", ")) if counts[2] != "0" else 0
            assert counts[0] == counts[1] + named_runs + sum(counts[3:]), (impl, counts)
    results["cases"][0]["runs"][0]["outcome"] = "ours-failed (something new)"
    with pytest.raises(ValueError):
        robustness_section(results)


def test_the_robustness_section_lists_each_shrunk_reference_failure_with_its_reproduce_line():
    crashed = {"reference": "openmesh", "outcome": "ref-crashed", "status": "crashed", "verdict": "ref-crashed",
               "minimal": {"mesh": "minimal/job3-openmesh.obj", "faces": 2, "vertices": 5,
                           "symptom": "openmesh fails (crashed)", "cut_short": False, "reproduces": True,
                           "reference": "openmesh",
                           "reproduce": "crossdiv compare minimal/job3-openmesh.obj --scheme catmull-clark "
                                        "--boundary edge-only --levels 2 --against openmesh"}}
    flaky = {"reference": "vtk", "outcome": "ref-crashed", "status": "crashed", "verdict": "ref-crashed",
             "minimal": {"mesh": "minimal/job4-vtk.obj", "faces": 900, "vertices": 500, "symptom": "vtk fails (crashed)",
                         "cut_short": True, "reproduces": False, "reproduce": "crossdiv compare ..."}}
    hung = {"reference": "cgal", "outcome": "ref-crashed", "status": "timeout", "verdict": "ref-crashed",
            "explanation": "timed out after 120 s",
            "minimal": {"note": "not shrunk: it timed out, and each smaller try would cost its time limit"}}
    # The same run of OpenMesh in a case with another rule of core's: shrunk once.
    repeated = dict(crashed, minimal=dict(crashed["minimal"], same_as="chair.obj | catmull-clark L2"))
    results = {"operations": [{"name": "catmull-clark", "kind": "comparison", "scheme": "catmull-clark"}],
               "cases": [{"operation": "catmull-clark", "input": "chair.obj",
                          "runs": [{"reference": "opensubdiv", "outcome": "agree", "status": "ok"}, crashed]},
                         {"operation": "catmull-clark", "input": "spider.stl", "runs": [flaky, hung]},
                         {"operation": "catmull-clark", "input": "chair.obj", "runs": [repeated]}]}
    section = robustness_section(results)
    [table] = [b for b in section.blocks if getattr(b, "header", None) == SHRUNK_HEADER]
    assert [[str(getattr(v, "text", v)) for v in row] for row in table.rows] == [
        ["catmull-clark", "openmesh", "chair.obj", "openmesh fails (crashed)", "2 faces, 5 vertices",
         crashed["minimal"]["reproduce"]],
        ["catmull-clark", "vtk", "spider.stl", "vtk fails (crashed)", "900 faces, 500 vertices (cut short) (comes and goes)",
         "crossdiv compare ..."],
        ["catmull-clark", "cgal", "spider.stl", "timed out after 120 s", hung["minimal"]["note"], "-"],
        ["catmull-clark", "openmesh", "chair.obj", "openmesh fails (crashed)",
         "2 faces, 5 vertices (shrunk once with chair.obj | catmull-clark L2)", crashed["minimal"]["reproduce"]]]
    assert table.rows[0][4].href == "minimal/job3-openmesh.obj"
    # Without a shrunk failure, no such table.
    del crashed["minimal"], flaky["minimal"], hung["minimal"], repeated["minimal"]
    assert not [b for b in robustness_section(results).blocks if getattr(b, "header", None) == SHRUNK_HEADER]


def test_the_corpus_statistics_count_each_input_once_by_source():
    def stats(faces, triangles, quads, genus, **extra):
        s = {"faces": faces, "triangles": triangles, "quads": quads, "genus": genus, "components": 1}
        s.update(extra)
        return s
    cases = [
        {"input": "bundled:tetrahedron", "input_statistics": stats(4, 4, 0, 0)},
        {"input": "bundled:tetrahedron", "input_statistics": stats(4, 4, 0, 0)},  # the same input again
        {"input": "bundled:torus", "input_statistics": stats(16, 0, 16, 1)},
        {"input": "/usr/share/assimp/models/OBJ/box.obj", "input_statistics": stats(12, 12, 0, 0)},
        {"input": "/data/furniture/chair.obj", "input_statistics":
            stats(10, 6, 4, None, non_manifold_vertices=2, boundary_edges=5, components=3)},
        {"input": "/data/furniture/broken.obj", "core_error": "unreadable"}]
    rows = {r[0]: r[1:] for r in corpus_statistics(cases)}
    assert rows["bundled"] == [2, 16, 0, 0, 0, 0, 0, 0, 0, 1, 1, 0, "1 / 1 / 0 / 0"]
    assert rows["furniture"] == [1, 10, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, "0 / 0 / 0 / 1"]
    assert rows["assimp"][:2] == [1, 12]
    assert rows["all"][0] == 4 and list(rows)[-1] == "all"
    assert corpus_statistics([{"input": "x", "runs": []}]) == []


def test_the_suite_time_splits_each_operations_seconds_into_core_references_and_the_rest():
    results = {"seconds": 3.0, "workers": 2, "cases": [
        {"operation": "loop", "job_seconds": 2.0, "core_seconds": 0.5,
         "runs": [{"reference": "opensubdiv", "seconds": 0.25}, {"reference": "meshlab", "seconds": 1.0}]},
        {"operation": "loop", "job_seconds": 1.0, "core_seconds": 0.25, "runs": [{"reference": "opensubdiv", "seconds": 0.25}]},
        {"operation": "curves", "job_seconds": 1.0, "runs": []}]}
    section = suite_time_section(results)
    ops, refs = section.blocks[1], section.blocks[2]
    rows = {r[0]: list(r[1:]) for r in ops.rows}
    # loop: 2 jobs, 3 runs, 3.0 s (75% of 4.0), core 0.75, references 1.5, the rest 0.75 over 5 runs.
    assert rows["loop"] == [2, 3, "3.0", "75%", "0.8", "1.5", "0.8", "0.150"]
    assert rows["curves"] == [1, 0, "1.0", "25%", "0.0", "0.0", "1.0", "1.000"]
    assert [r[0] for r in ops.rows] == ["loop", "curves"]  # the largest first
    assert {r[0]: list(r[1:]) for r in refs.rows} == {"meshlab": [1, "1.0", "1.000"], "opensubdiv": [2, "0.5", "0.250"]}
    assert "1.8 s (44%)" in section.blocks[0].text  # the rest in all: 0.75 + 1.0
    assert suite_time_section({"cases": [{"operation": "loop", "runs": []}]}) is None


def test_the_coverage_table_has_a_row_for_every_core_header_folder():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    with open(os.path.join(root, "docs", "coverage.md")) as f:
        rows = [line for line in f.read().splitlines() if line.startswith("| ") and line.count("|") == 5]
    assert len(rows) > 10
    for part in ("subdiv/", "mesh/", "curves/", "surfaces/", "io/"):
        assert any(part in row for row in rows), part


def test_interpolating_splines_get_their_figure_and_continuity_table(tmp_path):
    results = results_fixture()
    curve = results["cases"][2]
    keys = [[0, 0], [1, 2], [3, 3], [4, 1]]
    curve["tables"] = {
        "shapes": [{"curve": "cr", "type": "tcb", "keys": keys, "tcb": [], "points": [[1, 2], [2, 2.8], [3, 3]]},
                   {"curve": "c+", "type": "tcb", "keys": keys, "tcb": [[0, 0.5, 0]] * 4,
                    "points": [[1, 2], [2.2, 2.9], [3, 3]]}],
        "continuity": [{"curve": "cr", "type": "tcb", "joints": 2, "c0_gap_rel": 0, "c1_jump_rel": 0, "c2_jump_rel": 1.0},
                       {"curve": "c+", "type": "tcb", "joints": 2, "c0_gap_rel": 0, "c1_jump_rel": 0.25,
                        "c2_jump_rel": 1.4},
                       {"curve": "b", "type": "bspline", "joints": 2, "c0_gap_rel": 0, "c1_jump_rel": 0,
                        "c2_jump_rel": 0}]}
    (tmp_path / "results.json").write_text(json.dumps(results))
    make_report.main(str(tmp_path))
    md = (tmp_path / "report.md").read_text()
    figures = list((tmp_path / "figures").glob("interpolating_splines_*.png"))
    assert len(figures) == 1 and figures[0].stat().st_size > 1000
    table = [t for t in tables_of(md) if t[0][0].strip() == "curve" and t[0][1].strip() == "type"][0]
    # The TCB rows, not the B-spline's (it is no interpolating spline).
    assert [row[0].strip() for row in table[2:]] == ["cr", "c+"]
    assert table[3][4].strip() == "0.25"


def test_a_camera_path_gets_its_orientation_figure(tmp_path):
    results = results_fixture()
    frame = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    results["cases"][2]["tables"] = {
        "orientations": [{"curve": "fly", "points": [[0, 0, 0], [1, 0.5, 0.2], [2, 1, 0]], "frames": [frame] * 3}]}
    (tmp_path / "results.json").write_text(json.dumps(results))
    make_report.main(str(tmp_path))
    figures = list((tmp_path / "figures").glob("orientation_frames_*.png"))
    assert len(figures) == 1 and figures[0].stat().st_size > 1000
    assert "fly: positions a cubic Bezier chain" in (tmp_path / "report.md").read_text()


def test_a_sweep_with_corners_gets_its_table_and_picture(tmp_path):
    results = results_fixture()
    square = {"positions": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.5]], "triangles": [[0, 1, 2], [0, 2, 3]]}
    row = {"surface": "frame (rmf)", "kind": "gcyl", "faces": 2, "closed": False, "boundary_edges": 4,
           "signed_volume": 0.0, "corners": 4, "corner_thickness_rel": 0.0, "mesh": square}
    results["cases"].append({"input": "surface:frame", "operation": "surfaces", "job": 4, "id": "surface:frame | surfaces",
                             "subjects": ["frame (rmf)"], "tables": {"surfaces": [row]}, "outcome": "agree",
                             "runs": []})
    (tmp_path / "results.json").write_text(json.dumps(results))
    make_report.main(str(tmp_path))
    md = (tmp_path / "report.md").read_text()
    table = [t for t in tables_of(md) if t[0][:2] == [" surface ", " corners "]]
    assert table and table[0][2][1].strip() == "4", tables_of(md)
    assert (tmp_path / "figures" / "cornered_sweep_0.png").stat().st_size > 1000


def test_a_kappa_curve_gets_its_table_curvature_plot_and_convergence(tmp_path):
    results = results_fixture()
    curve = [c for c in results["cases"] if c["operation"] == "curves"][0]
    square = [[1, 1], [-1, 1], [-1, -1], [1, -1]]
    control = [[4 / 3, 0], [4 / 3, 4 / 3], [0, 4 / 3], [0, 4 / 3], [-4 / 3, 4 / 3], [-4 / 3, 0],
               [-4 / 3, 0], [-4 / 3, -4 / 3], [0, -4 / 3], [0, -4 / 3], [4 / 3, -4 / 3], [4 / 3, 0]]
    measures = {"interpolation": 1e-16, "curvature_maximum": 2e-16, "tangent_angle": 0,
                "curvature_jump": 1e-15, "inflections": 0, "sharpest": 3.1}
    curve["tables"] = {
        "kappa": [{"curve": "square", "points": square, "control": control, "curve_points": control,
                   "curvature": [[u / 4, 1.0 + (u % 4) / 8] for u in range(17)], "point_params": [0.5, 1.5, 2.5, 3.5],
                   "iterations": 2, "converged": True, "error_estimate": 3e-16, "contraction": 2e-15,
                   "residuals": [0.17, 3e-16], "measures": measures}],
        "kappa_hard_cases": [{"family": "spike", "case": "1 deg", "points": 4, "iterations": 163, "converged": True,
                              "outcome": "converged", "residual": 9e-15, "error_estimate": 5e-14, "contraction": 0.82,
                              "measures": measures},
                             {"family": "spike, close back point", "case": "0.6 deg", "points": 4, "iterations": 5000,
                              "converged": False, "outcome": "not converged", "residual": 2e-8, "error_estimate": None,
                              "contraction": 1.0, "measures": measures}]}
    (tmp_path / "results.json").write_text(json.dumps(results))
    make_report.main(str(tmp_path))
    md = (tmp_path / "report.md").read_text()
    table = [t for t in tables_of(md) if t[0][:2] == [" curve ", " points "]]
    assert table and table[0][2][2].strip() == "2", tables_of(md)
    hard = [t for t in tables_of(md) if t[0][:2] == [" family ", " case "]]
    assert [row[3].strip() for row in hard[0][2:]] == ["converged", "not converged"]
    assert hard[0][3][5].strip() == "-"  # no estimate: the moves did not shrink
    for name in ("kappa_curve_0_0.png", "kappa_convergence_0.png"):
        assert (tmp_path / "figures" / name).stat().st_size > 1000


def test_vertex_age_gets_its_table_and_coloured_meshes(tmp_path):
    results = results_fixture()
    tetra = {"positions": [[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1], [1, 0, 0], [0, 1, 0]],
             "faces": [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]}
    rows = [{"scheme": "loop", "input": "tetrahedron", "levels": 1, "vertex_counts": [4, 6], "born": [4, 2],
             "expected": [4, 2], "mesh": tetra, "ages": [0, 0, 0, 0, 1, 1]},
            {"scheme": "doo-sabin", "input": "tetrahedron", "levels": 1, "vertex_counts": [4, 12], "born": [0, 12],
             "expected": [0, 12]}]
    results["cases"].append({"input": "catalog", "operation": "vertex-age", "job": 4, "id": "catalog | vertex-age",
                             "subjects": [], "tables": {"vertex_age": rows}, "outcome": "agree", "runs": []})
    (tmp_path / "results.json").write_text(json.dumps(results))
    make_report.main(str(tmp_path))
    md = (tmp_path / "report.md").read_text()
    table = [t for t in tables_of(md) if t[0][:2] == [" scheme ", " input "] and len(t[0]) == 6]
    assert table and [row[4].strip() for row in table[0][2:]] == ["4 / 2", "0 / 12"], tables_of(md)
    assert (tmp_path / "figures" / "vertex_age.png").stat().st_size > 1000


def test_curvature_gets_its_tables_and_figures(tmp_path):
    results = results_fixture()
    tetra = {"positions": [[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]],
             "faces": [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]}
    conv = [{"surface": s, "estimator": e, "method": "m", "vertices": 10 * 4 ** k, "h": 0.5 / 2 ** k, "estimated": 10,
             "mean_max": 0.1 / 4 ** k, "mean_rms": 0.05 / 4 ** k, "gauss_max": 0.2 / 4 ** k, "gauss_rms": 0.1 / 4 ** k,
             "direction_max": 0.01 / 4 ** k} for s in ("sphere", "torus") for e in ("core", "cgal") for k in range(3)]
    gb = [{"mesh": "tetrahedron", "vertices": 4, "faces": 4, "boundary_vertices": 0, "chi": 2,
           "total_defect": 12.566370614359172, "error": 1.8e-15, "bound": 6.7e-14},
          {"mesh": "edgecase:fin", "refused": "edge 0-1 in three faces"}]
    growth = [{"valence": 7, "lambda": 0.53, "nu": 0.32, "predicted_ratio": 1.284, "gaussian": [-0.5, -0.6, -0.77],
               "mean": [1, 1, 1], "ratio": [1.2, 1.28]}]
    figure = [{"surface": "tetra", "mesh": tetra, "gaussian": [1, -1, 2, 0.5], "estimated": [1, 1, 1, 0]},
              {"surface": "tetra again", "mesh": tetra, "gaussian": [0, 0, 0, 0], "estimated": [0, 0, 0, 0]}]
    results["cases"].append({"input": "catalog", "operation": "curvature", "job": 5, "id": "catalog | curvature",
                             "subjects": ["sphere", "torus"], "outcome": "agree", "runs": [],
                             "tables": {"curvature_convergence": conv, "gauss_bonnet": gb,
                                        "loop_curvature_growth": growth, "curvature_figure": figure}})
    (tmp_path / "results.json").write_text(json.dumps(results))
    make_report.main(str(tmp_path))
    md = (tmp_path / "report.md").read_text()
    assert "on 1 manifold meshes; 1 meshes are refused" in md
    refused = [t for t in tables_of(md) if t[0] == [" refused mesh ", " why "]]
    assert refused and refused[0][2][1].strip() == "edge 0-1 in three faces", tables_of(md)
    growth_table = [t for t in tables_of(md) if t[0][:2] == [" valence ", " lambda "]]
    assert growth_table and growth_table[0][2][4].strip() == "1.28", tables_of(md)
    conv_table = [t for t in tables_of(md) if t[0][:2] == [" surface ", " estimator "]]
    assert conv_table and len(conv_table[0]) == 2 + 12
    for name in ("curvature_convergence.png", "curvature_mesh.png", "loop_curvature_growth.png"):
        assert (tmp_path / "figures" / name).stat().st_size > 1000


def test_isosurface_gets_its_tables_and_figures(tmp_path):
    results = results_fixture()
    tetra = {"positions": [[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]],
             "faces": [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]}
    open_tetra = {"positions": tetra["positions"], "faces": tetra["faces"][:3]}
    conv = [dict({"surface": s, "description": s, "resolution": 17 * 2 ** k, "h": 0.2 / 2 ** k, "grid": [17, 17, 9],
                  "max_distance": 0.01 / 4 ** k, "rms_distance": 0.005 / 4 ** k, "ambiguous_faces": 0,
                  "centred_polygons": 0, "vertices": 100, "faces": 196, "boundary_edges": 0, "boundary_loops": 0,
                  "mesh_errors": 0, "euler": 2, "volume": 4.1},
                 **({"expected_euler": 2, "exact_volume": 4.18, "volume_error": 0.02 / 4 ** k} if s == "sphere" else {}))
            for s in ("sphere", "gyroid") for k in range(3)]
    facts = {"boundary_edges": 0, "mesh_errors": 0, "euler": -28, "ambiguous_faces": 40}
    amb = [{"samples": 9, "decider": facts, "minority": dict(facts, boundary_edges=176, euler=-32),
            "skimage_lewiner": dict(facts, euler=-34), "skimage_lorensen": {"failed": "unavailable: no skimage"}}]
    ref = [{"subject": "sphere res 33", "status": "ok", "agreement": "triangulation", "max_vertex_distance": 7.5e-8,
            "tolerance": 5.5e-7, "faces_only_ours": 3051, "faces_only_theirs": 3051, "ours": {"euler": 2},
            "theirs": {"euler": 2}},
           {"subject": "torus res 33", "status": "unavailable", "explanation": "unavailable: no skimage"}]
    figure = [{"title": "closed", "mesh": tetra}, {"title": "with a hole", "mesh": open_tetra}]
    results["cases"].append({"input": "catalog", "operation": "isosurface", "job": 6, "id": "catalog | isosurface",
                             "subjects": ["sphere", "gyroid"], "outcome": "agree", "runs": [],
                             "tables": {"isosurface_convergence": conv, "isosurface_ambiguity": amb,
                                        "isosurface_reference": ref, "isosurface_figure": figure}})
    (tmp_path / "results.json").write_text(json.dumps(results))
    make_report.main(str(tmp_path))
    md = (tmp_path / "report.md").read_text()
    conv_table = [t for t in tables_of(md) if t[0][:2] == [" surface ", " samples "]]
    assert conv_table and len(conv_table[0]) == 2 + 6
    assert conv_table[0][2][6].strip() == "2 (2)" and conv_table[0][5][6].strip() == "2", conv_table
    amb_table = [t for t in tables_of(md) if t[0][:2] == [" samples ", " ambiguous faces "]]
    assert amb_table and amb_table[0][2][3].strip() == "176 / 0 / -32"
    assert amb_table[0][2][5].strip() == "failed: unavailable: no skimage"
    ref_table = [t for t in tables_of(md) if t[0][:2] == [" samples ", " status "]]
    assert ref_table and ref_table[0][3][6].strip() == "unavailable: no skimage", ref_table
    for name in ("isosurface_convergence.png", "isosurface_meshes.png"):
        assert (tmp_path / "figures" / name).stat().st_size > 1000


def test_fitting_gets_its_tables_and_figures(tmp_path):
    results = results_fixture()
    tetra = {"positions": [[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]],
             "faces": [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]}
    recovery = [{"mesh": "tetrahedron", "scheme": "loop", "vertices": 4, "samples": 34, "error": 6.4e-17,
                 "predicted_singular": False},
                {"mesh": "quad-cube", "scheme": "catmull-clark", "vertices": 8, "samples": 98,
                 "singular": "fitting: the least-squares system is singular", "predicted_singular": True}]

    def steps(h0):
        return [{"energy": 1.0 / (k + 1), "rms_sample_to_target": 0.01, "max_sample_to_target": 0.02,
                 "rms_target_to_surface": 0.01 / (k + 1), "max_target_to_surface": 0.03, "hausdorff": h0 / (k + 1)}
                for k in range(4)]
    iterations = [{"target": "bunny", "scheme": s, "edge_budget": b, "target_vertices": 2503, "control_vertices": v,
                   "control_faces": 2 * v, "samples": 16 * v, "steps": steps(0.05 if b == 300 else 0.02),
                   "hausdorff_rises": 0} for s in ("loop", "catmull-clark") for b, v in ((300, 102), (1200, 407))]
    iterations.append({"target": "oblong", "edge_budget": 1200, "error": "cgal's simplification changed the topology"})
    figure = [{"title": "target", "mesh": tetra}, {"title": "control", "mesh": tetra, "wire": True}]
    results["cases"].append({"input": "catalog", "operation": "fitting", "job": 7, "id": "catalog | fitting",
                             "subjects": ["catalog", "bunny"], "outcome": "agree", "runs": [],
                             "tables": {"fitting_recovery": recovery, "fitting_iterations": iterations,
                                        "fitting_figure": figure}})
    (tmp_path / "results.json").write_text(json.dumps(results))
    make_report.main(str(tmp_path))
    md = (tmp_path / "report.md").read_text()
    assert "Recovered on 1 mesh x scheme pairs" in md and "quad-cube (catmull-clark, predicted: yes)" in md
    table = [t for t in tables_of(md) if t[0][:2] == [" target ", " scheme "]]
    assert table and len(table[0]) == 2 + 4
    assert table[0][2][4].strip() == "0.05" and table[0][2][5].strip() == "0.0125", table
    failed = [t for t in tables_of(md) if t[0][:2] == [" target ", " edge budget "]]
    assert failed and failed[0][2][2].strip() == "cgal's simplification changed the topology"
    for name in ("fitting_convergence.png", "fitting_meshes.png"):
        assert (tmp_path / "figures" / name).stat().st_size > 1000


def test_multiresolution_gets_its_table_and_figure(tmp_path):
    results = results_fixture()
    tetra = {"positions": [[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]],
             "faces": [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]}
    rows = [{"mesh": "torus", "levels": 3, "base_vertices": 96, "finest_vertices": 6144, "round_trip": 1.8e-18,
             "rigid_motion": 7.3e-16, "detail_rms": [5.7e-4, 3e-5, 1.9e-6], "moved": 1379, "reach": 1387, "support": 631,
             "outside_reach": 0, "smooth_moved": 631, "smooth_mismatch": 0},
            {"mesh": "pole-64", "levels": 3, "base_vertices": 65, "error": "multiresolution: vertex 3 has no normal"}]
    figure = [{"title": "before", "mesh": tetra}, {"title": "after", "mesh": tetra}]
    results["cases"].append({"input": "catalog", "operation": "multiresolution", "job": 8, "id": "catalog | multiresolution",
                             "subjects": ["torus", "pole-64"], "outcome": "agree", "runs": [],
                             "tables": {"multiresolution": rows, "multiresolution_figure": figure}})
    (tmp_path / "results.json").write_text(json.dumps(results))
    make_report.main(str(tmp_path))
    md = (tmp_path / "report.md").read_text()
    table = [t for t in tables_of(md) if t[0][:2] == [" mesh ", " finest V "]]
    assert table and len(table[0]) == 3 and table[0][2][4].strip() == "1379" and table[0][2][6].strip() == "631", table
    failed = [t for t in tables_of(md) if t[0][:2] == [" mesh ", " not decomposed "]]
    assert failed and failed[0][2][1].strip() == "multiresolution: vertex 3 has no normal"
    assert (tmp_path / "figures" / "multiresolution.png").stat().st_size > 1000


def test_a_view_file_reads_back_and_names_the_first_level_where_surfaces_part(tmp_path):
    import base64
    import struct
    from report.viewer import first_parting_level, read_view
    b64 = lambda code, values: base64.b64encode(struct.pack("<%d%s" % (len(values), code), *values)).decode()  # noqa: E731
    triangle = [0, 0, 0, 1, 0, 0, 0, 1, 0]
    nan = float("nan")
    data = {"job": 0, "subject": "core",
            "levels": [{"positions": b64("d", triangle), "triangles": b64("i", [0, 1, 2])},
                       {"positions": b64("d", triangle), "triangles": b64("i", [0, 1, 2]), "origins": b64("i", [0, -1] * 3)},
                       {"positions": b64("d", triangle), "triangles": b64("i", [0, 1, 2]), "origins": b64("i", [0, -1] * 3)}],
            # Level 1 parts by 1e-14 of the diagonal sqrt(2), level 2 by 0.5 (and one vertex unmatched).
            "references": {"ref": [None, b64("f", [0, 0, 1e-14, 0, 0, 0, 0, 0, 0]), b64("f", [0, 0, 0.5, 0, 0, 0, nan, nan, nan])]}}
    (tmp_path / "views").mkdir()
    (tmp_path / "views" / "job0.js").write_text("crossdivView(" + json.dumps(data) + ");\n")
    view = read_view(str(tmp_path), "views/job0.js")
    assert view["levels"][1]["positions"] == [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    assert view["levels"][2]["triangles"] == [(0, 1, 2)]
    assert view["references"]["ref"][0] is None
    level, distance = first_parting_level(view, "ref", 1e-12)
    assert level == 2 and distance[0] == 0.5 and distance[1] == 0 and math.isnan(distance[2])
    assert first_parting_level(view, "ref", 1e-16)[0] == 1  # 1e-14 > 1e-16 * sqrt(2)
    assert first_parting_level(view, "other", 1e-12) is None
    (tmp_path / "views" / "bad.js").write_text("alert(1);")
    with pytest.raises(ValueError, match="not a crossdiv view file"):
        read_view(str(tmp_path), "views/bad.js")


def test_invariance_gets_its_table_and_a_representative_per_finding(tmp_path):
    results = results_fixture()
    results["operations"].append({"name": "invariance", "kind": "invariance"})

    def run(impl, transformation, verdict, cls="", bit_identical=True, measured=0.0):
        outcome = verdict if not cls else f"{verdict} ({cls})"
        return {"reference": "the input as written", "subject": impl, "check": transformation, "measured": measured,
                "tolerance": 1e-12, "unit": "rel", "verdict": verdict, "divergence_class": cls, "outcome": outcome,
                "bit_identical": bit_identical, "explanation": f"{impl} {transformation}"}

    minimal = {"mesh": "invariance/job5-cgal-reverse-faces.obj", "faces": 2, "tests": 3,
               "transformation": "reverse-faces", "explanation": "0.155 of the diagonal",
               "reproduce": "crossdiv invariance invariance/job5-cgal-reverse-faces.obj --scheme loop --levels 2 "
                            "--impl cgal --transform reverse-faces --seed 1"}
    case = {"input": "edgecase:bowtie", "operation": "invariance", "job": 5, "scheme": "loop", "input_faces": 2,
            "id": "edgecase:bowtie | invariance loop", "transformations": ["reverse-faces", "relabel-vertices"],
            "view": "views/job5.js", "view_reference": "cgal under reverse-faces", "view_worst_vertex": 0,
            "implementations": [{"name": "core", "under_test": True, "invariant": True},
                                {"name": "cgal", "under_test": False, "invariant": False, "minimal": minimal}],
            "runs": [run("core", "reverse-faces", "agree", bit_identical=False, measured=1e-17),
                     run("core", "relabel-vertices", "agree"),
                     run("cgal", "reverse-faces", "diverge", "non-manifold-handling", False, 0.155),
                     run("cgal", "relabel-vertices", "not-compared")]}
    results["cases"].append(case)
    (tmp_path / "results.json").write_text(json.dumps(results))
    make_report.main(str(tmp_path))
    md = (tmp_path / "report.md").read_text()
    assert "## Invariance" in md
    [table] = [t for t in tables_of(md) if [h.strip() for h in t[0]][:3] == ["scheme", "implementation", "reverse-faces"]]
    rows = {row[1].strip(): [c.strip() for c in row] for row in table[2:]}
    # Invariant of compared, how many only within the tolerance (weak tier, not strict), findings by class.
    assert rows["core"][2:] == ["1 of 1 (1 not bit for bit)", "1 of 1"]
    assert rows["cgal"][2:] == ["0 of 1; 1 diverge (non-manifold-handling)", "0 of 0 (+1 n/c)"]
    [reps] = [t for t in tables_of(md) if [h.strip() for h in t[0]][:3] == ["scheme", "implementation", "transformation"]]
    [rep] = reps[2:]
    assert [c.strip() for c in rep][:8] == ["loop", "cgal", "reverse-faces", "diverge (non-manifold-handling)", "1",
                                           "edgecase:bowtie", "0.155", "2 faces"]
    assert "--transform reverse-faces" in rep[8]
    html = (tmp_path / "index.html").read_text()
    assert "href='invariance/job5-cgal-reverse-faces.obj'" in html
    # The catalogue lists the finding among the runs that are not agreement.
    assert "cgal reverse-faces" in html
    # The representative opens the case's view: CGAL's levels against its run on the faces reversed.
    assert "<a href='#crossdiv-viewer' data-view='0'>edgecase:bowtie</a>" in html
    assert '"reference": "cgal under reverse-faces"' in html
    assert '"runs": [{"reference": "cgal under reverse-faces", "check": "", "outcome": "diverge (non-manifold-handling)"' in html


def test_the_timing_section_shows_core_loops_own_goals(tmp_path):
    record = {"impl": "core", "scheme": "loop", "input": "torus-20000", "levels": 2, "memory": "warm",
              "input_faces": 20000, "output_faces": 320000, "median_ms": 6.0, "peak_rss_mb": 26}
    goals = [{"goal": "floor", "scheme": "loop", "input": "torus-20000", "levels": 2, "output_faces": 320000,
              "core_ms": 6.0, "base_ms": 0.96, "ratio": 6.25, "target_ratio": 1.5, "met": False},
             {"goal": "cold over warm", "scheme": "loop", "input": "torus-20000", "levels": 2, "output_faces": 320000,
              "core_ms": 11.0, "base_ms": 6.0, "ratio": 11.0 / 6.0, "target_ratio": 2.0, "met": True}]
    section = timing_section({"repeats": 5, "records": [record], "core_goals": goals}, str(tmp_path))
    table = section.blocks[-1]
    assert [list(r) for r in table.rows] == [
        ["floor", "loop", "torus-20000", 2, 320000, "6.00", "0.96", "6.25", "1.5", "NOT met"],
        ["cold over warm", "loop", "torus-20000", 2, 320000, "11.00", "6.00", "1.83", "2.0", "met"]]
    assert "at most 1.5x the floor" in section.blocks[-2].text
