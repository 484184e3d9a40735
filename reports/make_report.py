#!/usr/bin/python3
"""Render a crossdiv suite folder into report.md, index.html and figures/*.png.

Usage: make_report.py DIR
Reads DIR/results.json (crossdiv suite / merge; schema in reports/results-schema.md) and,
when present, DIR/bench.json (crossdiv bench). The report is one list of sections (report/
model.py) rendered twice, to Markdown and to HTML; figures are drawn with matplotlib.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from report import roster, sections, viewer  # noqa: E402
from report.invariance import invariance_cases, invariance_section  # noqa: E402
from report.model import render_html, render_markdown  # noqa: E402
from report.records import halfedge_cases, split_cases  # noqa: E402
from report.robustness import robustness_section  # noqa: E402
from report.suite_time import suite_time_section  # noqa: E402
from report.records import SCHEMA_VERSION, fmt  # noqa: E402


def load(folder):
    """results.json and bench.json (None when absent) of a suite folder."""
    with open(os.path.join(folder, "results.json")) as f:
        results = json.load(f)
    if results.get("schema_version") != SCHEMA_VERSION:
        sys.exit(f"{folder}/results.json has schema_version {results.get('schema_version')}; this report reads "
                 f"{SCHEMA_VERSION} (reports/results-schema.md): run the suite again with this build")
    bench = None
    if os.path.exists(os.path.join(folder, "bench.json")):
        with open(os.path.join(folder, "bench.json")) as f:
            bench = json.load(f)
    return results, bench


def build(results, bench, folder, figdir):
    """(title, intro lines, sections) of the report."""
    mesh, curves, surfaces, studies, schemes = split_cases(results)
    s = results["summary"]
    refs = ", ".join(f"{r['name']} ({r['version']})" for r in results.get("references", []))
    intro = [f"- manifest: `{results.get('manifest')}`, shard {results.get('shard')}, {s['cases']} cases, "
             f"{s['runs']} reference runs, {s['failures']} failure(s), {fmt(results.get('seconds'), '.1f')} s with "
             f"{results.get('workers', 1)} worker(s)",
             f"- references: {refs}"]
    before, after = sections.mesh_sections(results, mesh, folder, figdir)
    # With a roster, roster.html holds each subject's cases; the per-case table is for one subject.
    roster_table = roster.roster_section(results, folder)
    subject = None if roster_table else sections.subject_section(mesh)
    invariance = invariance_cases(results)
    viewed = mesh + schemes + invariance  # the cases the 3D viewer may show
    body = [viewer.first_screen(results["cases"], viewed, [r["name"] for r in results.get("references", [])], folder),
            sections.outcomes_section(s), robustness_section(results),
            *([roster_table] if roster_table else []), *([subject] if subject else []), *before,
            sections.catalogue_section(sections.catalogue_rows(mesh + schemes, curves + surfaces + studies +
                                                              halfedge_cases(results["cases"]) +
                                                              invariance)), *after,
            sections.curve_section(curves, bench, figdir), sections.surface_section(surfaces, bench, figdir),
            sections.schemes_section(schemes), invariance_section(invariance, viewer.view_index(viewed)),
            sections.halfedge_section(halfedge_cases(results["cases"])),
            sections.studies_section(studies, figdir), sections.timing_section(bench, figdir),
            suite_time_section(results)]
    return f"crossdiv conformance report: suite {results.get('suite')}", intro, [b for b in body if b is not None]


def main(folder):
    results, bench = load(folder)
    if not results["cases"]:
        sys.exit(f"{folder}/results.json holds no cases: nothing to report")
    figdir = os.path.join(folder, "figures")
    os.makedirs(figdir, exist_ok=True)
    title, intro, body = build(results, bench, folder, figdir)
    with open(os.path.join(folder, "report.md"), "w") as f:
        f.write(render_markdown(title, intro, body))
    with open(os.path.join(folder, "index.html"), "w") as f:
        f.write(render_html(title, intro, body))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: make_report.py DIR")
    main(sys.argv[1])
