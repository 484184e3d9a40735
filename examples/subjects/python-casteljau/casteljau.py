#!/usr/bin/env python3
"""The course's de Casteljau task in Python, standard library only: read a BZC file (the
number of control points, then their x y coordinates), and write every level of the
construction at t, one line per level, from the control points down to the point on the curve:

    python3 casteljau.py IN.bzc T OUT.txt [--swapped]

--swapped takes t * p_i + (1 - t) * p_(i+1), the weights the wrong way round (the classic slip,
which evaluates at 1 - t: crossdiv names it).
"""
import sys


def main():
    src, t, out = sys.argv[1], float(sys.argv[2]), sys.argv[3]
    swapped = "--swapped" in sys.argv[4:]
    words = open(src).read().split()
    n = int(words[0])
    numbers = [float(w) for w in words[1:]]
    level = [numbers[2 * i:2 * i + 2] for i in range(n)]
    a, b = (t, 1 - t) if swapped else (1 - t, t)
    with open(out, "w") as f:
        while level:
            f.write(" ".join(repr(c) for p in level for c in p) + "\n")
            level = [[a * p[k] + b * q[k] for k in range(2)] for p, q in zip(level, level[1:])]


if __name__ == "__main__":
    main()
