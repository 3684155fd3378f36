"""Metrics with scripted behaviour for the sweep tests: one that fails on some designs, one
that kills its worker process, one that raises KeyboardInterrupt (a Ctrl-C stand-in).

Module-level, so process pools can unpickle them (the tests directory is on sys.path).
"""

import math
import os

from kresling.sweeps import Analysis, Evaluation, Metric

#: Set to a (n, Lc, lam) in a test to make ``interrupting`` raise KeyboardInterrupt there.
INTERRUPT_AT = []


def _is(design, n, Lc, lam):
    return design.n == n and design.Lc == Lc and design.lam == lam


def _failing(_tester, design):
    if design.lam == 0.9 and design.Lc == 15.0:
        raise RuntimeError("scripted failure\nsecond line")
    if design.lam == 0.7 and design.Lc == 15.0:
        return Evaluation({"fake": math.nan}, 3, "did not converge (scripted)")
    return Evaluation({"fake": design.psi_ratio}, 1)


def _crashing(_tester, design):
    if _is(design, 4, 60.0, 0.9):
        os._exit(3)  # the worker process dies without a word
    return Evaluation({"fake": design.psi_ratio}, 1)


def _interrupting(_tester, design):
    if INTERRUPT_AT and _is(design, *INTERRUPT_AT[0]):
        raise KeyboardInterrupt
    return Evaluation({"fake": design.psi_ratio}, 1)


def fake_metric(name, evaluate):
    return Metric(name, Analysis(f"fake_{name}", ("fake",), evaluate), ("fake",))


FAILING = fake_metric("failing", _failing)
CRASHING = fake_metric("crashing", _crashing)
INTERRUPTING = fake_metric("interrupting", _interrupting)
