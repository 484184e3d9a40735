#!/usr/bin/env python3
"""sqrt3 subdivision as the course notes state it (Kobbelt 2000): insert each triangle's
centroid, move each interior vertex of valence n to

    (1 - alpha_n) v + alpha_n / n * (sum of its neighbours),  alpha_n = (4 - 2 cos(2 pi / n)) / 9,

and flip every old interior edge, so that it joins the centroids on its two sides. A
boundary edge keeps its triangle (a, b, centroid) and boundary vertices stay where they are:
the exercise does not ask for Kobbelt's ternary boundary rule. Standard library only.

    python3 sqrt3.py IN.obj LEVELS OUT.obj
"""
import math
from polymesh import Tables, add, centroid, main, scale


def subdivide(verts, faces):
    t = Tables(verts, faces)
    new_verts = []
    for v, p in enumerate(verts):
        n = len(t.neighbours[v])
        if t.on_boundary(v) or n == 0:
            new_verts.append(list(p))
            continue
        alpha = (4.0 - 2.0 * math.cos(2.0 * math.pi / n)) / 9.0
        ring = [sum(verts[u][i] for u in t.neighbours[v]) for i in range(3)]
        new_verts.append(add(scale(p, 1.0 - alpha), ring, alpha / n))
    first_centroid = len(new_verts)
    new_verts += [centroid(verts, f) for f in faces]
    new_faces = []
    for a, b in t.edges:
        f = t.half_edge[(a, b)][0] if (a, b) in t.half_edge else t.half_edge[(b, a)][0]
        if t.is_boundary_edge(a, b):
            x, y = (a, b) if (a, b) in t.half_edge else (b, a)
            new_faces.append([x, y, first_centroid + f])
            continue
        g = t.half_edge[(b, a)][0]
        # a -> b has f on its left and g on its right: the quad a, c_g, b, c_f split the other way.
        cf, cg = first_centroid + t.half_edge[(a, b)][0], first_centroid + g
        new_faces.append([a, cg, cf])
        new_faces.append([cg, b, cf])
    return new_verts, new_faces


if __name__ == "__main__":
    main(subdivide)
