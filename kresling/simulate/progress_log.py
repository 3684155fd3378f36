"""Progress lines for a run whose stderr is no terminal (a log, a batch job), or for the part
of a run before its progress bar: one half a second after the run starts saying what runs
(reading the problem and building its model, then the path), one when the path starts if
that is later, then one every few seconds saying where the path is, from a thread of their
own (the solver runs without the GIL, so the lines come even while one long increment is
solved). A run that ends within half a second logs none."""

from __future__ import annotations

import logging
import threading

__all__ = ["ProgressLog"]

logger = logging.getLogger(__name__)


class ProgressLog:
    """Logs ``what`` after ``first`` seconds (and each later :meth:`begin`), then the
    latest :meth:`update` every ``every`` seconds, until :meth:`close`."""

    def __init__(self, source: str, what: str, *, first: float = 0.5, every: float = 5.0):
        self.source, self.what, self.first, self.every = source, what, first, every
        self.increments, self.load_factor = 0, 0.0
        self._lock = threading.Lock()
        self._said = False    # the first line is out
        self._path = False    # the path has begun: increment lines follow
        self._done = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def begin(self, what: str) -> None:
        """The path begins: ``what`` it is (logged now if the first line is out)."""
        with self._lock:
            self.what, self._path = what, True
            if self._said:
                logger.info("%s: running: %s", self.source, self.what)

    def update(self, increments: int, load_factor: float) -> None:
        """The path's latest accepted increment and its load factor."""
        self.increments, self.load_factor = increments, float(load_factor)

    def close(self) -> None:
        self._done.set()
        if self._thread.is_alive():
            self._thread.join()

    def _run(self) -> None:
        if self._done.wait(self.first):
            return
        with self._lock:
            self._said = True
            logger.info("%s: running: %s", self.source, self.what)
        while not self._done.wait(self.every):
            if self._path:
                logger.info("%s: increment %d, load factor %.4g", self.source,
                            self.increments, self.load_factor)
