"""Bending-trial files: a testing-machine export per trial, with the trial's state and
module length as metadata lines above the header (or given by the caller)::

    # state: contracted
    # module_length: 60.0 mm
    time_s,displacement_mm,force_N
    0.0,0.0000,0.00012
    ...
"""

from __future__ import annotations

from kresling.fits.bending import BendingStiffness, BendingTrial, fit_bending, state_name
from kresling.fits.records import RecordError, read_machine_record

__all__ = ["read_bending_trial", "fit_bending_files"]


def read_bending_trial(path, *, state=None, module_length: float | None = None, names=None,
                       units=None, on_invalid: str = "raise", negate=()):
    """Read one bending trial.

    Parameters
    ----------
    path : str or Path
        A machine export (see :func:`~kresling.fits.records.read_machine_record`).
    state : {"extended", "contracted", 1, 0}, optional
        Overrides the file's ``# state:`` line; one of the two is required.
    module_length : float, optional
        Lm in mm; overrides the file's ``# module_length: <value> <unit>`` line.
    names, units, on_invalid, negate
        As in :func:`~kresling.fits.records.read_table`.

    Returns
    -------
    trial : BendingTrial
    skipped : list of SkippedRow
    """
    record = read_machine_record(path, names=names, units=units, on_invalid=on_invalid,
                                 negate=negate)
    if state is None:
        if "state" not in record.metadata:
            raise RecordError(path, None, None, "no '# state: extended|contracted' line; "
                              "give the state")
        text, line = record.metadata["state"]
        try:
            state = state_name(text)
        except ValueError as error:
            raise RecordError(path, line, None, str(error)) from None
    if module_length is None:
        if "module_length" not in record.metadata:
            raise RecordError(path, None, None, "no '# module_length: <value> mm' line; "
                              "give the module length")
        module_length = record.quantity("module_length", "length")
    if not module_length > 0:
        line = record.metadata.get("module_length", (None, None))[1]
        raise RecordError(path, line, None,
                          f"module_length = {module_length!r} mm is invalid: must be > 0")
    trial = BendingTrial(state_name(state), float(module_length),
                         record.columns["displacement"], record.columns["force"],
                         source=str(path))
    return trial, record.skipped


def fit_bending_files(paths, *, state=None, module_length=None, names=None, units=None,
                      on_invalid: str = "raise", negate=(), **fit_options) -> BendingStiffness:
    """Read bending trials (:func:`read_bending_trial`) and fit them
    (:func:`~kresling.fits.bending.fit_bending`, which takes ``fit_options``)."""
    trials, skipped = [], []
    for path in paths:
        trial, passed_over = read_bending_trial(path, state=state, module_length=module_length,
                                                names=names, units=units,
                                                on_invalid=on_invalid, negate=negate)
        trials.append(trial)
        skipped += passed_over
    return fit_bending(trials, skipped=skipped, **fit_options)
