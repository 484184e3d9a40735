#!/usr/bin/env python3
"""The course's Bezier-patch task in Python, standard library only: read a BEZ file (the
number of patches, then 16 control points per patch, four rows of four), evaluate every bicubic
patch on a (res + 1) x (res + 1) grid with its normal du x dv, and write an OBJ with a `vn` per
`v` and two triangles per grid quad, patch by patch (not welded):

    python3 patches.py IN.bez RES OUT.obj [--swap-uv]

--swap-uv indexes the control net the other way round (u down the rows): the surface is
the same, its normals point the other way, the classic slip that crossdiv names ("reversed").
At a collapsed patch edge du x dv vanishes; the program writes a zero normal there.
"""
import math
import sys


def bernstein(t):
    s = 1 - t
    return [s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t], [-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def main():
    src, res, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    swap = "--swap-uv" in sys.argv[4:]
    numbers = [float(w) for w in open(src).read().split()]
    count, numbers = int(numbers[0]), numbers[1:]
    lines_v, lines_vn, lines_f = [], [], []
    for p in range(count):
        rows = [[numbers[48 * p + 12 * i + 3 * j:48 * p + 12 * i + 3 * j + 3] for j in range(4)] for i in range(4)]
        # Each row of the file runs along u, the rows follow one another along v: net[i][j] is
        # the point i along u and j along v.
        net = rows if swap else [[rows[j][i] for j in range(4)] for i in range(4)]
        first = len(lines_v)
        size = max(max(abs(c) for row in net for q in row for c in q), 1e-300)
        for a in range(res + 1):
            bu, du = bernstein(a / res)
            for b in range(res + 1):
                bv, dv = bernstein(b / res)
                point = [sum(bu[i] * bv[j] * net[i][j][k] for i in range(4) for j in range(4)) for k in range(3)]
                pu = [sum(du[i] * bv[j] * net[i][j][k] for i in range(4) for j in range(4)) for k in range(3)]
                pv = [sum(bu[i] * dv[j] * net[i][j][k] for i in range(4) for j in range(4)) for k in range(3)]
                n = cross(pu, pv)
                length = math.sqrt(sum(x * x for x in n))
                # A derivative that is rounding (a collapsed edge) leaves no direction.
                tiny = 1e-9 * size
                degenerate = min(math.sqrt(sum(x * x for x in pu)), math.sqrt(sum(x * x for x in pv))) < tiny
                n = [x / length for x in n] if length > 0 and not degenerate else [0.0, 0.0, 0.0]
                lines_v.append("v %r %r %r" % tuple(point))
                lines_vn.append("vn %r %r %r" % tuple(n))
        for a in range(res):
            for b in range(res):
                i00, i10 = first + a * (res + 1) + b + 1, first + (a + 1) * (res + 1) + b + 1
                i01, i11 = i00 + 1, i10 + 1
                lines_f.append(f"f {i00}//{i00} {i10}//{i10} {i11}//{i11}")
                lines_f.append(f"f {i00}//{i00} {i11}//{i11} {i01}//{i01}")
    with open(out, "w") as f:
        f.write("\n".join(lines_v + lines_vn + lines_f) + "\n")


if __name__ == "__main__":
    main()
