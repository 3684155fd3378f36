"""``sweep``: many designs through the chosen metrics, in parallel, resumable from disk."""

from __future__ import annotations

import logging
import time
from collections import deque
from concurrent.futures import FIRST_COMPLETED, BrokenExecutor, wait

import numpy as np
from tqdm.auto import tqdm

from kresling import __version__
from kresling._validation import as_integer
from kresling.sweeps.designs import DesignSet, as_design_set
from kresling.sweeps.executors import make_executor
from kresling.sweeps.metrics import require_even_n, resolve_metrics
from kresling.sweeps.store import SweepStore
from kresling.sweeps.table import DESIGN_COLUMNS, FAILED, OK, STATUS_COLUMNS, SweepTable
from kresling.sweeps.worker import Plan, make_plan, run_chunk

__all__ = ["sweep", "DEFAULT_METRICS"]

logger = logging.getLogger(__name__)

DEFAULT_METRICS = ("kb_ratio", "psi_ratio")
_FORMAT = "kresling-sweep/1"
_MAX_CHUNK = 32


def sweep(designs, metrics=DEFAULT_METRICS, *, workers=None, executor=None, out=None,
          progress=True, chunk_size=None, parameters=None) -> SweepTable:
    """Compute ``metrics`` for every design, in parallel; write to and resume from ``out``.

    Parameters
    ----------
    designs : DesignSet, iterable of Design, or mapping of columns
        E.g. :func:`~kresling.sweeps.design_grid` (the thesis's 100 x 100 x 4 grid).
    metrics : sequence of str or Metric, default ("kb_ratio", "psi_ratio")
        Names from :data:`~kresling.sweeps.METRICS`. Each adds its columns; metrics that
        share an analysis run it once per design.
    workers : int, optional
        Parallel workers; default every core. With ``executor`` given, twice this many
        chunks are kept in flight.
    executor : {"threads", "processes"}, concurrent.futures.Executor, or dask Client, optional
        Threads by default (the C++ runs release the GIL). Any Executor works: with
        ``dask.distributed`` pass ``client`` or ``client.get_executor()``.
    out : str or Path, optional
        Directory for ``results.csv`` (appended chunk by chunk) and ``manifest.json``. An
        existing directory of the same sweep is resumed: designs already on disk are read
        back, not recomputed. One of a different sweep is refused.
    progress : bool, default True
        A progress bar (designs done, rate, ETA) on stderr when it is a terminal.
    chunk_size : int, optional
        Designs per task; default up to 32, smaller so each worker gets about 16 chunks.
    parameters : SpecimenParameters, optional
        The specimens' material and model (crease stiffness ``kf`` [N/rad], the other
        elements' ratios to it, cut or intact mountain creases, MERLIN2's duplicated
        elements or one per edge); default the thesis's. Recorded in the manifest: a
        directory is resumed only under the same parameters.

    Returns
    -------
    SweepTable
        One row per design, in the order of ``designs``: ``n, Lc, lam, R``, every metric's
        columns, ``status``, ``reason``, ``iterations``, ``seconds``, ``index``.
        ``attrs["computed"]`` counts the designs computed by this call;
        ``attrs["parameters"]`` holds the specimen parameters (``SpecimenParameters.as_dict``).

    Raises
    ------
    ValueError
        For no designs, an invalid design, an unknown or repeated metric, an odd n with a
        bending metric, ``workers < 1``, a bad executor, ``parameters`` that are not a
        SpecimenParameters, or an ``out`` that holds a different sweep (other designs,
        metrics or parameters: the message names what differs, with both values).

    Notes
    -----
    A design whose analysis fails (an increment that does not converge, an exception) is a
    row with ``status = "failed"``, NaN metrics and the reason; the sweep goes on. Ctrl-C
    stops the sweep with every finished chunk saved; run the same call again to resume.

    Examples
    --------
    >>> from kresling.sweeps import design_grid, sweep
    >>> table = sweep(design_grid((8,), 3), ["psi_ratio"], workers=1, progress=False)
    >>> table.best("psi_ratio")["Lc"], table.best("psi_ratio")["lam"]
    (15.0, 0.9)
    """
    start = time.perf_counter()
    if chunk_size is not None:
        chunk_size = as_integer("chunk_size", chunk_size, minimum=1)
    design_set = as_design_set(designs)
    metrics = resolve_metrics(metrics)
    parameters = _parameters(parameters)
    plan = _plan(metrics, design_set, parameters)
    handle = make_executor(executor, workers)
    columns = (*DESIGN_COLUMNS, *plan.columns, *STATUS_COLUMNS)
    store = None
    if out is not None:
        try:
            store = SweepStore.open(out, _manifest(metrics, plan, columns, design_set,
                                                   parameters),
                                    check_row=_row_checker(design_set, columns))
        except BaseException:
            handle.shutdown(interrupted=True)
            raise
    done = {} if store is None else dict(store.rows)
    loaded = len(done)
    pending = [i for i in range(len(design_set)) if i not in done]
    size = max(1, min(_MAX_CHUNK, len(pending) // (16 * handle.workers))) \
        if chunk_size is None else chunk_size
    logger.info("sweep: %d designs (%d on disk), metrics %s, %s, chunks of %d",
                len(design_set), loaded, ", ".join(m.name for m in metrics),
                _describe_workers(handle), size)
    bar = tqdm(total=len(design_set), initial=loaded, unit="design", desc="sweep",
               disable=None if progress else True, smoothing=0.05, dynamic_ncols=True)
    interrupted = True
    try:
        _run(handle, plan, design_set, pending, size, done, store, bar)
        interrupted = False
    finally:
        bar.close()
        handle.shutdown(interrupted)
        if interrupted and store is not None:
            logger.warning("sweep interrupted: %d of %d designs saved in %s; run it again to "
                           "resume", len(done), len(design_set), store.directory)
            store.close()
    rows = [done[i] for i in range(len(design_set))]
    seconds = time.perf_counter() - start
    table = SweepTable(dict(zip(columns, map(list, zip(*rows)))), {
        "metrics": [m.name for m in metrics], "computed": len(pending), "loaded": loaded,
        "seconds": seconds, "workers": handle.workers, "out": None if out is None else str(out),
        "parameters": parameters.as_dict()})
    failed = int((table["status"] != OK).sum())
    if store is not None:
        store.finish(rows, {"failed": failed, "seconds_last_run": round(seconds, 3)})
    logger.info("sweep: %d designs computed, %d loaded, %d failed, %.1f s", len(pending),
                loaded, failed, seconds)
    return table


def _describe_workers(handle) -> str:
    """``"2 threads"``, ``"1 process"``, ``"8 workers of the given executor"``."""
    count = handle.workers
    if handle.kind == "threads":
        return f"{count} thread{'s' if count != 1 else ''}"
    if handle.kind == "processes":
        return f"{count} process{'es' if count != 1 else ''}"
    return f"{count} worker{'s' if count != 1 else ''} of the given executor"


def _parameters(parameters):
    """``parameters`` checked, the thesis's when None."""
    from kresling.model import SpecimenParameters

    if parameters is None:
        return SpecimenParameters()
    if not isinstance(parameters, SpecimenParameters):
        raise ValueError(f"parameters = {parameters!r} is invalid: must be a "
                         f"kresling.model.SpecimenParameters")
    return parameters


def _plan(metrics, design_set: DesignSet, parameters) -> Plan:
    require_even_n(metrics, np.unique(design_set.n))
    return make_plan(metrics, parameters)


def _manifest(metrics, plan: Plan, columns, design_set: DesignSet, parameters) -> dict:
    return {"format": _FORMAT, "kresling": __version__,
            "metrics": [m.name for m in metrics], "columns": list(columns),
            "analyses": {a.name: a.settings for a in plan.analyses},
            "parameters": parameters.as_dict(),
            "designs": {"count": len(design_set), "sha256": design_set.key,
                        "spec": design_set.spec}}


def _design_values(design_set: DesignSet, i: int) -> tuple:
    return (int(design_set.n[i]), float(design_set.Lc[i]), float(design_set.lam[i]),
            float(design_set.R[i]))


def _row_checker(design_set: DesignSet, columns):
    position = {name: k for k, name in enumerate(columns)}

    def check(row):
        i = row[position["index"]]
        if not 0 <= i < len(design_set) or tuple(row[position[c]] for c in DESIGN_COLUMNS) \
                != _design_values(design_set, i):
            raise ValueError(f"a row of results.csv (index {i}) is not design {i} of this sweep")
    return check


def _run(handle, plan, design_set, pending, size, done, store, bar) -> None:
    """Submit chunks (a bounded number in flight) and record each as it finishes; ``done``
    maps design index to its row in column order.

    A chunk lost to its worker (a process that died, a task the executor dropped) makes its
    designs suspects: each is then run alone, with nothing else in flight, and one that is
    lost again is recorded as failed. On an interruption (Ctrl-C) the chunks that had already
    finished are recorded before it propagates.
    """
    queue = deque([pending[k:k + size] for k in range(0, len(pending), size)])
    suspects, in_flight = deque(), {}

    def record(results):
        rows = [(*_design_values(design_set, r[0]), *r[1:], r[0]) for r in results]
        if store is not None:
            store.append(rows)
        for row in rows:
            done[row[-1]] = row
        bar.update(len(rows))

    def submit(indices, alone=False):
        chunk = [(i, *_design_values(design_set, i)) for i in indices]
        try:
            future = handle.executor.submit(run_chunk, plan, chunk)
        except BrokenExecutor as error:
            _rebuild(handle, error)
            future = handle.executor.submit(run_chunk, plan, chunk)
        in_flight[future] = (indices, handle.executor, alone)

    try:
        while queue or suspects or in_flight:
            if suspects:
                if not in_flight:
                    submit([suspects.popleft()], alone=True)
            else:
                while queue and len(in_flight) < 2 * handle.workers:
                    submit(queue.popleft())
            finished, _ = wait(in_flight, return_when=FIRST_COMPLETED)
            for future in finished:
                indices, executor, alone = in_flight.pop(future)
                try:
                    record(future.result())
                except Exception as error:  # noqa: BLE001 - a worker died or the task was lost
                    if isinstance(error, BrokenExecutor) and executor is handle.executor:
                        _rebuild(handle, error)
                    logger.warning("a worker was lost on designs %s%s: %s: %s", indices[:5],
                                   "..." if len(indices) > 5 else "", type(error).__name__, error)
                    if alone:
                        record([_failed_row(plan, indices[0], error)])
                    else:
                        suspects.extend(indices)
    except BaseException:
        for future in in_flight:
            future.cancel()
        for future in in_flight:
            if future.done() and not future.cancelled() and future.exception() is None:
                record(future.result())
        raise


def _rebuild(handle, error) -> None:
    if not handle.rebuild():
        raise RuntimeError(f"the executor broke ({error}); finished chunks are saved: run the "
                           f"sweep again to resume") from error


def _failed_row(plan, index, error) -> tuple:
    reason = f"its worker was lost twice, the second time running it alone: " \
             f"{type(error).__name__}: {error}".replace("\n", " ")
    return (index, *([np.nan] * len(plan.columns)), FAILED, reason, 0, 0.0)
