#!/usr/bin/env python3
"""Mutation testing of core: does the default suite catch each realistic bug of the catalogue?

For each mutant of verification/mutation/catalogue.json, in a copy of this tree (tracked files
as they are now, uncommitted edits included) with its own Release build:
  1. apply the edit (its 'find' text must occur exactly once in its file: a stale entry is an
     error, never silently skipped),
  2. rebuild crossdiv incrementally,
  3. run the default suite's cases of the mutant's operations (the manifest's other statements
     kept), and call the mutant caught when the suite fails (exit 1), naming the failed checks,
  4. for a survivor, run the unit tests too (ctest), to tell "no test catches it" from "only a
     unit test does",
  5. restore the file.
The suite is first run unmutated over every operation the chosen mutants use: a failure there
makes every verdict meaningless, and the run stops.

    verification/mutation/run_mutants.py [--work DIR] [--only ID,...] [--jobs N] [--no-unit-tests]
                                         [--results FILE.json] [--markdown FILE.md]

Writes the results (JSON, and a Markdown table for reports/mutation.md) and prints one line per
mutant. Exit status: 0 when every mutant was caught by the suite, 1 when some survived, 2 on an
error (a stale catalogue entry, a build that fails unmutated, a failing baseline).
Not run in CI: it rebuilds once per mutant (about 1 to 4 minutes each on 2 cores).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CATALOGUE = os.path.join(SOURCE, "verification", "mutation", "catalogue.json")
DEFAULT_SUITE = os.path.join("verification", "suites", "default.suite")
SUITE_TIMEOUT = 3600  # seconds: a mutant that makes core hang is caught by the clock


class Failure(Exception):
    """An error that makes the run's verdicts meaningless."""


def run(argv, cwd, timeout=None, log=None):
    """Runs an argument vector (no shell); returns (exit status, seconds). Output goes to `log`."""
    start = time.monotonic()
    with open(log or os.devnull, "w") as out:
        try:
            status = subprocess.run(argv, cwd=cwd, stdout=out, stderr=subprocess.STDOUT, timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            status = None
    return status, time.monotonic() - start


def copy_tree(work):
    """The tracked files of SOURCE into `work`, as they are on disk. Files that did not change
    keep their time stamps there, so the build stays incremental between runs; a copied file is
    stamped now (not with its time in SOURCE), so that a file an interrupted run left mutated,
    and built, is rebuilt restored."""
    listed = subprocess.run(["git", "-C", SOURCE, "ls-files", "-z"], check=True, capture_output=True).stdout
    for name in filter(None, listed.decode().split("\0")):
        src, dst = os.path.join(SOURCE, name), os.path.join(work, name)
        if not os.path.isfile(src):
            continue  # deleted in the working tree
        if os.path.isfile(dst) and open(src, "rb").read() == open(dst, "rb").read():
            continue
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        shutil.copyfile(src, dst)
        shutil.copymode(src, dst)


def build(work, targets, log):
    build_dir = os.path.join(work, "build")
    if not os.path.isfile(os.path.join(build_dir, "CMakeCache.txt")):
        status, _ = run(["cmake", "-S", work, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release"], work, log=log)
        if status != 0:
            return False
    status, _ = run(["cmake", "--build", build_dir, "-j2", "--target", *targets], work, log=log)
    return status == 0


def suite_for(operations, work, path, dropped=()):
    """The default suite with only the case lines of `operations` (the third word of a case line),
    without the `reference` statements of `dropped` and the cases only they run."""
    kept = []
    for line in open(os.path.join(work, DEFAULT_SUITE)):
        words = line.split()
        if words and words[0] == "case" and (len(words) < 3 or words[2] not in operations):
            continue
        if words and words[0] == "reference" and len(words) > 1 and words[1] in dropped:
            continue
        if words and words[0] == "case" and any(w.startswith("against=") and w[len("against="):] in dropped for w in words):
            continue
        kept.append(line)
    with open(path, "w") as f:
        f.writelines(kept)
    return sum(1 for line in kept if line.startswith("case"))


def failed_checks(results_path, limit=3):
    """The first failures of a suite's results.json, as 'case: reference check (outcome)'."""
    try:
        results = json.load(open(results_path))
    except (OSError, ValueError):
        return ["no results.json (the suite stopped before writing it)"]
    found = []
    for case in results.get("cases", []):
        runs = case.get("runs") or [case]
        for r in runs:
            outcome = r.get("outcome", "")
            if outcome in ("diverge (unexplained)", "ours-rejected (unexplained)", "ours-failed"):
                what = " ".join(x for x in (r.get("reference", ""), r.get("check", "")) if x)
                found.append(f"{case.get('id', '?')}: {what} ({outcome})")
    return found[:limit] + ([f"... {len(found) - limit} more"] if len(found) > limit else [])


def run_suite(work, operations, out, jobs, dropped=()):
    manifest = os.path.join(out, "mutant.suite")
    os.makedirs(out, exist_ok=True)
    cases = suite_for(operations, work, manifest, dropped)
    crossdiv = os.path.join(work, "build", "verification", "crossdiv")
    status, seconds = run([crossdiv, "suite", manifest, "--out", os.path.join(out, "suite"), "--no-report", "--jobs", str(jobs)],
                          work, timeout=SUITE_TIMEOUT, log=os.path.join(out, "suite.log"))
    return status, seconds, cases


def write_results(rows, planned, minutes, args):
    """results JSON and the Markdown table; written after every mutant, so that an interrupted run
    keeps what it measured."""
    caught = sum(r["verdict"] == "caught" for r in rows)
    survived = [r for r in rows if r["verdict"] == "survived"]
    summary = {"mutants": len(rows), "planned": planned, "caught": caught, "survived": len(survived),
               "not_building": sum(r["verdict"] == "does-not-build" for r in rows), "minutes": round(minutes, 1),
               "dropped_references": args.drop_reference}
    json.dump({"summary": summary, "mutants": rows}, open(args.results, "w"), indent=1)
    with open(args.markdown, "w") as f:
        f.write("# Mutation testing of core\n\n")
        f.write("Written by `verification/mutation/run_mutants.py` from `verification/mutation/catalogue.json`: each\n"
                "mutant applied alone to a copy of the tree, crossdiv rebuilt, and the default suite's cases of its\n"
                "operations run; caught when the suite fails. Survivors are also run against the unit tests.\n\n")
        f.write(f"Last run: {len(rows)} of {planned} mutants ({'complete' if len(rows) == planned else 'interrupted'}), "
                f"{caught} caught by the suite, {len(survived)} survived, {summary['not_building']} not building; "
                f"{summary['minutes']} minutes on this machine"
                + (f" (first without {', '.join(args.drop_reference)}; survivors again with the whole suite)" if args.drop_reference else "")
                + ".\n\n")
        f.write("| mutant | file | what it breaks | suite | caught by (first failures) |\n| --- | --- | --- | --- | --- |\n")
        for r in rows:
            verdict = r["verdict"] + (f" (unit tests: {r['unit_tests']})" if "unit_tests" in r else "")
            by = "; ".join(r["caught_by"]).replace("|", "\\|")
            f.write(f"| {r['id']} | {r['file']} | {r['why']} | {verdict} | {by} |\n")
    return caught, survived, summary


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--work", default=os.path.join(tempfile.gettempdir(), "crossdiv-mutation"),
                        help="the copy of the tree and its build (kept between runs)")
    parser.add_argument("--only", default="", help="comma-separated mutant ids, run in that order (default: all)")
    parser.add_argument("--jobs", type=int, default=2, help="suite worker processes")
    parser.add_argument("--no-unit-tests", action="store_true", help="do not run ctest for survivors")
    parser.add_argument("--drop-reference", action="append", default=[], metavar="NAME",
                        help="leave out a slow external reference (meshlab: about 3 minutes of every Loop run) at first; "
                             "a mutant that survives without it is run again with the whole suite before it is called a survivor")
    parser.add_argument("--results", default=os.path.join(SOURCE, "reports", "mutation-results.json"))
    parser.add_argument("--markdown", default=os.path.join(SOURCE, "reports", "mutation.md"))
    args = parser.parse_args()

    catalogue = json.load(open(CATALOGUE))["mutants"]
    if args.only:
        wanted = args.only.split(",")
        unknown = [w for w in wanted if w not in {m["id"] for m in catalogue}]
        if unknown:
            print(f"unknown mutant id(s): {', '.join(unknown)}", file=sys.stderr)
            return 2
        by_id = {m["id"]: m for m in catalogue}
        catalogue = [by_id[w] for w in wanted]  # in the order given
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    logs = os.path.join(work, "mutation-logs")
    os.makedirs(logs, exist_ok=True)
    started = time.monotonic()
    try:
        copy_tree(work)
        for m in catalogue:
            count = open(os.path.join(work, m["file"])).read().count(m["find"])
            if count != 1:
                raise Failure(f"{m['id']}: its text occurs {count} times in {m['file']} (the catalogue is stale)")
        if not build(work, ["crossdiv"], os.path.join(logs, "baseline-build.log")):
            raise Failure(f"the unmutated tree does not build (see {logs}/baseline-build.log)")
        operations = sorted({op for m in catalogue for op in m["operations"]})
        status, seconds, cases = run_suite(work, operations, os.path.join(logs, "baseline"), args.jobs, args.drop_reference)
        if status != 0:
            raise Failure(f"the unmutated suite fails on {', '.join(operations)} (exit {status}): "
                          + "; ".join(failed_checks(os.path.join(logs, "baseline", "suite", "results.json"))))
        print(f"baseline: {cases} case lines of {', '.join(operations)} pass ({seconds:.0f} s)", flush=True)
    except Failure as e:
        print(f"error: {e}", file=sys.stderr)
        return 2

    rows = []
    for m in catalogue:
        path = os.path.join(work, m["file"])
        original = open(path).read()
        with open(path, "w") as f:
            f.write(original.replace(m["find"], m["replace"], 1))
        out = os.path.join(logs, m["id"])
        shutil.rmtree(out, ignore_errors=True)
        os.makedirs(out)
        row = {"id": m["id"], "file": m["file"], "operations": m["operations"], "why": m["why"]}
        t0 = time.monotonic()
        try:
            if not build(work, ["crossdiv"], os.path.join(out, "build.log")):
                row.update(verdict="does-not-build", caught_by=[])
            else:
                status, seconds, cases = run_suite(work, m["operations"], out, args.jobs, args.drop_reference)
                if status == 0 and args.drop_reference:  # survived the reduced suite: the whole one decides
                    status, more, cases = run_suite(work, m["operations"], out, args.jobs)
                    seconds += more
                row["suite_seconds"] = round(seconds, 1)
                if status is None:
                    row.update(verdict="caught", caught_by=[f"the suite did not finish in {SUITE_TIMEOUT} s (core hangs)"])
                elif status == 1:
                    row.update(verdict="caught", caught_by=failed_checks(os.path.join(out, "suite", "results.json")))
                elif status == 0:
                    row.update(verdict="survived", caught_by=[])
                else:
                    row.update(verdict="caught", caught_by=[f"the suite stopped with exit status {status} (see {out}/suite.log)"])
                if row["verdict"] == "survived" and not args.no_unit_tests:
                    ok = build(work, ["all"], os.path.join(out, "build-tests.log"))
                    status, _ = run(["ctest", "-j2", "--output-on-failure"], os.path.join(work, "build"), log=os.path.join(out, "ctest.log"))
                    row["unit_tests"] = "fail" if not ok or status != 0 else "pass"
        finally:
            with open(path, "w") as f:
                f.write(original)
        row["seconds"] = round(time.monotonic() - t0, 1)
        rows.append(row)
        print(f"{m['id']:40} {row['verdict']:15} {row['seconds']:7.0f} s  {(row['caught_by'] or [''])[0]}", flush=True)
        write_results(rows, len(catalogue), (time.monotonic() - started) / 60, args)

    caught, survived, summary = write_results(rows, len(catalogue), (time.monotonic() - started) / 60, args)
    total_minutes = summary["minutes"]
    print(f"{caught} of {len(rows)} caught by the suite; {len(survived)} survived"
          + (f": {', '.join(r['id'] for r in survived)}" if survived else "") + f" ({total_minutes:.0f} min)")
    return 0 if not survived and summary["not_building"] == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
