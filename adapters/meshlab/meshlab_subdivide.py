#!/usr/bin/env python3
"""MeshLab (the VCG library) as a crossdiv reference: one subdivision run of meshlabserver.

    meshlab_subdivide.py SCHEME WEIGHTS LEVELS IN.off OUT.ply
    meshlab_subdivide.py --check
    meshlab_subdivide.py --serve    (each run's SCHEME WEIGHTS LEVELS IN.off OUT.ply as a request)

MeshLab 2020.09 (Debian `meshlab`) has no C++ API here, only meshlabserver, which runs a filter
script on a mesh file and needs an X display: this script writes the filter script for the
scheme and runs `meshlabserver -i IN -o OUT -s SCRIPT` on an Xvfb display of its own (class
Display), from an argument vector.

Filters (the names and parameters of meshlabserver's filter dump):
  loop        "Subdivision Surfaces: Loop", LoopWeight 0 loop | 1 regularity | 2 continuity
              (VCG's LoopWeight, RegularLoopWeight, ContinuityLoopWeight)
  butterfly   "Subdivision Surfaces: Butterfly Subdivision" (VCG's MidPointButterfly: the
              eight-point stencil, the four-point rule on boundary edges, and for a wing
              beyond the boundary the triangle's own opposite vertex, crossdiv's
              opposite-vertex-wings)
Both with Iterations = LEVELS, Edge Threshold 0 (split every edge: a positive threshold
refines only the longer edges) and Selected false.

Input: OFF, which meshlabserver reads without trouble (its OBJ importer aborts on a VCG
assertion with some valid OBJ files). Output: PLY, which meshlabserver writes in binary, so
the float coordinates it computes read back exactly (its OFF has 7 significant digits).

`--serve` (adapters/common/serve.py) starts one Xvfb display for all its runs and runs
meshlabserver on it for each request: a display's start and end are paid once per suite worker.
The display is in the server's process group, so it ends with the server however that ends.

`--check` exits 0 when Xvfb and meshlabserver are on PATH, else 1 naming what is missing:
the manifest's setup command, so that a machine without MeshLab records `ref-unavailable`.
"""
import os
import shutil
import subprocess
import sys
import tempfile

LOOP_WEIGHTS = {"loop": 0, "regularity": 1, "continuity": 2}
LOOP_WEIGHT_NAMES = ('enum_val0="Loop" enum_val1="Enhance regularity" enum_val2="Enhance continuity" '
                     'enum_cardinality="3"')


def filter_script(scheme, weights, levels):
    common = (f'  <Param type="RichInt" value="{levels}" name="Iterations"/>\n'
              '  <Param type="RichAbsPerc" value="0" min="0" max="1" name="Threshold"/>\n'
              '  <Param type="RichBool" value="false" name="Selected"/>\n')
    if scheme == "loop":
        if weights not in LOOP_WEIGHTS:
            raise SystemExit(f"meshlab has no Loop weights '{weights}' (it has: {', '.join(LOOP_WEIGHTS)})")
        body = (' <filter name="Subdivision Surfaces: Loop">\n'
                f'  <Param type="RichEnum" value="{LOOP_WEIGHTS[weights]}" name="LoopWeight" {LOOP_WEIGHT_NAMES}/>\n'
                + common + ' </filter>\n')
    elif scheme == "butterfly":
        body = ' <filter name="Subdivision Surfaces: Butterfly Subdivision">\n' + common + ' </filter>\n'
    else:
        raise SystemExit(f"meshlab has no {scheme} here (it has: loop, butterfly)")
    return "<!DOCTYPE FilterScript>\n<FilterScript>\n" + body + "</FilterScript>\n"


def missing_programs():
    return [p for p in ("Xvfb", "meshlabserver") if shutil.which(p) is None]


def main(argv):
    if argv[1:] == ["--check"]:
        missing = missing_programs()
        if missing:
            print("not on PATH: " + ", ".join(missing) + " (Debian packages meshlab, xvfb)", file=sys.stderr)
            return 1
        return 0
    if len(argv) != 6:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    scheme, weights, levels, mesh_in, mesh_out = argv[1:]
    if not levels.isdigit() or int(levels) < 1:
        print(f"levels must be a positive integer, got '{levels}'", file=sys.stderr)
        return 2
    with Display() as env:
        return run(scheme, weights, int(levels), mesh_in, mesh_out, env)


class Display:
    """An Xvfb display for meshlabserver, as a context: the environment that names it.

    Xvfb picks a free display number itself (-displayfd), and is waited for when it is told to
    end, so that it removes its /tmp/.X*-lock file and socket. (xvfb-run does not wait: when the
    harness then kills the run's process group, Xvfb dies in its clean-up and leaves both behind,
    one pair per run, and xvfb-run -a walks past every one of them to find a free number.)
    """

    def __enter__(self):
        read_end, write_end = os.pipe()
        self.server = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-nolisten", "tcp", "-screen", "0", "640x480x24"],
                                       pass_fds=(write_end,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(write_end)
        with os.fdopen(read_end) as f:
            number = f.readline().strip()  # written once the display accepts connections
        if not number.isdigit():
            self.server.wait()
            raise SystemExit(f"Xvfb did not start (exit status {self.server.returncode})")
        return dict(os.environ, DISPLAY=":" + number)

    def __exit__(self, *exc):
        self.server.terminate()
        self.server.wait()
        return False


def run(scheme, weights, levels, mesh_in, mesh_out, env):
    """One meshlabserver run on the display `env` names."""
    with tempfile.TemporaryDirectory(prefix="crossdiv-meshlab-") as tmp:
        script = os.path.join(tmp, "filter.mlx")
        with open(script, "w") as f:
            f.write(filter_script(scheme, weights, levels))
        log = os.path.join(tmp, "meshlab.log")
        with open(log, "w") as out:
            status = subprocess.run(["meshlabserver", "-i", mesh_in, "-o", mesh_out, "-s", script],
                                    stdout=out, stderr=subprocess.STDOUT, env=env).returncode
        if status != 0 or not os.path.exists(mesh_out):
            with open(log, errors="replace") as f:
                # meshlabserver prints progress on one long line; its last words say what failed.
                said = " ".join(f.read().split())[-400:]
            print(f"meshlabserver exited with status {status}: {said}", file=sys.stderr)
            return status or 1
    return 0


def serve_runs():
    """--serve: one Xvfb display, a meshlabserver on it per request."""
    missing = missing_programs()
    if missing:
        print("not on PATH: " + ", ".join(missing) + " (Debian packages meshlab, xvfb)", file=sys.stderr)
        return 1

    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
    from serve import serve
    with Display() as env:
        def one(args):
            if len(args) != 5:
                print(__doc__.strip().splitlines()[2], file=sys.stderr)
                return 2
            scheme, weights, levels, mesh_in, mesh_out = args
            if not levels.isdigit() or int(levels) < 1:
                print(f"levels must be a positive integer, got '{levels}'", file=sys.stderr)
                return 2
            return run(scheme, weights, int(levels), mesh_in, mesh_out, env)

        return serve(one)


if __name__ == "__main__":
    sys.exit(serve_runs() if sys.argv[1:] == ["--serve"] else main(sys.argv))
