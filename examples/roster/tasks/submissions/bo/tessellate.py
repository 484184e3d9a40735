#!/usr/bin/env python3
"""Bo's curve task: the B-spline records read with the Bezier basis matrix."""
import os
import runpy
import sys

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "subjects", "python-curves/tessellate.py")
sys.argv[0] = EXAMPLE
sys.argv += "--bspline-as-bezier".split()
runpy.run_path(EXAMPLE, run_name="__main__")
