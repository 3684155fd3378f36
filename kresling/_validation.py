"""Checks on user input shared by the Python API: messages name the parameter, the value
given and what is allowed, matching the C++ core's std::invalid_argument messages."""

from __future__ import annotations

import csv
import math
import numbers
import os
import stat

import numpy as np

#: The largest integer the C++ core takes (a C ``int``): larger ones are refused here, with
#: the parameter's name, instead of failing in the binding's type conversion (a TypeError).
INT_MAX = 2**31 - 1

#: Largest input file (a problem or pattern file) read [bytes]: far above any real one (a
#: 10,000-vertex FOLD file is under 1 MB), far below what a device or a sparse file offers.
INPUT_FILE_LIMIT = 256 * 2**20

#: Longest value a message shows (a longer one is cut, with "...").
_SHOWN = 200


def show(value) -> str:
    """A value as messages print it: numpy scalars as plain Python numbers; long reprs cut."""
    if isinstance(value, np.generic):
        value = value.item()
    text = repr(value)
    return text if len(text) <= _SHOWN else text[:_SHOWN - 3] + "..."


def _integer_range(minimum, maximum) -> str:
    text = "an integer"
    if minimum is not None:
        text += f" >= {minimum}"
    if maximum is not None:
        text += f" and <= {maximum}" if minimum is not None else f" <= {maximum}"
    return text


def as_integer(name: str, value, minimum: int | None = None, maximum: int | None = INT_MAX) -> int:
    """Return ``value`` as an ``int``, rejecting non-integral values and bools.

    Integral floats (``10.0``, as read from a CSV file) are accepted; ``2.7``, ``nan`` and
    ``True`` are not (never truncated). ``maximum`` defaults to the largest C ``int``, what
    the C++ core takes (None: no bound).

    >>> as_integer("steps", 10.0, minimum=1)
    10
    >>> as_integer("steps", 2.7)  # no minimum given: any C int
    Traceback (most recent call last):
    ...
    ValueError: steps = 2.7 is invalid: must be an integer >= -2147483648 and <= 2147483647
    """
    if minimum is None and maximum == INT_MAX:
        minimum = -INT_MAX - 1  # a C int either way
    allowed = _integer_range(minimum, maximum)
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} = {show(value)} is invalid: must be {allowed}")
    if isinstance(value, numbers.Integral):
        result = int(value)
    else:
        number = float(value)
        if not math.isfinite(number) or number != math.floor(number):
            raise ValueError(f"{name} = {show(value)} is invalid: must be {allowed}")
        result = int(number)
    if (minimum is not None and result < minimum) or (maximum is not None and result > maximum):
        raise ValueError(f"{name} = {result} is invalid: must be {allowed}")
    return result


def as_integer_array(name: str, values) -> np.ndarray:
    """Return ``values`` as an int32 array; every entry must be integral and finite (no
    bools, no 1.7 read as 1)."""
    try:
        array = np.asarray(values)
    except (TypeError, ValueError, OverflowError) as error:
        raise ValueError(f"{name} is invalid: must be an array of integers ({error})") from None
    if array.dtype == bool or not (np.issubdtype(array.dtype, np.number)):
        raise ValueError(f"{name} has dtype {array.dtype}: must be integers")
    if np.issubdtype(array.dtype, np.complexfloating):
        raise ValueError(f"{name} has dtype {array.dtype}: must be integers")
    if np.issubdtype(array.dtype, np.floating):
        bad = ~np.isfinite(array) | (array != np.round(array))
        if bad.any():
            index = tuple(int(i) for i in np.argwhere(bad)[0])
            where = ", ".join(str(i) for i in index)
            raise ValueError(f"{name}[{where}] = {show(array[index])} is invalid: must be an integer")
    if array.size and (array.max() > np.iinfo(np.int32).max or array.min() < np.iinfo(np.int32).min):
        raise ValueError(f"{name} has entries outside the 32-bit integer range")
    return array.astype(np.int32)


def as_float_array(name: str, values) -> np.ndarray:
    """``values`` as a float array; anything numpy cannot read as numbers (text, ragged
    lists, None, complex) is a ValueError naming ``name``."""
    try:
        array = np.asarray(values)
        if array.dtype == object or not (np.issubdtype(array.dtype, np.number) or
                                         array.dtype == bool):
            raise TypeError(f"dtype {array.dtype}")
        if np.issubdtype(array.dtype, np.complexfloating):
            raise TypeError("complex numbers")
        return array.astype(float)
    except (TypeError, ValueError, OverflowError) as error:
        raise ValueError(f"{name} = {show(values)} is invalid: must be an array of real "
                         f"numbers ({error})") from None


def as_index_lists(name: str, values) -> list:
    """Lists of integer indices, e.g. panels (the vertex indices around each face): a
    ValueError naming the entry for anything else (text, None, 1.5, True)."""
    def listlike(value):
        return not isinstance(value, (str, bytes, dict)) and hasattr(value, "__iter__")

    if not listlike(values):
        raise ValueError(f"{name} = {show(values)} is invalid: must be a list of lists of "
                         "indices")
    out = []
    for i, item in enumerate(values):
        if not listlike(item):
            raise ValueError(f"{name}[{i}] = {show(item)} is invalid: must be a list of indices")
        out.append([as_integer(f"{name}[{i}][{k}]", v) for k, v in enumerate(item)])
    return out


def as_mask(name: str, value) -> np.ndarray:
    """A boolean array from bools or 0/1 (NaN, 0.5 or 2 are not a support flag)."""
    try:
        array = np.asarray(value)
    except (TypeError, ValueError) as error:
        raise ValueError(f"{name} is invalid: must be an array of booleans ({error})") from None
    if array.dtype == bool:
        return array
    if not np.issubdtype(array.dtype, np.number) or \
            np.issubdtype(array.dtype, np.complexfloating) or \
            not np.isin(array, (0, 1)).all():
        raise ValueError(f"{name} is invalid: must be booleans (or 0/1), got {show(value)}")
    return array.astype(bool)


def as_list(name: str, value, what: str) -> list:
    """``value`` as a list, if it is a sequence (not text, a dict or a scalar)."""
    if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__iter__"):
        raise ValueError(f"{name} = {show(value)} is invalid: must be a list of {what}")
    return list(value)


def as_choice(name: str, value, choices):
    """``value`` if it is one of ``choices`` (strings); else a ValueError listing them (an
    unhashable value is just another wrong one)."""
    if not isinstance(value, str) or value not in choices:
        raise ValueError(f"{name} = {show(value)} is invalid: must be one of {sorted(choices)}")
    return value


def as_points(name: str, values, dimension: int = 3) -> np.ndarray:
    """An (N, dimension) array of finite coordinates."""
    array = as_float_array(name, values)
    if array.ndim != 2 or array.shape[1] != dimension:
        raise ValueError(f"{name} has shape {array.shape}: must be (N, {dimension})")
    if not np.isfinite(array).all():
        row, column = (int(i) for i in np.argwhere(~np.isfinite(array))[0])
        raise ValueError(f"{name}[{row}, {column}] = {array[row, column]!r} is invalid: must be "
                         "a finite coordinate")
    return np.ascontiguousarray(array)


def _float(name: str, value, allowed: str) -> float:
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} = {show(value)} is invalid: must be {allowed}")
    try:
        return float(value)
    except OverflowError:  # an int beyond the float range
        raise ValueError(f"{name} = {show(value)} is invalid: must be {allowed} (within the "
                         "float range)") from None


def as_positive_real(name: str, value) -> float:
    """Return ``value`` as a float that is finite and > 0 (a tolerance, a step size)."""
    value = _float(name, value, "a finite number > 0")
    if not (math.isfinite(value) and value > 0):
        raise ValueError(f"{name} = {value!r} is invalid: must be a finite number > 0")
    return value


def as_real(name: str, value) -> float:
    """Return ``value`` as a float; the core checks ranges and finiteness."""
    return _float(name, value, "a real number")


def as_finite_real(name: str, value) -> float:
    """Return ``value`` as a finite float."""
    value = _float(name, value, "a finite number")
    if not math.isfinite(value):
        raise ValueError(f"{name} = {value!r} is invalid: must be a finite number")
    return value


def as_bool(name: str, value) -> bool:
    """Return ``value`` as a bool: True/False (or numpy's), 0 or 1; not NaN, not "no"."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, numbers.Integral) and int(value) in (0, 1):
        return bool(value)
    raise ValueError(f"{name} = {show(value)} is invalid: must be True or False")


def csv_cells(text: str, source, line: int, delimiter: str = ",") -> list:
    """The cells of one line of a CSV file. A line csv cannot read (a field over csv's limit
    of 131072 characters, an unterminated quote in strict mode, ...) is a ValueError naming ``source`` and ``line``,
    not a ``_csv.Error``.

    >>> csv_cells('a,"b,c"', "t.csv", 3)
    ['a', 'b,c']
    >>> csv_cells("1," + "9" * 200_000, "t.csv", 3)
    Traceback (most recent call last):
    ...
    ValueError: t.csv, line 3: not a CSV line (field larger than field limit (131072))
    """
    try:
        return next(csv.reader([text], delimiter=delimiter), [])
    except csv.Error as error:
        raise ValueError(f"{source}, line {line}: not a CSV line ({error})") from None


def csv_records(handle, source):
    """``(line number, cells)`` of every record of an open CSV file, as ``csv.reader``
    gives them, with csv's errors as a ValueError naming ``source`` and the line."""
    reader = csv.reader(handle)
    while True:
        try:
            cells = next(reader)
        except StopIteration:
            return
        except csv.Error as error:
            raise ValueError(f"{source}, line {reader.line_num}: not a CSV line ({error})") \
                from None
        yield reader.line_num, cells


def _size(count: int) -> str:
    for unit, factor in (("GiB", 2**30), ("MiB", 2**20), ("KiB", 2**10)):
        if count >= factor:
            return f"{count / factor:.3g} {unit}"
    return f"{count} bytes"


def read_input_file(path, limit: int = INPUT_FILE_LIMIT) -> bytes:
    """The bytes of an input file, refusing what is not a regular file or is over ``limit``.

    A FIFO would block the read forever and a device (``/dev/zero``) or a sparse file of
    gigabytes would fill the memory, so both are refused before anything is read, with a
    ValueError naming the file (and its size). A missing or unreadable file is an OSError
    naming it.
    """
    name = os.fspath(path)
    info = os.stat(name)  # follows links: a link to a regular file is read
    if not stat.S_ISREG(info.st_mode):
        kind = ("a directory" if stat.S_ISDIR(info.st_mode) else "a FIFO"
                if stat.S_ISFIFO(info.st_mode) else "a device or socket")
        raise ValueError(f"{name}: is {kind}, not a regular file")
    if info.st_size > limit:
        raise ValueError(f"{name}: is {_size(info.st_size)}, larger than the {_size(limit)} "
                         "an input file may have")
    with open(name, "rb") as handle:
        data = handle.read(limit + 1)  # a file growing while read is still capped
    if len(data) > limit:
        raise ValueError(f"{name}: is larger than the {_size(limit)} an input file may have")
    return data
