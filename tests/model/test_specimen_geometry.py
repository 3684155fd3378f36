"""The built specimens' geometry: every bar has its design length in both states,
both states are stress-free, and the optimum's extended module is 111.639 mm."""

import numpy as np
import pytest

from kresling import Design
from kresling.assembly import assemble
from kresling.model import SpecimenParameters, kresling_specimen

DESIGNS = [Design(10, 0.9, 15), Design(8, 0.8, 30), Design(8, 0.8, 15), Design(4, 0.7, 30)]


@pytest.mark.parametrize("duplicate", [True, False], ids=["merlin2", "deduplicated"])
@pytest.mark.parametrize("design", DESIGNS, ids=repr)
def test_bars_have_their_design_lengths_and_states_are_stress_free(design, duplicate):
    expected = {"valley": design.Vg, "mountain": design.Mg, "polygon_edge": design.P,
                "polygon_spoke": design.R}
    parameters = SpecimenParameters(duplicate_shared_edges=duplicate)
    for state in (0, 1):
        s = kresling_specimen(design, [state] * 4, parameters=parameters)
        X, bars = s.model.nodes, s.model.bars
        lengths = np.linalg.norm(X[bars[:, 1]] - X[bars[:, 0]], axis=1)
        for family, length in expected.items():
            chosen = s.bar_family == family
            assert chosen.sum() >= design.n
            assert np.abs(lengths[chosen] - length).max() <= 1e-10 * length, family
        assert np.allclose(s.model.bar_rest_length, lengths, rtol=0, atol=1e-12)
        a = assemble(s.model)
        assert a.energy == 0.0 and np.abs(a.force).max() <= 1e-9
        assert np.allclose(np.diff(s.level_height), design.height(state), rtol=0, atol=1e-12)


def test_optimum_extended_module_length():
    s = kresling_specimen(Design(10, 0.9, 15), ["extended"] * 2)
    assert round(float(s.level_height[-1]), 3) == 111.639      # thesis eqn 30: 111.6 mm
    assert s.level_height[-1] == pytest.approx(2 * 55.8194667799374, abs=1e-9)


@pytest.mark.parametrize("kwargs, message", [
    (dict(states=[1, 1], chirality=[1]), "chirality: has 1 entries but states has 2; give one per cell"),
    (dict(states=[]), "states: the specimen needs at least one cell"),
    (dict(states=[1, 2]), "state = 2 is invalid"),
    (dict(states=[1], chirality=[2]), r"chirality\[0\] = 2 is invalid"),
])
def test_bad_state_and_chirality_lists(kwargs, message):
    with pytest.raises(ValueError, match=message):
        kresling_specimen(Design(8, 0.8, 30), **kwargs)
