"""FOLD export and 3D plot of a built specimen."""

import json

import numpy as np
import pytest

from kresling import Design
from kresling.analyses import bending_test
from kresling.analyses.specimen_views import (plot_specimen, specimen_edges, specimen_faces,
                                              write_specimen_fold)
from kresling.model import SpecimenParameters, kresling_specimen


@pytest.mark.parametrize("duplicate", [True, False])
def test_fold_file_of_a_bending_specimen(tmp_path, duplicate):
    d = Design(8, 0.8, 30)
    s = kresling_specimen(d, [1] * 4, parameters=SpecimenParameters(duplicate_shared_edges=duplicate))
    bent = bending_test(d, 1, parameters=s.parameters)
    path = write_specimen_fold(tmp_path / "specimen.fold", s,
                               frames=[("end of the bending test", bent.final_displacement)])
    doc = json.loads(path.read_text())
    n, cells = 8, 4
    assert len(doc["vertices_coords"]) == (cells + 1) * (n + 1)
    # 2n facets per cell and an n-triangle fan per level; one edge per geometric edge.
    assert len(doc["faces_vertices"]) == 2 * n * cells + n * (cells + 1)
    counts = {k: doc["edges_assignment"].count(k) for k in "VCMFB"}
    assert counts == {"V": n * cells, "C": n * cells, "M": n * (cells + 1), "F": n * (cells + 1), "B": 0}
    angles = np.array(doc["edges_foldAngle"])
    polygon = np.array(doc["edges_assignment"]) == "M"
    assert np.allclose(angles[polygon][:n], -(180 - np.degrees(d.psi_ext)))   # bottom polygon
    frame = doc["file_frames"][0]
    assert frame["frame_title"] == "end of the bending test"
    centre = 2 * (n + 1) + n
    assert frame["vertices_coords"][centre][1] == pytest.approx(-5.0)


def test_faces_point_outward():
    s = kresling_specimen(Design(6, 0.85, 20), [0, 1])
    X, faces = s.model.nodes, specimen_faces(s)
    a, b, c = (X[faces[:, k]] for k in range(3))
    normal = np.cross(b - a, c - a)
    centroid = (a + b + c) / 3
    fan = np.isin(faces, [s.centre(k) for k in range(3)]).any(axis=1)
    radial = np.einsum("ij,ij->i", normal[~fan][:, :2], centroid[~fan][:, :2])
    assert np.all(radial > 0)
    bottom = np.isin(faces[fan], s.centre(0)).any(axis=1)
    assert np.all(normal[fan][bottom, 2] < 0) and np.all(normal[fan][~bottom, 2] > 0)


def test_mountains_as_folds_when_not_cut():
    s = kresling_specimen(Design(4, 0.7, 30), [1])
    _, cut = specimen_edges(s)
    _, folded = specimen_edges(s, cut_mountains=False)
    assert cut.count("C") == 4 and folded.count("C") == 0 and folded.count("M") == 4 + 8


def test_plot_undeformed_and_deformed(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    d = Design(10, 0.9, 15)
    s = kresling_specimen(d, [0] * 4)
    plot_specimen(s).figure.savefig(tmp_path / "a.png")
    r = bending_test(d, 0)
    ax = plot_specimen(s, r.final_displacement, scale=3)
    assert "× 3" in ax.get_title()
    ax.figure.savefig(tmp_path / "b.png")
    assert (tmp_path / "b.png").stat().st_size > 10_000
