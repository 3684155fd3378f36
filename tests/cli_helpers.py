"""Running the ``kresling`` command line in a subprocess, as a user would."""

import subprocess
import sys


def run_kresling(*args, cwd, timeout=300):
    """``python -m kresling ARGS`` in ``cwd``; returns the CompletedProcess (text output)."""
    return subprocess.run([sys.executable, "-m", "kresling", *args], capture_output=True,
                          text=True, cwd=cwd, timeout=timeout)
