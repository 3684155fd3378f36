"""Running the ``kresling`` command line in a subprocess, as a user would."""

import json
import subprocess
import sys


def run_kresling(*args, cwd, timeout=300):
    """``python -m kresling ARGS`` in ``cwd``; returns the CompletedProcess (text output)."""
    return subprocess.run([sys.executable, "-m", "kresling", *args], capture_output=True,
                          text=True, cwd=cwd, timeout=timeout)


def run_kresling_json(*args, cwd):
    """``python -m kresling ARGS --json`` in ``cwd``, which must succeed; its JSON output."""
    result = run_kresling(*args, "--json", cwd=cwd)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)
