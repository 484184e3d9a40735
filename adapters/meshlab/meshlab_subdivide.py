#!/usr/bin/env python3
"""MeshLab (the VCG library) as a crossdiv reference: one subdivision run of meshlabserver.

    meshlab_subdivide.py SCHEME WEIGHTS LEVELS IN.off OUT.ply
    meshlab_subdivide.py --check

MeshLab 2020.09 (Debian `meshlab`) has no C++ API here, only meshlabserver, which runs a filter
script on a mesh file and needs an X display: this script writes the filter script for the
scheme and runs `xvfb-run -a meshlabserver -i IN -o OUT -s SCRIPT`, from an argument vector.

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

`--check` exits 0 when xvfb-run and meshlabserver are on PATH, else 1 naming what is missing:
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
    return [p for p in ("xvfb-run", "meshlabserver") if shutil.which(p) is None]


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
    with tempfile.TemporaryDirectory(prefix="crossdiv-meshlab-") as tmp:
        script = os.path.join(tmp, "filter.mlx")
        with open(script, "w") as f:
            f.write(filter_script(scheme, weights, int(levels)))
        log = os.path.join(tmp, "meshlab.log")
        with open(log, "w") as out:
            status = subprocess.run(["xvfb-run", "-a", "meshlabserver", "-i", mesh_in, "-o", mesh_out, "-s", script],
                                    stdout=out, stderr=subprocess.STDOUT).returncode
        if status != 0 or not os.path.exists(mesh_out):
            with open(log, errors="replace") as f:
                # meshlabserver prints progress on one long line; its last words say what failed.
                said = " ".join(f.read().split())[-400:]
            print(f"meshlabserver exited with status {status}: {said}", file=sys.stderr)
            return status or 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
