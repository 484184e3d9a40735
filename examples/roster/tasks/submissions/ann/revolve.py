#!/usr/bin/env python3
"""Ann's surface of revolution: the profile's outward normal rotated with it."""
import os
import runpy
import sys

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..", "subjects", "python-revolve/revolve.py")
sys.argv[0] = EXAMPLE
sys.argv += "".split()
runpy.run_path(EXAMPLE, run_name="__main__")
