"""Where a suite's time goes: per operation, the seconds of its jobs split into core's own work,
the references' own runs and the rest (reading inputs, starting and isolating processes,
correspondence, classification, writing views), measured per job by the worker
(results.json: job_seconds, core_seconds, each run's seconds)."""
from collections import defaultdict

from .model import Section, Table, Text
from .records import fmt


def _seconds(x):
    return x if isinstance(x, (int, float)) and x == x else 0.0


def suite_time_section(results):
    """The section, or None for results without job times (a suite of an older build)."""
    cases = [c for c in results.get("cases", []) if "job_seconds" in c]
    if not cases:
        return None
    per_op = defaultdict(lambda: {"jobs": 0, "job": 0.0, "core": 0.0, "refs": 0.0, "runs": 0})
    per_ref = defaultdict(lambda: {"runs": 0, "seconds": 0.0})
    for c in cases:
        op = per_op[c.get("operation", "?")]
        op["jobs"] += 1
        op["job"] += _seconds(c["job_seconds"])
        op["core"] += _seconds(c.get("core_seconds"))
        for r in c.get("runs", []):
            s = _seconds(r.get("seconds"))
            op["refs"] += s
            op["runs"] += 1
            ref = per_ref[r.get("reference", "?")]
            ref["runs"] += 1
            ref["seconds"] += s
    total = sum(o["job"] for o in per_op.values())
    other = sum(max(0.0, o["job"] - o["core"] - o["refs"]) for o in per_op.values())

    def share(x):
        return fmt(100.0 * x / total, ".0f") + "%" if total > 0 else "-"

    rows = []
    for name, o in sorted(per_op.items(), key=lambda kv: -kv[1]["job"]):
        rest = max(0.0, o["job"] - o["core"] - o["refs"])
        rows.append((name, o["jobs"], o["runs"], fmt(o["job"], ".1f"), share(o["job"]), fmt(o["core"], ".1f"),
                     fmt(o["refs"], ".1f"), fmt(rest, ".1f"), fmt(rest / max(1, o["jobs"] + o["runs"]), ".3f")))
    wall = results.get("seconds")
    workers = results.get("workers", 1)
    s = Section("Where the suite's time goes")
    s.add(Text(f"Seconds summed over the jobs ({len(cases)} jobs, {fmt(total, '.1f')} s in all; wall time "
               f"{fmt(wall, '.1f')} s with {workers} worker(s)): core's own work, the references' runs (each run's "
               f"own time: a program's includes its start, or for a program that serves, the start of its server in its "
               f"first run of each worker) and the rest of each job -- reading the input, forking "
               f"and isolating each run, correspondence, classification, views -- {fmt(other, '.1f')} s "
               f"({share(other)}). Per run: the rest divided by the job's runs, core's included."),
          Table(["operation", "jobs", "reference runs", "job s", "share", "core s", "references s", "rest s",
                 "rest per run s"], rows),
          Table(["reference", "runs", "seconds", "per run s"],
                [(name, r["runs"], fmt(r["seconds"], ".1f"), fmt(r["seconds"] / max(1, r["runs"]), ".3f"))
                 for name, r in sorted(per_ref.items(), key=lambda kv: -kv[1]["seconds"])]))
    return s
