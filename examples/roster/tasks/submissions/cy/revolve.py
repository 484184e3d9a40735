#!/usr/bin/env python3
"""Cy's surface of revolution: the curve task's planar normal, which points inward here."""
import os
import runpy
import sys

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "subjects", "python-revolve/revolve.py")
sys.argv[0] = EXAMPLE
sys.argv += "--left-normals".split()
runpy.run_path(EXAMPLE, run_name="__main__")
