#!/usr/bin/env python3
"""Bo's vertex normals: every face weighs the same."""
import os
import runpy
import sys

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "subjects", "python-normals/normals.py")
sys.argv[0] = EXAMPLE
sys.argv += "--uniform".split()
runpy.run_path(EXAMPLE, run_name="__main__")
