#!/usr/bin/env python3
"""Ann's curve task: the course-style tessellator as the lecture notes give it."""
import os
import runpy
import sys

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "subjects", "python-curves/tessellate.py")
sys.argv[0] = EXAMPLE
sys.argv += "".split()
runpy.run_path(EXAMPLE, run_name="__main__")
