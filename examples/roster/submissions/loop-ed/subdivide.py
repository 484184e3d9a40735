"""loop-ed: loop, planted fault: corners."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
from faults import submission  # noqa: E402

submission("loop", "corners")
