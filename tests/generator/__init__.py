"""Tests of the Python generator (stdlib unittest).

Run from the repository root:
    python3 -m unittest discover -s tests/generator -t .

Importing this package puts generator/ on sys.path so the tests can
`import gaphys_gen` without installing it.
"""

import os
import sys

_GENERATOR_DIR = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", "..", "generator"))
if _GENERATOR_DIR not in sys.path:
    sys.path.insert(0, _GENERATOR_DIR)
