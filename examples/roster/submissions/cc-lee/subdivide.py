"""cc-lee: catmull-clark, planted fault: corners-kept."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from faults import submission  # noqa: E402

submission("catmull-clark", "corners-kept")
