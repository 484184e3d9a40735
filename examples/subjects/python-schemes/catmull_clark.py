#!/usr/bin/env python3
"""Catmull-Clark subdivision as the course notes state it (Catmull and Clark 1978):

  face point    the centroid of the face;
  edge point    the average of the edge's two ends and its two face points; on the boundary,
                the edge's midpoint;
  vertex point  (F + 2 R + (n - 3) P) / n with F the average of the n face points around P and
                R the average of the n edge midpoints; on the boundary, the cubic B-spline
                curve rule 1/8, 3/4, 1/8 along the boundary polygon.

Every face of n corners becomes n quads. Standard library only.

    python3 catmull_clark.py IN.obj LEVELS OUT.obj [--edge-points]

--edge-points takes R as the average of the new edge *points* instead of the edge midpoints,
as some course notes (and, for a time, Wikipedia) state the rule: crossdiv names it
(vertex=edge-point-average).
"""
import sys

from polymesh import Tables, add, centroid, combine, main, scale

EDGE_POINTS = "--edge-points" in sys.argv[4:]


def vertex_point(F, R, P, n):
    """Catmull and Clark's interior vertex point."""
    return scale(add(add(F, R, 2.0), P, n - 3.0), 1.0 / n)


def subdivide(verts, faces):
    t = Tables(verts, faces)
    face_points = [centroid(verts, f) for f in faces]

    # New vertices: the old ones moved, then one per edge, then one per face.
    edge_index = {}
    edge_points = []
    for a, b in t.edges:
        fs = t.edge_faces[(a, b)]
        if len(fs) == 2:
            p = scale(add(add(verts[a], verts[b]), add(face_points[fs[0]], face_points[fs[1]])), 0.25)
        else:
            p = scale(add(verts[a], verts[b]), 0.5)
        edge_index[(a, b)] = len(verts) + len(edge_points)
        edge_points.append(p)

    faces_around = [[] for _ in verts]
    for fi, f in enumerate(faces):
        for v in f:
            faces_around[v].append(fi)
    moved = []
    for v, p in enumerate(verts):
        if t.on_boundary(v):
            nb = t.boundary_neighbours[v]
            moved.append(combine(verts, [(v, 0.75), (nb[0], 0.125), (nb[-1], 0.125)]))
            continue
        n = len(t.neighbours[v])
        if n == 0:
            moved.append(list(p))
            continue
        F = scale([sum(face_points[f][i] for f in faces_around[v]) for i in range(3)], 1.0 / len(faces_around[v]))
        if EDGE_POINTS:
            ends = [edge_points[edge_index[(min(v, u), max(v, u))] - len(verts)] for u in t.neighbours[v]]
            R = scale([sum(e[i] for e in ends) for i in range(3)], 1.0 / n)
        else:
            R = scale([sum(0.5 * (p[i] + verts[u][i]) for u in t.neighbours[v]) for i in range(3)], 1.0 / n)
        moved.append(vertex_point(F, R, p, n))

    first_face_point = len(verts) + len(edge_points)
    new_faces = []
    for fi, f in enumerate(faces):
        n = len(f)
        for k in range(n):
            before, v, after = f[k - 1], f[k], f[(k + 1) % n]
            new_faces.append([v, edge_index[(min(v, after), max(v, after))], first_face_point + fi,
                              edge_index[(min(before, v), max(before, v))]])
    return moved + edge_points + face_points, new_faces


if __name__ == "__main__":
    main(subdivide)
