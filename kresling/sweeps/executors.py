"""Where a sweep's chunks run: threads, a process pool, or any ``concurrent.futures.Executor``
(a ``dask.distributed`` cluster through ``client.get_executor()``, or the client itself).

Threads are the default: the C++ bending test releases the GIL, so threads use every core
without starting processes or pickling results. Processes isolate a crash in the C++ core
(a pool the sweep owns is rebuilt when a worker dies).
"""

from __future__ import annotations

import ctypes
import multiprocessing
import os
import signal
import sys
from concurrent.futures import Executor, ProcessPoolExecutor, ThreadPoolExecutor

__all__ = ["ExecutorHandle", "default_workers", "make_executor"]

KINDS = ("threads", "processes")
#: Most threads or processes a sweep starts on this machine (a cluster may have more).
MAX_LOCAL_WORKERS = 1024


def default_workers() -> int:
    """The cores this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - not Linux
        return os.cpu_count() or 1


class ExecutorHandle:
    """An executor and whether the sweep owns it (may shut it down and rebuild it)."""

    def __init__(self, kind: str | None, workers: int, executor: Executor | None = None):
        self.kind = kind
        self.workers = workers
        self.owned = executor is None
        self.executor = executor if executor is not None else self._new()

    def _new(self) -> Executor:
        if self.kind == "processes":
            # spawn: workers start clean (no threads or locks inherited from the parent).
            return ProcessPoolExecutor(self.workers,
                                       mp_context=multiprocessing.get_context("spawn"),
                                       initializer=_die_with_parent, initargs=(os.getpid(),))
        return ThreadPoolExecutor(self.workers, thread_name_prefix="kresling-sweep")

    def rebuild(self) -> bool:
        """Replace a broken pool the sweep owns; False if it cannot (not ours)."""
        if not self.owned:
            return False
        self.executor.shutdown(wait=False, cancel_futures=True)
        self.executor = self._new()
        return True

    def shutdown(self, interrupted: bool = False) -> None:
        if not self.owned:
            return
        if interrupted and isinstance(self.executor, ProcessPoolExecutor):
            # The workers would finish the chunk they are on (up to a minute) before
            # noticing; their results are not wanted: stop them now.
            for process in list((getattr(self.executor, "_processes", None) or {}).values()):
                if process.is_alive():
                    process.terminate()
        self.executor.shutdown(wait=not interrupted, cancel_futures=True)


def _die_with_parent(parent: int) -> None:
    """In a worker process: ask Linux to end it (SIGTERM) when the sweep's process dies, even
    by SIGKILL, so that no worker outlives a killed sweep. Elsewhere: nothing."""
    if not sys.platform.startswith("linux"):
        return
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(1, signal.SIGTERM)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):  # pragma: no cover - no prctl
        return
    if os.getppid() != parent:  # the parent died before the call
        os._exit(1)


def make_executor(executor, workers) -> ExecutorHandle:
    """Resolve ``sweep``'s ``executor`` and ``workers`` arguments.

    Parameters
    ----------
    executor : None, "threads", "processes", Executor, or dask.distributed.Client
    workers : int or None
        Parallel workers (default: every core, or every thread of a Dask cluster). With an
        executor passed in, the number of chunks kept in flight is twice this.

    Raises
    ------
    ValueError
        For ``workers < 1`` or an executor of an unknown kind.
    """
    if workers is None and callable(getattr(executor, "nthreads", None)):
        workers = max(1, sum(executor.nthreads().values()))  # a dask.distributed.Client
    if workers is None:
        workers = default_workers()
    if isinstance(workers, bool) or not isinstance(workers, int) or workers < 1:
        raise ValueError(f"workers = {workers!r} is invalid: must be an integer >= 1")
    if executor is None or isinstance(executor, str):
        kind = executor or "threads"
        if kind not in KINDS:
            raise ValueError(f"executor = {executor!r} is invalid: must be one of "
                             f"{', '.join(KINDS)}, or a concurrent.futures.Executor")
        if workers > MAX_LOCAL_WORKERS:  # a pool of this machine starts that many
            raise ValueError(f"workers = {workers} is invalid for {kind} on this machine: must "
                             f"be an integer >= 1 and <= {MAX_LOCAL_WORKERS}")
        return ExecutorHandle(kind, workers)
    if not isinstance(executor, Executor) and callable(getattr(executor, "get_executor", None)):
        executor = executor.get_executor()  # a dask.distributed.Client
    if not isinstance(executor, Executor):
        raise ValueError(f"executor = {executor!r} is invalid: must be 'threads', 'processes', "
                         f"a concurrent.futures.Executor or a dask.distributed.Client")
    return ExecutorHandle(None, workers, executor)
