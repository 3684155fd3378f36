"""Fuzz: models (Model, its views, panel topology, panel elements, pattern models, Kresling
specimens) and the assembly of their forces and tangents."""

import numpy as np
from hypothesis import assume, given
from hypothesis import strategies as st

from _fuzz import attempt, edgy_floats, finite, fuzz, junk, mostly
from kresling import Design
from kresling.assembly import assemble
from kresling.model import (ManualProperties, Model, SheetMaterial, build_panel_elements,
                            build_pattern_model, kresling_specimen, panel_topology)

coordinate = st.one_of(st.floats(-10, 10), st.sampled_from([0.0, 1.0, 1e-300, 1e300,
                                                            float("nan"), float("inf")]))
vertices = st.integers(3, 8).flatmap(
    lambda n: st.lists(st.lists(coordinate, min_size=3, max_size=3), min_size=n, max_size=n))
index = st.one_of(st.integers(-2, 9), st.sampled_from([1.5, True, 2**40, -2**40, "1", None]))
panels = st.lists(st.lists(index, min_size=0, max_size=6), min_size=0, max_size=5)
grid_panels = st.sampled_from([[[0, 1, 2]], [[0, 1, 2], [0, 2, 3]], [[0, 1, 2, 3]],
                               [[0, 1, 2, 3], [1, 4, 5, 2]], [[0, 1, 2, 3, 4]]])

MODEL = ("nodes", "bars", "hinges", "bar_modulus", "hinge_stiffness", "bar_area",
         "bar_rest_length", "bar_law", "hinge_rest_angle", "hinge_length", "hinge_law",
         "hinge_limits", "fixed", "node ", "bar ", "hinge ")  # the C++ names the element


def flat_sheet(rng_points):
    """A planar sheet of 6 nodes (two quads) moved by the drawn offsets out of plane."""
    base = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0], [2, 1, 0]], float)
    return base + np.asarray(rng_points)


@fuzz(300)
@given(vertices, st.lists(st.lists(index, min_size=2, max_size=2), max_size=4),
       st.lists(st.lists(index, min_size=4, max_size=4), max_size=3),
       st.fixed_dictionaries({}, optional={
           "bar_modulus": st.one_of(edgy_floats, junk), "hinge_stiffness": st.one_of(edgy_floats, junk),
           "bar_area": st.one_of(edgy_floats, junk), "bar_law": st.one_of(
               st.sampled_from(["ogden", "linear", "nope"]), junk),
           "hinge_law": st.one_of(st.sampled_from(["enhanced_linear", "linear"]), junk),
           "hinge_limits": st.one_of(st.lists(edgy_floats, max_size=3), junk),
           "fixed": st.one_of(junk, st.lists(st.lists(st.sampled_from([0, 1, True, 0.5, float("nan")]),
                                                      min_size=3, max_size=3), max_size=8))}))
def test_model(nodes, bars, hinges, properties):
    properties.setdefault("bar_modulus", 1.0)
    properties.setdefault("hinge_stiffness", 0.1)
    model = attempt(lambda: Model(nodes, bars, hinges, **properties), *MODEL)
    if model is None:
        return
    u = np.zeros(model.num_dofs)
    state = attempt(lambda: model.element_state(u), "u")
    if state is not None:
        finite(*state.values())
    a = attempt(lambda: assemble(model, u), "u")
    if a is not None:
        finite(a.energy, a.force, a.stiffness.data)


@fuzz(200)
@given(st.integers(1, 6), st.one_of(junk, st.sampled_from(["x", "y", "z", 0, 1, 2, 3])),
       st.one_of(index, junk), st.one_of(junk, st.lists(edgy_floats, max_size=20)))
def test_model_views(n, axis, node, u):
    model = Model(np.c_[np.arange(n + 2.0), np.zeros(n + 2), np.zeros(n + 2)],
                  [[i, i + 1] for i in range(n + 1)], [], bar_modulus=1.0, hinge_stiffness=0.0)
    dof = attempt(lambda: model.dof(node, axis), "node", "axis")
    assert dof is None or 0 <= dof < model.num_dofs
    state = attempt(lambda: model.element_state(u), "u")
    if state is not None:
        finite(*state.values())


@fuzz(200)
@given(vertices, st.one_of(panels, grid_panels, junk),
       st.one_of(st.sampled_from(["N4B5", "N5B8"]), junk), st.booleans())
def test_panel_topology_and_elements(nodes, faces, split, duplicate):
    topology = attempt(lambda: panel_topology(nodes, faces, split=split,
                                              duplicate_shared_edges=duplicate),
                       "nodes", "panels", "panel", "split", "vertex", "face")
    if topology is not None:
        finite(topology.nodes)
    elements = attempt(lambda: build_panel_elements(nodes, faces, split=split),
                       "vertices", "panels", "panel", "split", "vertex", "face")
    if elements is not None:
        finite(elements.nodes)


@fuzz(120)
@given(st.lists(st.lists(st.floats(-0.3, 0.3), min_size=3, max_size=3), min_size=6, max_size=6),
       st.one_of(grid_panels, panels, junk),
       mostly(st.tuples(st.just(SheetMaterial), mostly(st.floats(1, 1e4), edgy_floats),
                        mostly(st.floats(-0.9, 0.5), edgy_floats),
                        mostly(st.floats(0.01, 1), edgy_floats)),
              st.tuples(st.just(ManualProperties), mostly(st.floats(1, 1e4), edgy_floats),
                        mostly(st.floats(0.1, 10), edgy_floats)),
              junk),
       st.one_of(st.sampled_from(["N5B8", "N4B5"]), junk),
       st.one_of(st.sampled_from(["merlin2", "mean"]), junk), st.booleans())
def test_build_pattern_model(offsets, faces, material, split, centre, compat):
    if isinstance(material, tuple):  # built here: a bad value is a ValueError to check
        kind, *values = material
        material = attempt(lambda: kind(*values), "youngs_modulus", "poisson_ratio",
                           "thickness", "bar_modulus", "bar_area")
        if material is None:
            return
    pm = attempt(lambda: build_pattern_model((flat_sheet(offsets), faces), material=material,
                                             split=split, centre=centre, merlin2_compat=compat),
                 "pattern", "panel", "panels", "material", "split", "centre", "vertices",
                 "youngs_modulus", "poisson_ratio", "thickness", "bar_modulus", "bar_area",
                 "face", "vertex")
    if pm is not None:
        m = pm.model
        finite(m.nodes, m.bar_area, m.bar_rest_length, m.hinge_stiffness, m.hinge_rest_angle)
        a = assemble(m)
        finite(a.energy, a.force)


@fuzz(150)
@given(st.builds(Design, n=st.integers(3, 12), lam=st.floats(0.55, 0.95), Lc=st.floats(0, 80)),
       st.one_of(st.lists(st.sampled_from([0, 1]), min_size=1, max_size=4),
                 st.lists(st.one_of(st.integers(-1, 2), junk), max_size=3), junk),
       st.one_of(st.none(), st.lists(st.sampled_from([1, -1]), max_size=4), junk))
def test_kresling_specimen(design, states, chirality):
    specimen = attempt(lambda: kresling_specimen(design, states, chirality),
                       "states", "chirality", "state")
    if specimen is not None:
        assume(specimen.model.num_nodes < 200)
        finite(specimen.model.nodes, specimen.model.hinge_rest_angle)
