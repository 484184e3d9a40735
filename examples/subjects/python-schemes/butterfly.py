#!/usr/bin/env python3
"""Butterfly subdivision as the course notes state it (Dyn, Levin and Gregory 1990): old
vertices stay, each triangle splits into four, and the point of an interior edge (a, b) is

    1/2 (a + b) + 1/8 (the two vertices opposite the edge) - 1/16 (the four wing vertices),

a wing vertex being the one across each of the other edges of the edge's two triangles; where
such an edge is on the boundary, the wing is reflected: x + y - (the triangle's third vertex)
for wing edge (x, y). A boundary edge (a, b) gets the four-point rule along the boundary,
9/16 (a + b) - 1/16 (the boundary vertex before a and the one after b). Standard library only.

    python3 butterfly.py IN.obj LEVELS OUT.obj
"""
from polymesh import Tables, add, combine, main, scale


def wing(t, verts, x, y, opposite):
    """The -1/16 term across wing edge x -> y of a triangle whose third vertex is `opposite`."""
    across = t.third_vertex(y, x)
    if across is not None:
        return verts[across]
    return add(add(verts[x], verts[y]), verts[opposite], -1.0)


def eight_point(t, verts, a, b):
    x = t.third_vertex(a, b)  # the triangle with a -> b
    y = t.third_vertex(b, a)  # the one with b -> a
    p = add(scale(add(verts[a], verts[b]), 0.5), scale(add(verts[x], verts[y]), 0.125))
    for w in (wing(t, verts, b, x, a), wing(t, verts, x, a, b), wing(t, verts, a, y, b), wing(t, verts, y, b, a)):
        p = add(p, w, -1.0 / 16.0)
    return p


def four_point(t, verts, a, b):
    if (a, b) not in t.half_edge:
        a, b = b, a
    return combine(verts, [(t.boundary_before(a), -1.0 / 16.0), (a, 9.0 / 16.0), (b, 9.0 / 16.0),
                           (t.boundary_after(b), -1.0 / 16.0)])


def subdivide(verts, faces, edge_point=eight_point):
    t = Tables(verts, faces)
    new_verts = [list(p) for p in verts]
    edge_index = {}
    for a, b in t.edges:
        edge_index[(a, b)] = len(new_verts)
        new_verts.append(four_point(t, verts, a, b) if t.is_boundary_edge(a, b) else edge_point(t, verts, a, b))
    new_faces = []
    for i, j, k in faces:
        eij, ejk, eki = edge_index[(min(i, j), max(i, j))], edge_index[(min(j, k), max(j, k))], edge_index[(min(k, i), max(k, i))]
        new_faces += [[i, eij, eki], [j, ejk, eij], [k, eki, ejk], [eij, ejk, eki]]
    return new_verts, new_faces


if __name__ == "__main__":
    main(subdivide)
