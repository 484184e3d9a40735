#!/usr/bin/env python3
"""Doo-Sabin subdivision as the course notes state it (Doo and Sabin 1978): every corner
(face f, vertex v_0) becomes a new vertex, the combination of f's n vertices taken from v_0
around the face with

    alpha_0 = 1/4 + 5/(4n),  alpha_k = (3 + 2 cos(2 pi k / n)) / (4n),

and the new mesh has a face per old face (its corner points), a quad per interior edge and a
face per interior vertex (the corner points around it). Edges and vertices on the boundary
get no face: the exercise only treats closed meshes, and an open one shrinks inward.
Standard library only.

    python3 doo_sabin.py IN.obj LEVELS OUT.obj [--centroid-weights]

--centroid-weights takes Catmull and Clark's weights instead: each corner point the average of
its vertex, the midpoints of its two edges in the face and the face's centroid (the same on
quads, different on every other face): crossdiv names them (weights=catmull-clark).
"""
import math
import sys

from polymesh import Tables, combine, main

CENTROID_WEIGHTS = "--centroid-weights" in sys.argv[4:]


def weight(n, k):
    if CENTROID_WEIGHTS:
        return 0.5 + 0.25 / n if k == 0 else (0.125 + 0.25 / n if k in (1, n - 1) else 0.25 / n)
    if k == 0:
        return 0.25 + 5.0 / (4.0 * n)
    return (3.0 + 2.0 * math.cos(2.0 * math.pi * k / n)) / (4.0 * n)


def subdivide(verts, faces):
    t = Tables(verts, faces)
    corner_point = {}  # (face, vertex) -> new vertex
    new_verts, new_faces = [], []
    for fi, f in enumerate(faces):
        n = len(f)
        face = []
        for k in range(n):
            corner_point[(fi, f[k])] = len(new_verts)
            face.append(len(new_verts))
            new_verts.append(combine(verts, [(f[(k + j) % n], weight(n, j)) for j in range(n)]))
        new_faces.append(face)
    for a, b in t.edges:
        if t.is_boundary_edge(a, b):
            continue
        f, g = t.half_edge[(a, b)][0], t.half_edge[(b, a)][0]
        new_faces.append([corner_point[(f, a)], corner_point[(g, a)], corner_point[(g, b)], corner_point[(f, b)]])
    for v in range(len(verts)):
        if t.on_boundary(v) or not t.neighbours[v]:
            continue
        # Around v counter-clockwise: from face f across its edge into v (u -> v) to the face
        # that has v -> u.
        first = t.neighbours[v][0]
        face, u = t.half_edge[(v, first)][0], first
        ring = []
        while True:
            ring.append(corner_point[(face, v)])
            f = faces[face]
            u = f[f.index(v) - 1]  # the vertex before v in this face
            face = t.half_edge[(v, u)][0]
            if u == first:
                break
        new_faces.append(ring)
    return new_verts, new_faces


if __name__ == "__main__":
    main(subdivide)
