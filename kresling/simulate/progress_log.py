"""Progress lines for a run whose stderr is no terminal (a log file, a batch job): one
after the first second saying what runs, then one every few seconds saying where the path
is, from a thread of their own (the solver runs without the GIL, so the lines come even
while one long increment is solved). A run that ends within a second logs none."""

from __future__ import annotations

import logging
import threading

__all__ = ["ProgressLog"]

logger = logging.getLogger(__name__)


class ProgressLog:
    """Logs ``what`` after ``first`` seconds, then the latest :meth:`update` every
    ``every`` seconds, until :meth:`close`."""

    def __init__(self, source: str, what: str, *, first: float = 1.0, every: float = 5.0):
        self.source, self.what, self.first, self.every = source, what, first, every
        self.increments, self.load_factor = 0, 0.0
        self._done = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def update(self, increments: int, load_factor: float) -> None:
        """The path's latest accepted increment and its load factor."""
        self.increments, self.load_factor = increments, float(load_factor)

    def close(self) -> None:
        self._done.set()
        self._thread.join()

    def _run(self) -> None:
        if self._done.wait(self.first):
            return
        logger.info("%s: running: %s", self.source, self.what)
        while not self._done.wait(self.every):
            logger.info("%s: increment %d, load factor %.4g", self.source, self.increments,
                        self.load_factor)
