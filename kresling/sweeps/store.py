"""A sweep's directory on disk: written as it goes, resumable after any interruption.

``DIR/manifest.json`` says what the sweep is (designs, metrics, analysis settings); it is
written before the first result. ``DIR/results.csv`` gets the rows in completion order, a
chunk at a time, each chunk flushed and fsynced before the sweep counts it as done. When the
sweep ends the file is rewritten in design order (atomically) and the manifest marked
complete.

Opening a directory again reads back every complete row (a line cut short by a crash is
dropped, and the file truncated to the last whole line), so only the missing designs are
computed. A directory holding a different sweep is refused rather than mixed. A lock file
(``.lock``, removed when the sweep ends or is interrupted) keeps two processes from writing one
directory at once.
"""

from __future__ import annotations

import json
import logging
import os
from datetime import datetime, timezone
from pathlib import Path

from kresling._validation import csv_cells, show
from kresling.sweeps.table import column_kind, format_row, parse_value

try:  # POSIX; without it the directory is simply not locked
    import fcntl
except ImportError:  # pragma: no cover
    fcntl = None

__all__ = ["SweepStore", "RESULTS", "MANIFEST"]

logger = logging.getLogger(__name__)

RESULTS, MANIFEST, _LOCK = "results.csv", "manifest.json", ".lock"
# Manifest entries that must agree for a directory to be resumed.
_IDENTITY = ("format", "metrics", "columns", "analyses", "parameters", "designs")


class SweepStore:
    """The results directory of one sweep (use :meth:`open`)."""

    def __init__(self, directory: Path, manifest: dict, rows: dict, lock):
        self.directory = directory
        self.manifest = manifest
        #: Rows read back from disk, by design index (each a tuple in column order).
        self.rows = rows
        self._lock = lock

    @property
    def results_path(self) -> Path:
        return self.directory / RESULTS

    @classmethod
    def open(cls, directory, manifest: dict, check_row=None) -> "SweepStore":
        """Create ``directory`` for a new sweep, or reopen it to resume the same sweep.

        Parameters
        ----------
        directory : str or Path
        manifest : dict
            What the sweep is; ``manifest["columns"]`` is the CSV header.
        check_row : callable, optional
            ``check_row(row)`` raises ValueError if a row read back does not belong to this
            sweep's designs.

        Raises
        ------
        ValueError
            If the directory holds a different sweep, results without a manifest, a damaged
            line before the last, or is being written by another process.
        """
        directory = Path(directory)
        directory.mkdir(parents=True, exist_ok=True)
        lock = _acquire(directory / _LOCK)
        try:
            manifest_path, results_path = directory / MANIFEST, directory / RESULTS
            if manifest_path.exists():
                found = _read_manifest(manifest_path)
                _check_same(directory, found, manifest)
                manifest = dict(found, complete=False)
            elif results_path.exists():
                raise ValueError(f"{directory} holds {RESULTS} but no {MANIFEST}: not a "
                                 f"sweep directory this package wrote; use another directory")
            else:
                manifest = dict(manifest, created=_now(), complete=False)
            _write_atomic(manifest_path, json.dumps(manifest, indent=2))
            rows = _read_rows(results_path, manifest["columns"], check_row)
            if not results_path.exists():
                _write_atomic(results_path, format_row(manifest["columns"]))
        except BaseException:
            _release(lock)
            raise
        return cls(directory, manifest, rows, lock)

    def append(self, rows) -> None:
        """Append ``rows`` (tuples in column order) and make them durable."""
        if not rows:
            return
        with open(self.results_path, "a", newline="") as f:
            f.write("".join(format_row(row) for row in rows))
            f.flush()
            os.fsync(f.fileno())

    def finish(self, ordered_rows, summary: dict) -> None:
        """Rewrite the results in design order, mark the manifest complete, unlock."""
        text = format_row(self.manifest["columns"]) + "".join(format_row(r) for r in ordered_rows)
        _write_atomic(self.results_path, text)
        self.manifest = dict(self.manifest, complete=True, finished=_now(), **summary)
        _write_atomic(self.directory / MANIFEST, json.dumps(self.manifest, indent=2))
        self.close()

    def close(self) -> None:
        """Release the directory's lock (rows already appended stay)."""
        _release(self._lock)
        self._lock = None


def _read_manifest(path: Path) -> dict:
    """The manifest on disk; a damaged one (cut short, not JSON, not an object) is a
    ValueError naming the file."""
    data = path.read_bytes()
    try:
        manifest = json.loads(data.decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as error:
        raise ValueError(f"{path} is damaged (not JSON: {error}); it says what sweep the "
                         f"directory holds: delete the directory to start again") from None
    if not isinstance(manifest, dict) or not isinstance(manifest.get("columns"), list):
        raise ValueError(f"{path} is damaged (not a sweep manifest: no list of columns); "
                         f"delete the directory to start again")
    return manifest


def _identity(manifest: dict, key: str):
    value = manifest.get(key)
    if key == "designs" and isinstance(value, dict):  # the values, not how they were made
        return value.get("count"), value.get("sha256")
    if key == "parameters" and value is None:
        # Written before sweeps took parameters: those ran with the thesis's.
        from kresling.model import SpecimenParameters

        return SpecimenParameters().as_dict()
    return value


def _check_same(directory: Path, found: dict, wanted: dict) -> None:
    differ = [key for key in _IDENTITY if _identity(found, key) != _identity(wanted, key)]
    if differ:
        shown = "; ".join(_difference(key, _identity(found, key), _identity(wanted, key))
                          if key == "parameters" else
                          f"{key}: {_short(found.get(key))} there, {_short(wanted.get(key))} "
                          f"here" for key in differ)
        raise ValueError(f"{directory} holds a sweep with different parameters ({shown}); "
                         f"use another directory, or delete it to start again")
    if found.get("kresling") != wanted.get("kresling"):
        logger.warning("%s was written by kresling %s; resuming with %s", directory,
                       found.get("kresling"), wanted.get("kresling"))


def _difference(key: str, there, here) -> str:
    """The parameters that differ, each with both values (``kf = 0.047 there, 0.094 here``)."""
    if not (isinstance(there, dict) and isinstance(here, dict)):
        return f"{key}: {_short(there)} there, {_short(here)} here"
    names = [name for name in sorted(set(there) | set(here)) if there.get(name) != here.get(name)]
    return "; ".join(f"{name} = {_short(there.get(name))} there, {_short(here.get(name))} here"
                     for name in names)


def _short(value) -> str:
    if isinstance(value, dict) and isinstance(value.get("sha256"), str):  # the designs
        spec = value.get("spec")
        spec = spec if isinstance(spec, dict) else {}
        if spec.get("kind") == "grid":
            return (f"{value.get('count')} designs (grid n {spec.get('n')}, size "
                    f"{spec.get('size')}, Lc {spec.get('Lc')}, lam {spec.get('lam')}, R "
                    f"{spec.get('R')}; {value['sha256'][:8]})")
        return f"{value.get('count')} designs (a list; {value['sha256'][:8]})"
    text = json.dumps(value, sort_keys=True)
    return text if len(text) <= 120 else text[:117] + "..."


def _read_rows(path: Path, columns, check_row) -> dict:
    """Rows already on disk, by index; truncates a final line cut short by a crash."""
    if not path.exists():
        return {}
    data = path.read_bytes()
    whole = data[: data.rfind(b"\n") + 1]
    lines = whole.split(b"\n")[:-1]  # the file writes "\n" only (format_row)
    if not lines or _fields(path, 1, lines[0]) != list(columns):
        raise ValueError(f"{path} does not start with the header this sweep writes")
    rows = {}
    for number, line in enumerate(lines[1:], start=2):
        fields = _fields(path, number, line)
        if len(fields) != len(columns):
            if number < len(lines):
                raise ValueError(f"{path}, line {number}: {len(fields)} fields, expected "
                                 f"{len(columns)} (damaged file)")
            whole = whole[: whole.rstrip(b"\n").rfind(b"\n") + 1]  # drop a partial last row
            break
        row = []
        for name, text in zip(columns, fields):
            try:
                row.append(parse_value(name, text))
            except ValueError:
                raise ValueError(f"{path}, line {number}: column {name!r} = {show(text)} is "
                                 f"not a {column_kind(name)} (damaged file)") from None
        row = tuple(row)
        if check_row is not None:
            try:
                check_row(row)
            except ValueError as error:
                raise ValueError(f"{path}, line {number}: {error}") from None
        rows.setdefault(row[columns.index("index")], row)
    if len(whole) != len(data):
        logger.warning("%s: dropped an incomplete last line (%d bytes) left by an interrupted "
                       "run", path, len(data) - len(whole))
        with open(path, "r+b") as f:
            f.truncate(len(whole))
    return rows


def _fields(path: Path, number: int, line: bytes) -> list:
    """The fields of one line of results.csv (UTF-8, as written); bytes that are not, or a
    line csv cannot read, are a ValueError naming the file and line."""
    try:
        text = line.decode("utf-8")
    except UnicodeDecodeError:
        raise ValueError(f"{path}, line {number}: not UTF-8 text (damaged file)") from None
    return csv_cells(text.rstrip("\r"), path, number)


def _write_atomic(path: Path, text: str) -> None:
    temporary = path.with_name(path.name + ".tmp")
    with open(temporary, "w", newline="") as f:
        f.write(text)
        f.flush()
        os.fsync(f.fileno())
    os.replace(temporary, path)


def _acquire(path: Path):
    """Lock ``path`` (created if missing); the lock is the open file. The file is removed
    when the lock is released, so a check that the path still names the locked file guards
    against locking a file another process has just released and removed."""
    for _ in range(100):
        handle = open(path, "a")
        if fcntl is None:
            return handle
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            handle.close()
            raise ValueError(f"{path.parent} is being written by another sweep (locked); wait "
                             f"for it or use another directory") from None
        try:
            same = os.stat(path).st_ino == os.fstat(handle.fileno()).st_ino
        except FileNotFoundError:
            same = False
        if same:
            return handle
        handle.close()  # released and removed by its holder meanwhile: lock the new file
    raise ValueError(f"{path.parent}: could not lock {path.name} (it keeps being replaced); "
                     f"is another sweep starting and stopping in this directory?")


def _release(handle) -> None:
    """Remove the lock file, then unlock (in that order: see :func:`_acquire`)."""
    if handle is None:
        return
    if fcntl is None:  # pragma: no cover - not POSIX: an open file cannot be removed there
        handle.close()
    try:
        os.unlink(handle.name)
    except OSError:  # pragma: no cover - removed by hand; a file left does no harm
        pass
    handle.close()


def _now() -> str:
    return datetime.now(timezone.utc).isoformat(timespec="seconds")
