#!/usr/bin/env python3
"""The course's vertex-normal task in Python, standard library only: each vertex's normal is
the sum of the cross products (b - a) x (c - a) of its triangles, normalized, so that each face
counts by its area (the seed's rule). Writes one `vn` line per vertex, in vertex order:

    python3 normals.py IN.obj OUT.obj [--uniform] [--clockwise]

--uniform sums unit face normals instead (every face counts the same); --clockwise takes the
cross product the other way round (normals pointing inward): the two classic slips, which
crossdiv names ("uniform", "area, reversed").
"""
import math
import sys


def main():
    src, out = sys.argv[1], sys.argv[2]
    uniform, clockwise = "--uniform" in sys.argv[3:], "--clockwise" in sys.argv[3:]
    verts, faces = [], []
    for line in open(src):
        w = line.split()
        if w and w[0] == "v":
            verts.append([float(x) for x in w[1:4]])
        elif w and w[0] == "f":
            faces.append([int(p.split("/")[0]) - 1 for p in w[1:]])
    sums = [[0.0, 0.0, 0.0] for _ in verts]
    for a, b, c in faces:
        u = [verts[b][k] - verts[a][k] for k in range(3)]
        v = [verts[c][k] - verts[a][k] for k in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        if clockwise:
            n = [-x for x in n]
        length = math.sqrt(sum(x * x for x in n))
        if uniform and length > 0:
            n = [x / length for x in n]
        for i in (a, b, c):
            sums[i] = [sums[i][k] + n[k] for k in range(3)]
    with open(out, "w") as f:
        for s in sums:
            length = math.sqrt(sum(x * x for x in s))
            n = [x / length for x in s] if length > 0 else [0.0, 0.0, 0.0]
            f.write("vn %r %r %r\n" % tuple(n))


if __name__ == "__main__":
    main()
