"""Fitting the specimen's stiffnesses on the full model (kresling.analyses.stiffness_fit).

Records made by the model itself with known kf and bar-modulus ratio (two designs, both
states, 5 mm in 20 increments) are fitted from the thesis's values: noise-free, the fit must
give the truth back to 1e-6 relative (measured: 1e-13; the model's Newton converges to 1e-10
mm, far below what moves the forces at that level). The K_B fit is checked the same way,
and against the closed form it must agree with: K_B is proportional to kf.
"""

import numpy as np
import pytest

from kresling.analyses.design_sensitivity import bending_gradient
from kresling.analyses.stiffness_fit import (BendingRecord, fit_bending_stiffnesses,
                                             fit_specimen_stiffness, record_from_model)
from kresling.geometry import Design
from kresling.model.kresling_specimen import SpecimenParameters

TRUTH = SpecimenParameters(kf=0.06, modulus_factor=2e3)
DESIGNS = (Design(8, 0.8, 15.0, 30.0), Design(8, 0.8, 30.0, 30.0))


def test_known_stiffnesses_come_back_from_the_models_own_records():
    records = [record_from_model(d, s, 5.0, 20, TRUTH) for d in DESIGNS for s in (0, 1)]
    fit = fit_specimen_stiffness(records, steps=20)
    assert fit.success, fit.message
    assert fit.values["kf"] == pytest.approx(0.06, rel=1e-6)
    assert fit.values["modulus_factor"] == pytest.approx(2e3, rel=1e-6)
    assert fit.rms < 1e-9
    assert fit.parameters.kf == fit.values["kf"]


def test_kf_alone_is_the_closed_form_ratio():
    # K_B is proportional to kf: fitted alone to K_B values made with kf = 0.06 and the
    # thesis's other ratios, kf comes back, and the log-residuals vanish.
    truth = SpecimenParameters(kf=0.06)
    measured = [(d, s, bending_gradient(d, s, "0.001rad", parameters=truth,
                                        variables=("kf",))[0]) for d in DESIGNS for s in (0, 1)]
    fit = fit_bending_stiffnesses(measured, variables=("kf",), protocol="0.001rad")
    assert fit.values["kf"] == pytest.approx(0.06, rel=1e-9)
    assert np.abs(fit.residual).max() < 1e-9


@pytest.mark.parametrize("make, message", [
    (lambda: fit_specimen_stiffness([]), "records must be a non-empty"),
    (lambda: fit_specimen_stiffness([BendingRecord(DESIGNS[0], 1, [1.0], [1.0])],
                                    variables=("lam",)), "variables: 'lam' is invalid"),
    (lambda: BendingRecord(DESIGNS[0], 1, [2.0, 1.0], [1.0, 2.0]), "positive and increasing"),
    (lambda: BendingRecord(DESIGNS[0], 1, [1.0], [1.0, 2.0]), "equally many"),
    (lambda: fit_bending_stiffnesses([(DESIGNS[0], 1, -1.0)]), "K_B > 0"),
])
def test_bad_input_is_refused(make, message):
    with pytest.raises(ValueError, match=message):
        make()
