#!/usr/bin/env python3
"""A curve subject that fails in one named way, for the tests of the curve task's subjects:

    misbehaving_curves.py MODE IN.swp OUT.csv

MODE: crash (SIGSEGV), hang, nothing (exit 0, no file), nan (one coordinate NaN), garbage (a
cell that is no number), short (the last sample of every curve dropped), frenet (normals by
the Frenet frame: the curvature direction, not the assignment's recursive update), unit
(tangents written unnormalized: the derivative itself). The others start from the course-style
program, examples/subjects/python-curves/tessellate.py.
"""
import os
import signal
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "examples", "subjects",
                                "python-curves"))
import tessellate  # noqa: E402


def second_derivatives(keyword, steps, points):
    """The second derivative at every sample, over the same windows as tessellate.tessellate."""
    if keyword.startswith("bez"):
        basis, windows = tessellate.BEZIER, [points[3 * s:3 * s + 4] for s in range((len(points) - 1) // 3)]
    else:
        basis, windows = tessellate.BSPLINE, [points[s:s + 4] for s in range(len(points) - 3)]
    out = []
    for s, p in enumerate(windows):
        for j in range(0 if s == 0 else 1, steps + 1):
            powers = [0, 0, 2, 6 * j / steps]
            w = [sum(powers[r] * basis[r][k] for r in range(4)) for k in range(4)]
            out.append([sum(w[k] * p[k][c] for k in range(4)) for c in range(3)])
    return out


def main():
    mode, src, out = sys.argv[1], sys.argv[2], sys.argv[3]
    if mode == "crash":
        os.kill(os.getpid(), signal.SIGSEGV)
    if mode == "hang":
        time.sleep(3600)
    if mode == "nothing":
        return
    rows = ["curve,index,x,y,z,tx,ty,tz,nx,ny,nz,bx,by,bz"]
    for index, (keyword, steps, points) in enumerate(tessellate.read_swp(src)):
        if keyword[:3] not in ("bez", "bsp"):
            continue
        samples = tessellate.tessellate(keyword, steps, points, False)
        if mode == "short":
            samples = samples[:-1]
        b = [0.0, 0.0, 1.0]
        for k, (pos, tan) in enumerate(samples):
            t = tessellate.normalized(tan)
            n = tessellate.normalized(tessellate.cross(b, t))
            if mode == "frenet":  # the second derivative's part across T
                d2 = second_derivatives(keyword, steps, points)[k]
                along = sum(d2[c] * t[c] for c in range(3))
                n = tessellate.normalized([d2[c] - along * t[c] for c in range(3)])
            b = tessellate.cross(t, n)
            written_t = tan if mode == "unit" else t
            row = [repr(v) for v in pos + written_t + n + b]
            if mode == "nan" and k == 1:
                row[1] = "nan"
            if mode == "garbage" and k == 1:
                row[0] = "1.2.3"
            rows.append(f"{index},{k}," + ",".join(row))
    with open(out, "w") as f:
        f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
