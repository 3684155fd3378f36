"""Bad input to the manipulator: a ValueError naming the parameter, the value and what is allowed
(the command line: one line on stderr, exit 2), never another exception, a hang or a
silent NaN. Reproducers of defects a fuzzing audit found; each must stay fixed (the C++
side of several is in cpp/tests/test_hardening.cpp)."""


import numpy as np
import pytest



def test_arcs_of_extreme_tendons():
    from kresling.manipulator import arc_from_tendons
    # (a^2 + b^2) / scale^2 overflowed to inf / inf = NaN, passed the check and gave s = NaN
    assert np.isfinite(arc_from_tendons([0.0, 0.0, 1.34078079299426e154], 4.5e153)).all()
    with pytest.raises(ValueError, match=r"sqrt\(Q\) / \(3 N d\)"):
        arc_from_tendons([0.0, 0.0, 1.34078079299426e154], 4e153)
    # the mean of subnormal lengths underflowed to 0: kappa was inf
    assert np.isfinite(arc_from_tendons([0.0, 0.0, 5e-324])).all()
    with pytest.raises(ValueError, match=r"^d = 1e-310 is invalid: must be large enough"):
        arc_from_tendons([0.0, 0.0, 1e-310], 1e-310)  # kappa = 2e310


def test_a_long_arm_does_not_list_every_configuration():
    from kresling.manipulator import Manipulator, inverse_kinematics
    with pytest.raises(ValueError, match=r"^modules = 52 is invalid for listing every "
                                         r"configuration \(2\*\*52 of them\)"):
        inverse_kinematics(Manipulator(modules=52), [0.0, 0.0, 0.0])
    far = inverse_kinematics(Manipulator(), [0.0, 0.0, 1.34e154])
    assert not far.reachable and np.isfinite(far.distance)
