"""The tests. A test run caches the modules it compiles (``__pycache__``, which git
ignores) even where the environment asks for none (``PYTHONDONTWRITEBYTECODE``): both test
processes and every server a test starts import the same app and tests, and compiling them
again in each cost about 25 s of CPU a run."""

import os
import sys

sys.dont_write_bytecode = False
os.environ.pop("PYTHONDONTWRITEBYTECODE", None)
