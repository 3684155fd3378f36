"""Table 3 side by side: our bending test, the MERLIN2 reference runs, and the thesis's model
and experimental columns; and how much MERLIN2's duplicated topology moves the answer.

Sources, read through :mod:`kresling.data.tables`: ``kresling/data/merlin2/table3_reference.csv``
(MERLIN2 runs of the thesis's Appendix B script, see its README) and
``kresling/data/thesis_table3_bending_stiffness.csv``. The experimental ratio is also
recomputed from the printed means: for n = 8, Lc = 30 the printed 4.91 is not
3.50 / 0.80 = 4.38.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from kresling.analyses.bending import BendingComparison, bending_stiffness
from kresling.data.tables import TABLE3_DESIGNS, merlin2_table3_reference, thesis_table3
from kresling.geometry import Design
from kresling.model.kresling_specimen import SpecimenParameters

__all__ = ["TABLE3_DESIGNS", "Table3Comparison", "table3_comparison", "merlin2_reference",
           "topology_effect", "model_curves"]

_KEYS = ("extended", "contracted", "ratio")

#: K_B of the MERLIN2 reference runs: ``(n, Lc, lam)`` to ``{"extended", "contracted",
#: "ratio"}`` [N*m/rad] (the shipped data, :func:`kresling.data.tables.merlin2_table3_reference`).
merlin2_reference = merlin2_table3_reference


@dataclass(frozen=True)
class Table3Comparison:
    """One design of Table 3 (K_B in N*m/rad; NaN where a source gives no value).

    Attributes
    ----------
    design : Design
    ours : BendingComparison
        Our bending test (both states).
    reference : dict
        MERLIN2's ``extended``, ``contracted``, ``ratio``.
    thesis_model : dict
        The thesis's model column (same keys; only the ratio for the optimum).
    experiment : dict
        The thesis's experiment: ``extended``, ``extended_sd``, ``contracted``,
        ``contracted_sd``, ``ratio`` (as printed), ``ratio_of_means`` (recomputed).
    """

    design: Design
    ours: BendingComparison
    reference: dict
    thesis_model: dict
    experiment: dict

    @property
    def ours_values(self) -> dict:
        """Our ``extended``, ``contracted`` and ``ratio``."""
        return {"extended": self.ours.extended.stiffness,
                "contracted": self.ours.contracted.stiffness, "ratio": self.ours.ratio}

    def row(self) -> dict:
        """A flat dict for printing or CSV: the design, then ``<source>_<quantity>``."""
        d = self.design
        out = {"n": d.n, "Lc_mm": d.Lc, "lambda": d.lam}
        for source, values in (("ours", self.ours_values), ("merlin2", self.reference),
                               ("thesis_model", self.thesis_model)):
            out.update({f"{source}_{k}": values[k] for k in _KEYS})
        out.update({f"experiment_{k}": v for k, v in self.experiment.items()})
        return out


def table3_comparison(protocol: str = "5mm", parameters=None, designs=TABLE3_DESIGNS) -> list:
    """Run the bending test on Table 3's designs and put every source beside it.

    Parameters
    ----------
    protocol : {"5mm", "0.001rad"}
        The reference runs and the thesis's Table 3 use "5mm".
    parameters : SpecimenParameters, optional
    designs : sequence of (n, Lc, lam)

    Returns
    -------
    list of Table3Comparison
    """
    thesis = {(row["n"], row["Lc"], row["lam"]): row for row in thesis_table3()
              if row["material"] == "paper"}
    reference = merlin2_table3_reference()
    nan = dict.fromkeys(_KEYS, math.nan)
    out = []
    for n, Lc, lam in designs:
        design = Design(n, lam, Lc)
        row = thesis.get((n, Lc, lam))
        experiment = {} if row is None else {
            "extended": row["K1_exp_mean"], "extended_sd": row["K1_exp_sd"],
            "contracted": row["K0_exp_mean"], "contracted_sd": row["K0_exp_sd"],
            "ratio": row["ratio_exp"], "ratio_of_means": row["K1_exp_mean"] / row["K0_exp_mean"]}
        model = nan if row is None else {"extended": row["K1_model"],
                                         "contracted": row["K0_model"],
                                         "ratio": row["ratio_model"]}
        out.append(Table3Comparison(
            design=design, ours=bending_stiffness(design, protocol, parameters=parameters),
            reference=reference.get((n, Lc, lam), nan), thesis_model=model,
            experiment=experiment))
    return out


def topology_effect(designs=TABLE3_DESIGNS, protocol: str = "5mm", parameters=None) -> list:
    """How much one bar and one hinge per edge (instead of MERLIN2's one per pair of
    triangles sharing it) moves K_B.

    Only the intermediate polygons' edges are shared by three triangles, so only stacks are
    affected (docs/model.md, 'Topology'; MERLIN2 runs gave about 0.5 %, 8 % for n = 10
    contracted; a single cell, as in the snap-through test, not at all). The runs use
    MERLIN2's Newton sequence (each increment starts from the last equilibrium), as those
    numbers came from MERLIN2: the
    de-duplicated specimen is softer, and the n = 10 contracted one loses stability near
    4.9 mm, where an extrapolated start would carry the path on along an unstable branch.
    Which branch the path takes there, and so that K_B (by up to half a percent), is decided
    by rounding: with MERLIN2's sequence the change is -8.37 % with a dense Cholesky,
    -8.03 % with CHOLMOD's and -7.41 % with the supernodal one (whose path goes on along a
    stable branch to the end). MERLIN2 factorises with CHOLMOD (the backslash of Octave and
    MATLAB on a sparse symmetric positive definite matrix), so these runs do too.

    Parameters
    ----------
    designs : sequence of (n, Lc, lambda), default the Table 3 designs
    protocol : {"5mm", "0.001rad"}
    parameters : SpecimenParameters, optional
        The material and model of both runs but for the topology (default the thesis's).

    Returns
    -------
    list of dict
        Per design: ``n``, ``Lc_mm``, ``lambda``, the relative changes ``extended``,
        ``contracted``, ``ratio`` (deduplicated / MERLIN2's - 1), and for the de-duplicated
        runs ``completed_extended``/``completed_contracted`` (False: the path stopped where
        the specimen lost stability; K_B is then fitted to the part before) and
        ``stable_extended``/``stable_contracted``.
    """
    duplicated = replace(parameters or SpecimenParameters(), duplicate_shared_edges=True)
    deduplicated = replace(duplicated, duplicate_shared_edges=False)
    out = []
    for n, Lc, lam in designs:
        design = Design(n, lam, Lc)
        base = bending_stiffness(design, protocol, parameters=duplicated, extrapolation=0,
                                 cholesky="simplicial")
        other = bending_stiffness(design, protocol, parameters=deduplicated, extrapolation=0,
                                  cholesky="simplicial")
        out.append({"n": n, "Lc_mm": Lc, "lambda": lam,
                    "extended": other.extended.stiffness / base.extended.stiffness - 1,
                    "contracted": other.contracted.stiffness / base.contracted.stiffness - 1,
                    "ratio": other.ratio / base.ratio - 1,
                    "completed_extended": other.extended.completed,
                    "completed_contracted": other.contracted.completed,
                    "stable_extended": other.extended.stable,
                    "stable_contracted": other.contracted.stable})
    return out


def model_curves(designs=TABLE3_DESIGNS, protocol: str = "5mm", parameters=None) -> dict:
    """Our bending test's moment-angle curves of the Table 3 designs, both states.

    Parameters
    ----------
    designs : sequence of (n, Lc, lambda), default the Table 3 designs
    protocol : {"5mm", "0.001rad"}
    parameters : SpecimenParameters, optional
        The specimens' material and model (default the thesis's).

    Returns
    -------
    dict
        ``(n, Lc, lam)`` to ``{"extended": (angle, moment), "contracted": (angle, moment)}``
        (rad, N*m): the form the experimental fits take as the model to compare the
        experiments with (:func:`kresling.fits.thesis_tables.experiment_vs_model`).
    """
    curves = {}
    for n, Lc, lam in designs:
        result = bending_stiffness(Design(n, lam, Lc), protocol, parameters=parameters)
        curves[(n, float(Lc), lam)] = {r.state_name: (r.angle, r.moment)
                                       for r in (result.extended, result.contracted)}
    return curves
