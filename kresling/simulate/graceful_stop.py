"""Stopping a run from outside without losing it: Ctrl-C (SIGINT) or ``kill`` (SIGTERM)
ends the path at its next converged increment, and the run keeps, and writes, every
increment before it; a second Ctrl-C stops at once.

The solvers ask a stopping rule after every accepted increment; the handlers here only note
the request, and the rule ends the path there. A handler is installed only in the main
thread and only where the signal has its usual action (not where a caller ignores it, as a
job started with ``nohup`` or SIGINT ignored does, nor where a caller installed its own).
"""

from __future__ import annotations

import signal
import threading

__all__ = ["GracefulStop"]


class GracefulStop:
    """A context in which SIGINT and SIGTERM request the path to end at its next increment.

    Attributes
    ----------
    requested : str
        The signal's name ("SIGINT", "SIGTERM") once one arrived, else "".
    """

    @property
    def listening(self) -> bool:
        """Whether a handler is installed (the main thread, signals with their usual
        action), so that a request can arrive."""
        return bool(self._previous)

    def __init__(self):
        self.requested = ""
        self._previous = {}

    def __enter__(self) -> "GracefulStop":
        if threading.current_thread() is not threading.main_thread():
            return self
        usual = {signal.SIGINT: signal.default_int_handler, signal.SIGTERM: signal.SIG_DFL}
        for number, default in usual.items():
            if signal.getsignal(number) is default:
                self._previous[number] = signal.signal(number, self._note)
        return self

    def __exit__(self, *exc) -> None:
        for number, handler in self._previous.items():
            signal.signal(number, handler)
        self._previous = {}

    def _note(self, number, frame) -> None:
        if self.requested and number == signal.SIGINT:
            raise KeyboardInterrupt  # a second Ctrl-C: now
        self.requested = signal.Signals(number).name
