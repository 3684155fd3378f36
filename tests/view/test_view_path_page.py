"""The compact path page (kresling.view.path_page): its binary parts decoded here by an
independent reading of the format (as the page's script reads it), its size on MERLIN2's
examples, and that writing it imports none of plotly's Python."""

from __future__ import annotations

import json
import re
import subprocess
import sys
import zlib
from pathlib import Path

import numpy as np
import pytest

from kresling.view.path_page import encode_frames, write_path_page
from kresling.view.plotly_js import ALPHABET, encode85, packed_plotly_js, plotly_js_path

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = [*sorted((ROOT / "tests" / "data" / "merlin2_examples").glob("*/problem.toml")),
            ROOT / "examples" / "miura_bending" / "problem.toml"]


def decode85(text: str) -> bytes:
    """The page's decoding, written out digit by digit."""
    value = {c: i for i, c in enumerate(ALPHABET)}
    pad, body = int(text[0]), text[1:]
    out = bytearray()
    for k in range(0, len(body), 5):
        number = 0
        for c in body[k:k + 5]:
            number = number * 85 + value[c]
        out += number.to_bytes(4, "big")
    return bytes(out[:len(out) - pad])


def decode_frames(blob: bytes, frames: int, values: int) -> np.ndarray:
    """Grid values (F, M) from encode_frames's bytes: planes joined, differences summed."""
    raw = np.frombuffer(zlib.decompress(blob), dtype=np.uint8)
    count = frames * values
    q = (raw[:count].astype(np.int64) | (raw[count:].astype(np.int64) << 8)).reshape(
        frames, values)
    for _ in range(2):
        q = np.cumsum(q, axis=0) % 65536
    return q


def page_parts(page: Path) -> dict:
    text = page.read_text(encoding="utf-8")
    return {name: re.search(f'id="kresling-{name}">(.*?)</script>', text, re.S).group(1)
            for name in ("plotly", "figure", "frames")}


@pytest.mark.parametrize("length", [0, 1, 2, 3, 4, 5, 9, 1000])
def test_the_text_encoding_round_trips(length):
    data = np.random.default_rng(length).integers(0, 256, length, dtype=np.uint8).tobytes()
    text = encode85(data)
    assert decode85(text) == data
    assert len(text) == 1 + 5 * -(-length // 4)
    assert not set(text) & set("\"'\\<>&`"), "a character that could end the script"


def test_the_frames_hold_every_position_to_half_a_grid_step():
    rng = np.random.default_rng(3)
    # A smooth path with a rough part: the differences need their wrap-around both ways.
    t = np.linspace(0, 1, 40)[:, None, None]
    points = rng.uniform(-50, 50, (1, 30, 3)) + 20 * np.sin(6 * t) + rng.normal(0, 2, (40, 30, 3))
    low, high = points.min(axis=(0, 1)) - 1, points.max(axis=(0, 1)) + 1
    q = decode_frames(encode_frames(points, low, high), 40, 90).reshape(40, 30, 3)
    back = low + q / 65535 * (high - low)
    step = (high - low) / 65535
    assert np.all(np.abs(back - points) <= 0.5 * step + 1e-12 * (high - low))


def test_the_packed_javascript_is_plotlys():
    text = packed_plotly_js()
    assert zlib.decompress(decode85(text)) == plotly_js_path().read_bytes()


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    from kresling.simulate import simulate

    out = tmp_path_factory.mktemp("pages")
    written = {}
    for problem in EXAMPLES:
        sim = simulate(problem, progress=False)
        written[problem.parent.name] = sim, sim.write(out / problem.parent.name)["view"]
    return written


def test_merlin2s_examples_give_pages_under_2_mb(pages):
    for name, (_, page) in pages.items():
        assert page.stat().st_size < 2_000_000, (name, page.stat().st_size)


def test_the_page_holds_the_path(pages):
    sim, page = pages["gmiura_pointload"]
    parts = page_parts(page)
    spec = json.loads(parts["figure"])
    info = spec["frames"]
    rows = np.array(info["rows"])
    assert info["names"] == [str(r + 1) for r in rows] and len(rows) == 200
    q = decode_frames(decode85(parts["frames"]), len(rows), 3 * sim.model.num_nodes)
    low, span = np.array(info["low"]), np.array(info["span"])
    shown = low + q.reshape(len(rows), -1, 3) / 65535 * span
    exact = sim.model.nodes + sim.path.displacement[rows].reshape(len(rows), -1, 3)
    assert np.abs(shown - exact).max() <= 0.5 * span.max() / 65535 * (1 + 1e-9)
    # The curve: the drive's reaction against the driven displacement, every increment, to
    # 10 significant digits of its largest value.
    curve = spec["data"][-2]
    dof = int(sim.path.constraint_dofs[0])
    for shown_values, exact_values in ((curve["x"], sim.path.displacement[:, dof]),
                                       (curve["y"], sim.path.constraint_force[:, 0])):
        scale = np.abs(exact_values).max()
        assert np.abs(np.array(shown_values) - exact_values).max() <= 1e-9 * scale
    assert spec["layout"]["yaxis"]["title"]["text"].startswith("reaction_58_y")


def test_writing_outputs_imports_none_of_plotlys_python(tmp_path):
    script = f"""
import sys
from kresling.simulate import simulate
sim = simulate({str(EXAMPLES[-1])!r}, progress=False)
sim.write({str(tmp_path)!r})
print(sorted(m for m in sys.modules if m.startswith("plotly")))
"""
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                            timeout=300)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "[]"
    assert (tmp_path / "view.html").is_file()


def test_bad_increments_are_refused(tmp_path):
    from view_cases import miura_sheet

    model, topo, family, path = miura_sheet()
    with pytest.raises(ValueError, match="increments has shape"):
        write_path_page(model, path, tmp_path / "v.html", increments=[1, 2])
    with pytest.raises(ValueError, match="path has no increments"):
        write_path_page(model, type("P", (), {"displacement": np.zeros((0, 3))})(),
                        tmp_path / "v.html")
