#!/usr/bin/env python3
"""The modified Butterfly (Zorin, Schroeder and Sweldens 1996) as the course notes state it:
the Butterfly's eight-point rule (butterfly.py) between two regular vertices (valence 6, or on
the boundary), and around an interior vertex v of valence K != 6 the K-point rule

    3/4 v + sum_j s_j p_j,  s_j = (1/4 + cos(2 pi j / K) + 1/2 cos(4 pi j / K)) / K,

p_0 being the edge's other end and p_j the ring around v (K = 3: 5/12, -1/12, -1/12;
K = 4: 3/8, 0, -1/8, 0); when both ends are such vertices, the average of their two rules.
Valence counts edges. Standard library only.

    python3 modified_butterfly.py IN.obj LEVELS OUT.obj
"""
import math

import butterfly
from polymesh import add, combine, main, scale


def k_point(t, verts, v, first):
    ring = t.ring(v, first)
    K = len(ring)
    if K == 3:
        s = [5.0 / 12.0, -1.0 / 12.0, -1.0 / 12.0]
    elif K == 4:
        s = [3.0 / 8.0, 0.0, -1.0 / 8.0, 0.0]
    else:
        s = [(0.25 + math.cos(2.0 * math.pi * j / K) + 0.5 * math.cos(4.0 * math.pi * j / K)) / K for j in range(K)]
    return combine(verts, [(v, 0.75)] + list(zip(ring, s)))


def edge_point(t, verts, a, b):
    def regular(v):
        return t.on_boundary(v) or len(t.neighbours[v]) == 6
    ra, rb = regular(a), regular(b)
    if ra and rb:
        return butterfly.eight_point(t, verts, a, b)
    if not ra and not rb:
        return scale(add(k_point(t, verts, a, b), k_point(t, verts, b, a)), 0.5)
    return k_point(t, verts, a, b) if not ra else k_point(t, verts, b, a)


def subdivide(verts, faces):
    return butterfly.subdivide(verts, faces, edge_point)


if __name__ == "__main__":
    main(subdivide)
