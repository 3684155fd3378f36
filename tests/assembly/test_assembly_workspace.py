"""kresling.assembly.Workspace: a pattern built once serves every model of its connectivity.

The reference is assembly without a workspace (a pattern built for the call): the same
arithmetic in the same order, so the results must be equal to the last bit, not to a
tolerance.
"""

import gc
import weakref

import numpy as np
import pytest

from kresling import Design
from kresling.assembly import Workspace, assemble
from kresling.model import kresling_specimen


def stack(lam, Lc, chirality=None):
    design = Design(n=6, lam=lam, Lc=Lc)
    return kresling_specimen(design, [1, 0, 1], chirality=chirality).model


def same_bits(a, b):
    assert a.energy_bars == b.energy_bars and a.energy_hinges == b.energy_hinges
    assert np.array_equal(a.force, b.force)
    if a.stiffness is None:
        assert b.stiffness is None
        return
    for name in ("data", "indices", "indptr"):
        assert np.array_equal(getattr(a.stiffness, name), getattr(b.stiffness, name)), name


@pytest.mark.parametrize("stiffness", [True, False])
def test_a_workspace_gives_the_fresh_results_bitwise_across_designs(stiffness):
    models = [stack(0.8, 20.0), stack(0.7, 25.0), stack(0.85, 15.0)]
    w = Workspace(models[0])
    rng = np.random.default_rng(3)
    for model in models + models[:1]:
        assert w.fits(model)
        u = rng.normal(scale=0.2, size=model.num_dofs)
        for shift in (0.0, 1e-8):
            same_bits(assemble(model, u, stiffness=stiffness, shift=shift, workspace=w),
                      assemble(model, u, stiffness=stiffness, shift=shift))
    # Each model is evaluated, not the one the workspace was built from.
    u = rng.normal(scale=0.2, size=models[0].num_dofs)
    a, b = (assemble(m, u, workspace=w) for m in models[:2])
    assert np.linalg.norm(a.force - b.force) > 1e-3 * np.linalg.norm(a.force)


def test_a_workspace_keeps_no_reference_to_its_model():
    model = stack(0.8, 20.0)
    w = Workspace(model)
    gone = weakref.ref(model)
    del model
    gc.collect()
    assert gone() is None
    other = stack(0.7, 25.0)
    same_bits(assemble(other, workspace=w), assemble(other))


def test_a_model_of_another_connectivity_is_refused():
    w = Workspace(stack(0.8, 20.0))
    other_n = kresling_specimen(Design(n=4, lam=0.8, Lc=20.0), [1]).model
    # Same counts of nodes and elements, the middle cell's creases on other vertices.
    flipped = stack(0.8, 20.0, chirality=[1, 1, 1])
    for model in (other_n, flipped):
        assert not w.fits(model)
        with pytest.raises(ValueError, match="workspace: was built for a model of another "
                                             "connectivity"):
            assemble(model, workspace=w)


def test_a_workspace_must_be_one():
    model = stack(0.8, 20.0)
    with pytest.raises(ValueError, match="workspace = .* is invalid: must be a "
                                         "kresling.assembly.Workspace or None"):
        assemble(model, workspace="pattern")
    with pytest.raises(ValueError, match="model = .* is invalid"):
        Workspace(np.zeros(3))
