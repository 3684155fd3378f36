"""What every fuzz target shares: its settings, junk values, and the property itself.

The property of every public entry point: it returns a finite result or a result that says
why it stopped, or raises a ValueError whose message names the parameter (for a file: the
file) - never another exception, a hang or a silent NaN.

Example counts: each target names its count for the normal test suite (a few seconds), with
hypothesis derandomized (the same examples on every run, so CI is deterministic).
``KRESLING_FUZZ_SCALE=N`` (``make fuzz``) runs N times as many, from a random seed (printed
on failure; ``--hypothesis-seed`` replays it).
"""

from __future__ import annotations

import math
import os

import numpy as np
from hypothesis import HealthCheck, event, settings
from hypothesis import strategies as st

SCALE = float(os.environ.get("KRESLING_FUZZ_SCALE", "1"))


def fuzz(examples: int):
    """Settings of a fuzz target: ``examples`` in the test suite, SCALE times as many (from
    a random seed) under ``make fuzz``."""
    return settings(max_examples=max(1, int(round(examples * SCALE))), deadline=None,
                    derandomize=SCALE == 1, database=None, print_blob=True,
                    suppress_health_check=list(HealthCheck))


#: Values of the wrong type or out of every range: what a user can pass by mistake.
junk = st.one_of(
    st.none(), st.booleans(), st.integers(-2**70, 2**70),
    st.floats(allow_nan=True, allow_infinity=True), st.sampled_from([0, 1, -1, 2**31, 2**63,
                                                                     10**30, 5e-324, -1e-310]),
    st.text(max_size=6), st.lists(st.integers(-3, 3), max_size=3),
    st.dictionaries(st.text(max_size=3), st.integers(-2, 2), max_size=2),
    st.just(float("nan")), st.just(float("inf")), st.just(object()), st.just(1 + 2j))

#: Numbers near and beyond every boundary.
edgy_floats = st.one_of(st.floats(allow_nan=True, allow_infinity=True),
                        st.sampled_from([0.0, -0.0, 1e-300, 5e-324, -1e-310, 1e300, 1e308,
                                         0.5, 1.0, 1e-12, 1e12]))
edgy_ints = st.one_of(st.integers(-10, 40), st.sampled_from([2**31 - 1, 2**31, -2**31 - 1,
                                                             10**20]))


def mostly(valid, *bad):
    """``valid`` three times in four, else one of ``bad``: most examples then reach deep
    into the call instead of stopping at the first check."""
    if not bad:
        return valid
    invalid = st.one_of(*bad)
    return st.integers(0, 3).flatmap(lambda k: valid if k < 3 else invalid)


def named(error: ValueError, *names) -> None:
    """Assert that ``error``'s message names one of ``names`` (a parameter or a file)."""
    message = str(error)
    assert message.strip(), f"a ValueError without a message: {error!r}"
    assert any(str(name) in message for name in names), \
        f"the message names none of {names}: {message!r}"


def attempt(call, *names):
    """``call()``'s result, or None if it raised a ValueError naming one of ``names``; any
    other exception propagates (the property fails)."""
    try:
        result = call()
    except ValueError as error:
        named(error, *names)
        event("ValueError")
        return None
    event("result")
    return result


def finite(*arrays) -> None:
    """Assert every number in ``arrays`` is finite (arrays, floats, nested lists)."""
    for a in arrays:
        values = np.asarray(a, dtype=float)
        assert np.isfinite(values).all(), f"not finite: {values}"


def finite_or_nan_with_reason(value, reason: str) -> None:
    """A scalar result: finite, or NaN with a non-empty reason (never inf, never unexplained)."""
    assert not math.isinf(value), f"inf result ({reason!r})"
    if math.isnan(value):
        assert reason.strip(), "NaN without a reason"


def path_ok(path) -> None:
    """A solver's PathResult: finite numbers; not completed means it says why."""
    finite(path.load_factor, path.displacement, path.constraint_force, path.energy)
    assert path.completed or path.message.strip(), "stopped without a message"


def mutated(data: bytes, cuts, insertions) -> bytes:
    """``data`` with bytes cut out and words spliced in at drawn positions."""
    data = bytearray(data)
    for position, length in cuts:
        position %= max(len(data), 1)
        del data[position:position + length]
    for position, word in insertions:
        position %= max(len(data) + 1, 1)
        data[position:position] = word
    return bytes(data)
