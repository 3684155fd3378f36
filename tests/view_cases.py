"""Small models and paths shared by the tests of kresling.view."""

import numpy as np

from kresling import Design
from kresling.model import Model, kresling_specimen, panel_topology
from kresling.solvers import solve_displacement_control

#: A 2 x 2 sheet of quads, Miura-like: the middle column zig-zags in y, the middle row is
#: raised, so the sheet is folded at rest [mm].
MIURA_NODES = np.array([[10.0 * i, 10.0 * j + (3.0 if i == 1 else 0.0), 2.0 if j == 1 else 0.0]
                        for j in range(3) for i in range(3)])
MIURA_PANELS = [[0, 1, 4, 3], [1, 2, 5, 4], [3, 4, 7, 6], [4, 5, 8, 7]]


def miura_sheet(steps=10):
    """The sheet, its topology, hinge families and a path: node 0 pinned, nodes 1 and 3 on
    rollers, the far corner (node 8) pulled 3 mm in -y.

    Returns
    -------
    (Model, Topology, ndarray of str, PathResult)
    """
    topo = panel_topology(MIURA_NODES, MIURA_PANELS)
    fixed = np.zeros((9, 3), bool)
    fixed[0] = True
    fixed[1, [1, 2]] = True
    fixed[3, [0, 2]] = True
    model = Model.from_panels(MIURA_NODES, MIURA_PANELS, bar_modulus=1e3, hinge_stiffness=1.0,
                              fixed=fixed)
    family = np.where(topo.hinge_is_bend, "bend",
                      np.where(np.arange(len(topo.hinges)) % 2 == 0, "mountain", "valley"))
    prescribed = np.zeros((9, 3))
    prescribed[8, 1] = -3.0
    return model, topo, family, solve_displacement_control(model, prescribed, steps)


def kresling_bending(steps=40, deflection=5.0, design=Design(8, 0.8, 30), cells=4):
    """The thesis's three-point bending test of an extended stack, as
    ``kresling.analyses.bending_test`` sets it up: vertices 0 and n/2 and the centre of the
    end polygons pinned, the middle polygon driven ``deflection`` mm in -y.

    Returns
    -------
    (KreslingSpecimen, PathResult)
    """
    n = design.n
    fixed = np.zeros(((cells + 1) * (n + 1), 3), bool)
    for level in (0, cells):
        for j in (0, n // 2, n):
            fixed[level * (n + 1) + j] = True
    specimen = kresling_specimen(design, [1] * cells, fixed=fixed)
    prescribed = np.zeros_like(fixed, dtype=float)
    prescribed[specimen.level_nodes(cells // 2), 1] = -deflection
    return specimen, solve_displacement_control(specimen.model, prescribed, steps,
                                                extrapolation=2)


def page_figure(page):
    """The figure an HTML page of :func:`kresling.view.write_html` holds, parsed from the
    JSON the page passes to plotly: ``(data, layout, frames)`` (lists and dicts; frames
    empty for a page without them)."""
    import json

    decoder = json.JSONDecoder()
    call = page.index("Plotly.newPlot(")
    data, end = decoder.raw_decode(page, page.index("[", call))
    layout, end = decoder.raw_decode(page, page.index("{", end))
    frames = []
    if "Plotly.addFrames(" in page[end:]:
        frames, _ = decoder.raw_decode(page, page.index("[", page.index("Plotly.addFrames(",
                                                                        end)))
    return data, layout, frames
