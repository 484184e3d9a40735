#!/usr/bin/env python3
"""The course's half-edge task in Python, standard library only: apply edge flips and splits in
order to a triangle mesh, with the faces as index triples (no half-edges: each operation finds
the triangles around its edge), and write the mesh:

    python3 edit.py IN.obj OPS.txt OUT.obj [--third] [--turned-flip]

OPS.txt has one `flip A B` or `split A B` per line (vertex indices from 0). A flip of a boundary
edge, of an edge whose two triangles share their third vertex, or one that would join two
vertices already joined, is refused (the mesh stays). A split appends the edge's midpoint as a
new vertex and cuts each triangle of the edge in two. --third splits at a third of the edge and
--turned-flip writes the flipped triangles turned over: two slips crossdiv names.
"""
import sys


def main():
    src, ops, out = sys.argv[1], sys.argv[2], sys.argv[3]
    third, turned = "--third" in sys.argv[4:], "--turned-flip" in sys.argv[4:]
    verts, faces = [], []
    for line in open(src):
        w = line.split()
        if w and w[0] == "v":
            verts.append([float(x) for x in w[1:4]])
        elif w and w[0] == "f":
            faces.append([int(p.split("/")[0]) - 1 for p in w[1:]])
    for line in open(ops):
        w = line.split()
        if not w:
            continue
        kind, a, b = w[0], int(w[1]), int(w[2])
        # The triangle with a -> b and the one with b -> a, each with its third vertex.
        t1 = next((i for i, f in enumerate(faces) if any(f[k] == a and f[(k + 1) % 3] == b for k in range(3))), None)
        t2 = next((i for i, f in enumerate(faces) if any(f[k] == b and f[(k + 1) % 3] == a for k in range(3))), None)
        third_of = {i: next(v for v in faces[i] if v not in (a, b)) for i in (t1, t2) if i is not None}
        if kind == "flip":
            if t1 is None or t2 is None:
                continue  # a boundary edge
            c, d = third_of[t1], third_of[t2]
            joined = any(c in f and d in f for f in faces)
            if c == d or joined:
                continue
            faces[t1], faces[t2] = ([c, d, a], [c, b, d]) if turned else ([a, d, c], [d, b, c])
        else:
            t = 1 / 3 if third else 0.5
            verts.append([verts[a][k] + t * (verts[b][k] - verts[a][k]) for k in range(3)])
            m = len(verts) - 1
            if t1 is not None:
                c = third_of[t1]
                faces[t1] = [a, m, c]
                faces.append([m, b, c])
            if t2 is not None:
                d = third_of[t2]
                faces[t2] = [b, m, d]
                faces.append([m, a, d])
    with open(out, "w") as f:
        for v in verts:
            f.write("v %r %r %r\n" % tuple(v))
        for t in faces:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


if __name__ == "__main__":
    main()
