#!/usr/bin/env python3
"""Midpoint subdivision of a triangle mesh: every triangle becomes four through its edge
midpoints; old vertices stay. The first step of the course's Loop exercise, before the
smoothing (and the linear subdivision of VTK and Open3D). Standard library only.

    python3 midpoint.py IN.obj LEVELS OUT.obj
"""
import sys

from polymesh import Tables, key, main, with_edge_midpoints


def subdivide(verts, faces):
    for f in faces:
        if len(f) != 3:
            sys.exit(f"midpoint subdivision refines triangles; a face has {len(f)} corners")
    new_verts, edge_index = with_edge_midpoints(verts, Tables(verts, faces))
    new_faces = []
    for v0, v1, v2 in faces:
        m01, m12, m20 = edge_index[key(v0, v1)], edge_index[key(v1, v2)], edge_index[key(v2, v0)]
        new_faces += [[v0, m01, m20], [v1, m12, m01], [v2, m20, m12], [m01, m12, m20]]
    return new_verts, new_faces


if __name__ == "__main__":
    main(subdivide)
