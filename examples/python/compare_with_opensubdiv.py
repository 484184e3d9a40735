#!/usr/bin/python3
"""Loads a mesh, compares a numpy Loop (loop_numpy.py) with OpenSubdiv through crossdiv, and
plots where the two part, with matplotlib.

Usage (from the repository, after the build):
    PYTHONPATH=build/python examples/python/compare_with_opensubdiv.py MESH [--weights loop|warren] [-o PNG]
MESH is an OBJ, OFF or PLY file of triangles. With --weights warren the numpy Loop uses Warren's
weights, which OpenSubdiv does not have: crossdiv names the rule it follows and the plot shows
the difference growing with the valence.
"""
import argparse
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.spatial import cKDTree  # noqa: E402

import crossdiv  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from loop_numpy import loop_once  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("mesh")
    parser.add_argument("--weights", default="loop", choices=["loop", "warren"])
    parser.add_argument("--levels", type=int, default=2)
    parser.add_argument("-o", "--output", default="loop_vs_opensubdiv.png")
    args = parser.parse_args()

    V, F = crossdiv.read_mesh(args.mesh)
    mine = lambda V, F: loop_once(V, F, args.weights)  # noqa: E731
    record = crossdiv.compare(V, F, levels=args.levels, references=["opensubdiv"], subject=mine, subject_name="numpy")
    run = record["runs"][0]
    print(f"numpy Loop vs opensubdiv: {run['verdict']} {run.get('divergence_class', '')}: {run['explanation']}")
    print("rule identified:", (record.get("subject", {}).get("rules") or {}).get("rule"))

    # Where they part: our last level against OpenSubdiv's, matched by position.
    ours = (V, F)
    for _ in range(args.levels):
        ours = loop_once(*ours, args.weights)
    ref = crossdiv.subdivide(V, F, levels=args.levels, impl="opensubdiv")
    distance = cKDTree(ref[0]).query(ours[0])[0]

    fig = plt.figure(figsize=(6, 5))
    ax = fig.add_subplot(projection="3d")
    tri = ax.plot_trisurf(*ours[0].T, triangles=ours[1], cmap="inferno", linewidth=0.1, edgecolor=(0, 0, 0, 0.2))
    tri.set_array(distance[ours[1]].max(axis=1))
    fig.colorbar(tri, ax=ax, shrink=0.6, label="distance to OpenSubdiv")
    ax.set_title(f"numpy Loop ({args.weights}) vs OpenSubdiv, level {args.levels}")
    ax.set_axis_off()
    fig.savefig(args.output, dpi=100)
    print(f"largest distance {distance.max():.3g}; figure: {args.output}")


if __name__ == "__main__":
    main()
