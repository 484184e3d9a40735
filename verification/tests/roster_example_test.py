#!/usr/bin/env python3
"""The roster example as a teacher runs it: `crossdiv suite examples/roster/roster.suite`, then
every row of the class table checked against the fault planted in that submission
(examples/roster/expected.tsv) in roster.csv, results.json and the report's roster.html, and
junit.xml checked to hold one test suite per subject whose failures match the verdict; every
failing submission's minimal failing input (its first failing case shrunk by the suite) is
linked from each and, run again, still fails; a hanging one is named as not shrunk.

    roster_example_test.py path/to/crossdiv [SUITE EXPECTED]

With SUITE and EXPECTED (examples/roster/tasks/: the course tasks' roster), rows are keyed
SUBJECT/TASK and a failing row's minimal input is the note that tasks are not shrunk."""
import csv
import json
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


TASKS = ("tessellate", "casteljau", "patch", "sweep", "vertex-normals", "flip-split")


def minimal_problems(crossdiv, out, subject, verdict, failures, record, row, page, junit, input_faces):
    """The row's minimal failing input: none for a passing subject; a note for a hanging one;
    otherwise a mesh smaller than the case's input, linked from roster.csv, roster.html and the
    JUnit failure, on which the subject still fails (exit 1, no named rule or a failed run)."""
    minimal = record.get("minimal")
    if verdict != "fail":
        return [] if minimal is None else [f"{subject}: a {verdict} has a minimal failing input {minimal}"]
    if minimal is None:
        return [f"{subject}: fails but has no minimal failing input"]
    if record["scheme"] in TASKS:
        return [] if minimal["note"].startswith("not shrunk: shrinking takes") else [f"{subject}: a task's minimal is {minimal}"]
    if "timeout" in failures:
        return [] if minimal["note"].startswith("not shrunk: it hangs") else [f"{subject}: hangs, minimal is {minimal}"]
    mesh = minimal["mesh"]
    problems = []
    if row["minimal_input"] != mesh or f"href='{mesh}'" not in page:
        problems.append(f"{subject}: {mesh} not linked from roster.csv ({row['minimal_input']!r}) and roster.html")
    if junit is None or not any(mesh in (f.text or "") for f in junit.iter("failure")):
        problems.append(f"{subject}: no JUnit failure names {mesh}")
    if not 0 < minimal["faces"] < input_faces[record["failing_case"]]:
        problems.append(f"{subject}: minimal input of {minimal['faces']} faces, its case's input "
                        f"{input_faces[record['failing_case']]}")
    command = f"python3 {ROOT}/examples/roster/submissions/{subject}/subdivide.py {{in}} {{levels}} {{out}}"
    again = subprocess.run([crossdiv, "compare", os.path.join(out, mesh), "--scheme", record["scheme"], "--levels", "2",
                            "--subject-name", subject, "--subject", command], capture_output=True, text=True)
    last = (again.stdout.strip().splitlines() or [""])[-1]
    if again.returncode != 1 or not re.search(r"failed on|no named rule", last):
        problems.append(f"{subject}: on its minimal input exit {again.returncode}: {last!r}")
    return problems


def main():
    crossdiv = sys.argv[1]
    suite = sys.argv[2] if len(sys.argv) > 3 else os.path.join(ROOT, "examples", "roster", "roster.suite")
    expected_file = sys.argv[3] if len(sys.argv) > 3 else os.path.join(ROOT, "examples", "roster", "expected.tsv")
    expected = {}
    with open(expected_file) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            subject, verdict, failures, pattern = line.rstrip("\n").split("\t")
            expected[subject] = (verdict, failures, pattern)
    problems = []
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run([crossdiv, "suite", suite, "--out", out], capture_output=True, text=True)
        if run.returncode != 1:  # submissions fail: the suite says so
            problems.append(f"crossdiv suite exited {run.returncode}, want 1: {run.stderr[-2000:]}")
        by_task = any("/" in k for k in expected)  # a task roster: one row per student and task
        key = (lambda r: f"{r['subject']}/{r['scheme']}") if by_task else (lambda r: r["subject"])
        with open(os.path.join(out, "roster.csv")) as f:
            rows = {key(r): r for r in csv.DictReader(f)}
        with open(os.path.join(out, "results.json")) as f:
            results = json.load(f)
        table = {key(r): r for r in results["roster"]}
        input_faces = {c["id"]: c.get("input_faces", 0) for c in results["cases"]}
        failing = {k.split("/")[0] for k, (verdict, _, _) in expected.items() if verdict == "fail"}
        page = open(os.path.join(out, "roster.html")).read()
        suites = {s.get("name"): s for s in ET.parse(os.path.join(out, "junit.xml")).getroot().iter("testsuite")}
        if set(rows) != set(expected):
            problems.append(f"roster.csv has {sorted(rows)}, want {sorted(expected)}")
        for subject, (verdict, failures, pattern) in expected.items():
            row, record = rows.get(subject), table.get(subject)
            if row is None or record is None:
                problems.append(f"{subject}: missing from roster.csv or results.json")
                continue
            got_failures = row["failures"] or "-"
            if row["verdict"] != verdict or got_failures != failures or not re.search(pattern, row["diagnosis"]):
                problems.append(f"{subject}: {row['verdict']} / {got_failures} / {row['diagnosis']!r}; "
                                f"want {verdict} / {failures} / /{pattern}/")
            if record["verdict"] != row["verdict"] or record["diagnosis"] != row["diagnosis"]:
                problems.append(f"{subject}: results.json says {record['verdict']}: {record['diagnosis']!r}")
            student = record["subject"]
            if f"data-subject='{student}'" not in page:
                problems.append(f"{subject}: no row in roster.html")
            junit = suites.get(f"{results['suite']}/{student}")
            if junit is None:
                problems.append(f"{subject}: no test suite {results['suite']}/{student} in junit.xml")
            elif (int(junit.get("failures")) > 0) != (student in failing):
                problems.append(f"{subject}: junit.xml reports {junit.get('failures')} failure(s) for a {verdict}")
            problems += minimal_problems(crossdiv, out, subject, verdict, failures, record, row, page, junit, input_faces)
    for p in problems:
        print("FAIL " + p)
    print(f"{len(expected)} rows of the class table, {len(problems)} problem(s)")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
