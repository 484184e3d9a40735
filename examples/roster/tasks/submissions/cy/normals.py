#!/usr/bin/env python3
"""Cy's vertex normals: the cross product taken the other way round."""
import os
import runpy
import sys

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "subjects", "python-normals/normals.py")
sys.argv[0] = EXAMPLE
sys.argv += "--clockwise".split()
runpy.run_path(EXAMPLE, run_name="__main__")
