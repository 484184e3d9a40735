#!/usr/bin/env python3
"""Bilinear (midpoint) subdivision: every face of n corners becomes n quads through its edge
midpoints and its centroid; old vertices stay. The first step of the course's Catmull-Clark
exercise, before the smoothing. Standard library only.

    python3 bilinear.py IN.obj LEVELS OUT.obj
"""
from polymesh import Tables, centroid, main, with_edge_midpoints


def subdivide(verts, faces):
    new_verts, edge_index = with_edge_midpoints(verts, Tables(verts, faces))
    new_faces = []
    for f in faces:
        centre = len(new_verts)
        new_verts.append(centroid(verts, f))
        n = len(f)
        for k in range(n):
            before, v, after = f[k - 1], f[k], f[(k + 1) % n]
            new_faces.append([v, edge_index[(min(v, after), max(v, after))], centre, edge_index[(min(before, v), max(before, v))]])
    return new_verts, new_faces


if __name__ == "__main__":
    main(subdivide)
