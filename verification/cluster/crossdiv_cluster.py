#!/usr/bin/python3
"""crossdiv-cluster: a suite run on a Dask cluster, merged into one results folder and report.

    crossdiv-cluster MANIFEST --out DIR (--local N | --scheduler tcp://HOST:PORT)
                     [--shards K] [--crossdiv PATH] [--retries R]

The suite is cut into K shards (`crossdiv suite --shard I/K`: job index mod K); each shard is one
Dask task, run on a worker by the crossdiv installed there, into a temporary folder of the
worker's; its result files come back through Dask (not through a shared file system) and are
written to DIR/shards/I. When every shard is in, `crossdiv merge` joins them into DIR (results,
JUnit, report), as for shards run by hand. A shard whose worker dies is run again on another
(Dask reschedules a task its worker did not finish; --retries more times for a shard whose run
failed); progress is printed as shards finish.

--local N starts a LocalCluster of N worker processes on this machine (one thread each: a
shard's crossdiv has --jobs 1, so that N shards use N cores); --scheduler connects to a running
cluster whose workers have crossdiv and the suite's inputs installed (the manifest is read
there at the same path when it exists, else its text is sent).

Exit status: crossdiv merge's (0 when no case failed, 1 when one did); 2 for a bad command line,
a shard that failed after its retries, or no cluster.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time


def worker_directory():
    """The Dask worker's own scratch folder, where there is one: a worker killed in a shard
    never reaches its `finally`, and Dask purges a dead worker's folder when the next one
    starts (a folder of /tmp would stay). None (the system's) outside a worker."""
    try:
        from distributed import get_worker
        return get_worker().local_directory
    except (ImportError, ValueError):
        return None


def run_shard(crossdiv, manifest_path, manifest_text, index, count):
    """On a worker: `crossdiv suite --shard index/count --no-report` into a temporary folder;
    returns its exit status, its stderr's tail and every file it wrote ({relative path: bytes})."""
    work = tempfile.mkdtemp(prefix=f"crossdiv-shard{index}-", dir=worker_directory())
    try:
        manifest = manifest_path
        if not os.path.exists(manifest):
            manifest = os.path.join(work, os.path.basename(manifest_path))
            with open(manifest, "w") as f:
                f.write(manifest_text)
        out = os.path.join(work, "out")
        t0 = time.monotonic()
        # setpriv (util-linux): the shard's crossdiv is stopped (SIGTERM: its children killed,
        # its folders removed) when the worker that started it dies, rather than running on
        # beside the shard's second run.
        r = subprocess.run(["setpriv", "--pdeathsig", "TERM", crossdiv, "suite", manifest, "--shard", f"{index}/{count}", "--no-report", "--jobs", "1",
                            "--out", out], capture_output=True, text=True)
        files = {}
        for folder, _, names in os.walk(out):
            for name in names:
                path = os.path.join(folder, name)
                with open(path, "rb") as f:
                    files[os.path.relpath(path, out)] = f.read()
        return {"index": index, "status": r.returncode, "stderr": r.stderr[-4000:], "files": files,
                "seconds": time.monotonic() - t0, "host": os.uname().nodename, "pid": os.getpid()}
    finally:
        shutil.rmtree(work, ignore_errors=True)


def write_shard(folder, result):
    for relative, data in result["files"].items():
        path = os.path.join(folder, relative)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(data)


def parse(argv):
    p = argparse.ArgumentParser(prog="crossdiv-cluster", description=__doc__.split("\n\n")[0])
    p.add_argument("manifest")
    p.add_argument("--out", required=True, help="results folder (DIR/shards/I holds each shard's files)")
    where = p.add_mutually_exclusive_group(required=True)
    where.add_argument("--local", type=int, metavar="N", help="start a LocalCluster of N worker processes")
    where.add_argument("--scheduler", metavar="ADDRESS", help="a running Dask scheduler, tcp://HOST:PORT")
    p.add_argument("--shards", type=int, help="how many shards (default: 2 per worker)")
    p.add_argument("--crossdiv", default=os.environ.get("CROSSDIV_BIN", shutil.which("crossdiv") or "crossdiv"),
                   help="the crossdiv program on the workers (default: $CROSSDIV_BIN, else crossdiv on PATH)")
    p.add_argument("--retries", type=int, default=1, help="runs again of a shard whose crossdiv failed (default 1)")
    a = p.parse_args(argv)
    if a.local is not None and not 1 <= a.local <= 256:
        p.error("--local: between 1 and 256 workers")
    if a.shards is not None and not 1 <= a.shards <= 100000:
        p.error("--shards: between 1 and 100000")
    if not os.path.isfile(a.manifest):
        p.error(f"{a.manifest}: no such manifest")
    return a


def main(argv=None):
    a = parse(sys.argv[1:] if argv is None else argv)
    try:
        from distributed import Client, LocalCluster, as_completed
    except ImportError as e:
        print(f"crossdiv-cluster: Dask distributed is missing (Debian python3-distributed): {e}", file=sys.stderr)
        return 2
    manifest = os.path.abspath(a.manifest)
    with open(manifest) as f:
        text = f.read()
    cluster = None
    try:
        if a.local:
            cluster = LocalCluster(n_workers=a.local, threads_per_worker=1, processes=True, dashboard_address=None)
            client = Client(cluster)
        else:
            client = Client(a.scheduler, timeout="30s")
    except Exception as e:  # noqa: the cluster's own error, said as is
        print(f"crossdiv-cluster: no cluster: {e}", file=sys.stderr)
        return 2
    try:
        workers = max(1, len(client.scheduler_info().get("workers", {})))
        count = a.shards or 2 * workers
        print(f"crossdiv-cluster: {os.path.basename(manifest)} in {count} shard(s) on {workers} worker(s)", flush=True)
        t0 = time.monotonic()
        tries = {}
        futures = {}
        for i in range(1, count + 1):
            futures[client.submit(run_shard, a.crossdiv, manifest, text, i, count, pure=False, key=f"shard-{i}-of-{count}-try-0")] = i
            tries[i] = 0
        shards = os.path.join(a.out, "shards")
        shutil.rmtree(shards, ignore_errors=True)
        done = 0
        pending = as_completed(list(futures))
        for future in pending:
            i = futures[future]
            try:
                result = future.result()
            except Exception as e:  # noqa: a task Dask gave up on (its workers died too often)
                result = {"index": i, "status": -1, "stderr": f"{type(e).__name__}: {e}", "files": {}, "seconds": 0, "host": "?"}
            if result["status"] not in (0, 1):  # 1: the shard has a failing case, a result like any other
                if tries[i] < a.retries:
                    tries[i] += 1
                    print(f"  shard {i}/{count} failed ({result['stderr'].strip()[-200:]}); run again", flush=True)
                    again = client.submit(run_shard, a.crossdiv, manifest, text, i, count, pure=False,
                                          key=f"shard-{i}-of-{count}-try-{tries[i]}")
                    futures[again] = i
                    pending.add(again)
                    continue
                print(f"crossdiv-cluster: shard {i}/{count} failed: {result['stderr'].strip()[-400:]}", file=sys.stderr)
                return 2
            write_shard(os.path.join(shards, str(i)), result)
            done += 1
            print(f"  [{done}/{count}] shard {i} in {result['seconds']:.1f} s on {result['host']} "
                  f"({len(result['files'])} files)", flush=True)
        elapsed = time.monotonic() - t0
        print(f"crossdiv-cluster: {count} shard(s) in {elapsed:.1f} s; merging", flush=True)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    merge = subprocess.run([a.crossdiv, "merge", *[os.path.join(shards, str(i)) for i in range(1, count + 1)], "--out", a.out])
    return merge.returncode


if __name__ == "__main__":
    sys.exit(main())
