"""Helpers of the bad-input tests of every layer: the command line run in this process, its
one-line error, and a Kresling cell driven down (the model most of them feed bad input)."""


import numpy as np

from kresling import Design
from kresling.cli import main
from kresling.model.kresling_specimen import kresling_specimen


def run_cli(capsys, *argv):
    """``kresling ARGV`` in this process: (exit status, stdout, stderr)."""
    status = main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def assert_one_line_error(status, err, command, *fragments):
    assert status == 2, err
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"kresling {command}: error: "), err
    for fragment in fragments:
        assert fragment in lines[0], lines[0]


def driven_cell(n=4, lam=0.7, Lc=30.0):
    """One cell, bottom polygon fixed, top polygon driven down 5 mm; (model, prescribed)."""
    specimen = kresling_specimen(Design(n, lam, Lc), [1])
    fixed = np.zeros((specimen.model.num_nodes, 3), dtype=bool)
    fixed[specimen.level_nodes(0)] = True
    model = specimen.model.replace(fixed=fixed)
    prescribed = np.zeros((model.num_nodes, 3))
    prescribed[specimen.level_nodes(1), 2] = -5.0
    return model, prescribed
