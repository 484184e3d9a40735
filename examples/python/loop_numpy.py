"""Loop subdivision in numpy, one level: the kind of implementation a course assignment or a
notebook holds, written to be tested by crossdiv (compare_with_opensubdiv.py).

loop_once(V, F, weights="loop" | "warren") -> (V1, F1): old vertices first (in input order),
then one vertex per edge; boundary edges by the midpoint rule, boundary vertices by
(3/4, 1/8, 1/8) (edge-only). Triangle meshes only.
"""
import numpy as np


def loop_once(V, F, weights="loop"):
    V = np.asarray(V, dtype=float)
    F = np.asarray(F, dtype=np.int64)
    n = len(V)
    # Half-edges in blocks: edge 0 (v0 v1), edge 1 (v1 v2), edge 2 (v2 v0) of every face, and
    # the corner opposite each.
    half = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    opposite = np.concatenate([F[:, 2], F[:, 0], F[:, 1]])
    edges, inverse, uses = np.unique(np.sort(half, axis=1), axis=0, return_inverse=True, return_counts=True)
    inverse = inverse.ravel()
    border = uses == 1

    # Edge points: 3/8 of the ends and 1/8 of each opposite corner; the midpoint on the border.
    wings = np.zeros((len(edges), 3))
    np.add.at(wings, inverse, V[opposite])
    edge_points = 3 / 8 * (V[edges[:, 0]] + V[edges[:, 1]]) + wings / 8
    edge_points[border] = (V[edges[border, 0]] + V[edges[border, 1]]) / 2

    # Vertex points: (1 - n beta) v + beta * (sum of the neighbours).
    valence = np.bincount(edges.ravel(), minlength=n).astype(float)
    ring = np.zeros((n, 3))
    np.add.at(ring, edges[:, 0], V[edges[:, 1]])
    np.add.at(ring, edges[:, 1], V[edges[:, 0]])
    with np.errstate(divide="ignore", invalid="ignore"):
        if weights == "warren":
            beta = np.where(valence == 3, 3 / 16, 3 / (8 * valence))
        else:
            beta = (5 / 8 - (3 / 8 + np.cos(2 * np.pi / valence) / 4) ** 2) / valence
    vertex_points = (1 - valence * beta)[:, None] * V + beta[:, None] * ring
    on_border = np.zeros(n, dtype=bool)
    on_border[edges[border].ravel()] = True
    border_ring = np.zeros((n, 3))
    np.add.at(border_ring, edges[border, 0], V[edges[border, 1]])
    np.add.at(border_ring, edges[border, 1], V[edges[border, 0]])
    vertex_points[on_border] = 3 / 4 * V[on_border] + border_ring[on_border] / 8

    # Each triangle into four: corners with the new vertices of their two edges, and the middle.
    m = inverse.reshape(3, -1).T + n
    a, b, c = F.T
    m0, m1, m2 = m.T
    faces = np.concatenate([np.stack([a, m0, m2], 1), np.stack([b, m1, m0], 1), np.stack([c, m2, m1], 1),
                            np.stack([m0, m1, m2], 1)])
    return np.vstack([vertex_points, edge_points]), faces.astype(np.int32)
