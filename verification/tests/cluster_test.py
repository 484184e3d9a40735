"""crossdiv-cluster on a Dask LocalCluster of 2 worker processes: the merged results equal a
single-machine run of the same manifest case for case, and a worker killed in the middle of a
shard is survived (the shard run again elsewhere, the results still equal).

Needs CROSSDIV_BIN (the built program) and Debian's python3-distributed.
"""
import json
import os
import signal
import subprocess
import sys
import time

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
LAUNCHER = os.path.join(HERE, "..", "cluster", "crossdiv_cluster.py")
CROSSDIV = os.environ.get("CROSSDIV_BIN", os.path.join(HERE, "..", "..", "build", "verification", "crossdiv"))

# Small but of every kind of record: Loop against two libraries (CGAL: a corner-rule divergence
# and a crash), a polygon scheme with a reference whose boundary rule differs, core refusals, and
# an invariance case. Not OpenMesh's Loop: at an isolated vertex it reads memory it never wrote,
# and whether a second run finds other bytes (ref-nondeterministic) or the same (a divergence)
# depends on the process, so no two runs need agree on it.
MANIFEST = """suite cluster-test
timeout 60
case bundled:all,edgecases:all   loop weights=loop boundary=edge-and-corner levels=2 tier=weak tolerance=1e-12 against=opensubdiv,cgal
case bundled:all,edgecases:all   modified-butterfly levels=2 tier=weak tolerance=1e-12 against=openmesh refuses=non-manifold-handling,orientation-handling
case bundled:icosahedron,bundled:open-patch   invariance scheme=loop levels=2 impls=core,opensubdiv
"""
# What may differ between two runs of the same cases: times, and the shard bookkeeping.
VOLATILE = {"seconds", "core_seconds", "job_seconds", "reference_seconds", "shard", "workers", "jobs_run"}


def comparable(folder):
    """results.json's cases by id, without the fields that time the run. A run found
    ref-nondeterministic (the reference reads memory it never wrote: OpenMesh at an isolated
    vertex) keeps its outcome and status; the numbers it read differ from process to process,
    the cluster's or not, and are left out."""
    def strip(x):
        if isinstance(x, dict):
            if x.get("verdict") == "ref-nondeterministic":
                return {k: x[k] for k in ("reference", "verdict", "outcome", "divergence_class", "status") if k in x}
            return {k: strip(v) for k, v in x.items() if k not in VOLATILE}
        if isinstance(x, list):
            return [strip(v) for v in x]
        return x
    with open(os.path.join(folder, "results.json")) as f:
        results = json.load(f)
    return {c["id"]: strip(c) for c in results["cases"]}, results["summary"]


@pytest.fixture(scope="module")
def single(tmp_path_factory):
    assert os.path.exists(CROSSDIV), f"{CROSSDIV}: build crossdiv first (or set CROSSDIV_BIN)"
    folder = tmp_path_factory.mktemp("cluster")
    manifest = folder / "cluster.suite"
    manifest.write_text(MANIFEST)
    out = folder / "single"
    r = subprocess.run([CROSSDIV, "suite", str(manifest), "--out", str(out), "--no-report"], capture_output=True, text=True, timeout=600)
    assert r.returncode in (0, 1), r.stderr
    return manifest, out, r.returncode


def launch(manifest, out, *where):
    env = dict(os.environ, CROSSDIV_BIN=CROSSDIV)
    return subprocess.Popen([sys.executable, LAUNCHER, str(manifest), "--out", str(out), *where],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)


def differences(a, b):
    """The cases whose records differ, each with its differing fields, for a failure message."""
    out = []
    for key in sorted(set(a) | set(b)):
        x, y = a.get(key, {}), b.get(key, {})
        if x != y:
            out.append(f"{key}: " + "; ".join(f"{k}: {json.dumps(x.get(k))[-600:]} != {json.dumps(y.get(k))[-600:]}"
                                             for k in sorted(set(x) | set(y)) if x.get(k) != y.get(k)))
    return "\n".join(out)


def test_a_local_cluster_merges_to_the_single_machine_results(single, tmp_path):
    manifest, single_out, single_status = single
    p = launch(manifest, tmp_path / "cluster", "--local", "2")
    output, _ = p.communicate(timeout=600)
    assert p.returncode == single_status, output
    assert "in 4 shard(s) on 2 worker(s)" in output and "[4/4]" in output, output
    cluster_cases, cluster_summary = comparable(tmp_path / "cluster")
    single_cases, single_summary = comparable(single_out)
    assert len(cluster_cases) == len(single_cases) > 100
    assert cluster_cases == single_cases, differences(cluster_cases, single_cases)
    assert cluster_summary == single_summary
    assert os.path.exists(tmp_path / "cluster" / "index.html")  # merge writes the report


def test_a_worker_killed_in_the_middle_of_a_shard_is_survived(single, tmp_path):
    from distributed import Client, LocalCluster
    manifest, single_out, single_status = single
    scratch = tmp_path / "scratch"
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                           local_directory=str(scratch))
    client = Client(cluster)
    try:
        p = launch(manifest, tmp_path / "cluster", "--scheduler", cluster.scheduler_address, "--shards", "4")
        # Kill one worker process as soon as a shard is running on it.
        victim = None
        deadline = time.monotonic() + 120
        while victim is None and time.monotonic() < deadline:
            processing = client.processing()
            for address, keys in processing.items():
                if keys:
                    victim = client.run(os.getpid, workers=[address])[address]
                    break
            time.sleep(0.05)
        assert victim is not None, "no shard started"
        os.kill(victim, signal.SIGKILL)
        output, _ = p.communicate(timeout=600)
    finally:
        client.close()
        cluster.close()
    assert p.returncode == single_status, output
    assert "[4/4]" in output, output
    cluster_cases, _ = comparable(tmp_path / "cluster")
    single_cases, _ = comparable(single_out)
    assert cluster_cases == single_cases, differences(cluster_cases, single_cases)
    # The killed worker's shard left nothing behind: its crossdiv stopped with it, its folder
    # purged by Dask with the dead worker's.
    left = [os.path.join(d, n) for d, names, _ in os.walk(scratch) for n in names if n.startswith("crossdiv-shard")]
    assert not left, left
    assert subprocess.run(["pgrep", "-f", str(manifest)], capture_output=True).returncode == 1, "a shard's crossdiv runs on"
