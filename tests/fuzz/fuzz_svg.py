"""Fuzz: the SVG crease-pattern reader on random bytes and on mutated valid drawings. A bad
file is a ValueError naming the file (or an OSError); a pattern read is finite and planar
(every face has 3 or more vertices, indices in range)."""

from pathlib import Path

from hypothesis import given
from hypothesis import strategies as st

from _fuzz import fuzz, mutated
from fuzz_io import check_read
from kresling.io import read_pattern, read_svg

DATA = Path(__file__).resolve().parents[1] / "data" / "patterns"
VALID = (DATA / "flapping_bird.svg").read_bytes()
WORDS = [b"", b"<", b">", b"/>", b"\"", b"0", b"-1", b"1e308", b"1e999", b"nan", b"inf",
         b" stroke=\"red\"", b" stroke=\"#00f\"", b" stroke-opacity=\"-3\"", b" opacity=\"x\"",
         b" transform=\"scale(0)\"", b" transform=\"scale(1e300)\"", b" transform=\"rotate(\"",
         b"<path stroke=\"red\" d=\"M 0 0 C 1 1 2 2 3 3\"/>", b"<line x1=\"nan\"/>",
         b"<polyline stroke=\"blue\" points=\"0,0 5\"/>", b"<rect stroke=\"black\" width=\"-4\"/>",
         b"<!DOCTYPE svg [<!ENTITY a \"aaaa\">]>", b"\x00", b"\xff\xfe", b"\n"]


@fuzz(60)
@given(st.binary(max_size=300), st.sampled_from([read_svg, read_pattern]))
def test_random_bytes(data, reader):
    check_read(data, ".svg", reader)


@fuzz(120)
@given(st.lists(st.tuples(st.integers(0, 10**5), st.integers(1, 40)), max_size=3),
       st.lists(st.tuples(st.integers(0, 10**5), st.sampled_from(WORDS)), max_size=4))
def test_mutated_drawings(cuts, insertions):
    check_read(mutated(VALID, cuts, insertions), ".svg", read_svg)
