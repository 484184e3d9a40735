#!/usr/bin/env python3
"""The course's curve task in Python, standard library only: every bez2/bez3 (piecewise cubic
Bezier, 3n + 1 points) and bsp2/bsp3 (uniform cubic B-spline) record of an SWP file evaluated
at STEPS uniform steps per segment with the basis matrices of the lecture notes, and a local
frame at each sample by the assignment's recursive update: B_-1 = +z, N_i = (B_(i-1) x T_i)
normalized, B_i = T_i x N_i. Other records (circles, ...) are not part of the exercise and are
skipped. Writes crossdiv's curve table (CSV with a header):

    python3 tessellate.py IN.swp OUT.csv [--bspline-as-bezier]

--bspline-as-bezier reads B-spline records with the Bezier basis: the classic bug of the
exercise, which crossdiv names ("bezier basis").
"""
import math
import sys

BEZIER = [[1, 0, 0, 0], [-3, 3, 0, 0], [3, -6, 3, 0], [-1, 3, -3, 1]]
BSPLINE = [[1 / 6, 4 / 6, 1 / 6, 0], [-3 / 6, 0, 3 / 6, 0], [3 / 6, -6 / 6, 3 / 6, 0], [-1 / 6, 3 / 6, -3 / 6, 1 / 6]]


def read_swp(path):
    """(keyword, steps, points) per curve record, points as [x, y, z]. A record is a line of
    words (keyword, name, STEPS, ...) and the [x y] or [x y z] lines after it; srev and gcyl
    lines build surfaces from curves and are not curves themselves."""
    records = []
    for line in open(path):
        words = line.replace("[", " [ ").replace("]", " ] ").split()
        if not words:
            continue
        if words[0] == "[":
            while words and words[0] == "[":  # one point or several on a line
                end = words.index("]")
                xyz = [float(v) for v in words[1:end]]
                records[-1][2].append(xyz + [0.0] * (3 - len(xyz)))
                words = words[end + 1:]
        elif words[0] in ("srev", "gcyl"):
            records.append(None)  # its lines name curves; it has no points of its own
        else:
            steps = int(words[2]) if len(words) > 2 and words[2].isdigit() else 0
            records.append((words[0], steps, []))
    return [r for r in records if r is not None]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def normalized(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v] if n > 0 else v


def evaluate(basis, p, t):
    """Position and derivative of one cubic segment with control points p at t."""
    powers, derivative = [1, t, t * t, t ** 3], [0, 1, 2 * t, 3 * t * t]
    weights = [sum(powers[r] * basis[r][k] for r in range(4)) for k in range(4)]
    dweights = [sum(derivative[r] * basis[r][k] for r in range(4)) for k in range(4)]
    pos = [sum(weights[k] * p[k][c] for k in range(4)) for c in range(3)]
    tan = [sum(dweights[k] * p[k][c] for k in range(4)) for c in range(3)]
    return pos, tan


def tessellate(keyword, steps, points, bspline_as_bezier):
    if keyword.startswith("bez"):
        basis, segments = BEZIER, [points[3 * s:3 * s + 4] for s in range((len(points) - 1) // 3)]
    else:
        basis = BEZIER if bspline_as_bezier else BSPLINE
        segments = [points[s:s + 4] for s in range(len(points) - 3)]
    samples = []
    for s, p in enumerate(segments):
        for j in range(0 if s == 0 else 1, steps + 1):  # a joint is the previous segment's last sample
            samples.append(evaluate(basis, p, j / steps))
    return samples


def main():
    src, out = sys.argv[1], sys.argv[2]
    bspline_as_bezier = "--bspline-as-bezier" in sys.argv[3:]
    with open(out, "w") as f:
        f.write("curve,index,x,y,z,tx,ty,tz,nx,ny,nz,bx,by,bz\n")
        for index, (keyword, steps, points) in enumerate(read_swp(src)):
            if keyword[:3] not in ("bez", "bsp"):
                continue
            b = [0.0, 0.0, 1.0]
            for k, (pos, tan) in enumerate(tessellate(keyword, steps, points, bspline_as_bezier)):
                t = normalized(tan)
                n = normalized(cross(b, t))
                b = cross(t, n)
                f.write(f"{index},{k}," + ",".join(repr(v) for v in pos + t + n + b) + "\n")


if __name__ == "__main__":
    main()
