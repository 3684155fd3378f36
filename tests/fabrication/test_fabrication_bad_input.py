"""Bad input to the fabrication: a ValueError naming the parameter, the value and what is allowed
(the command line: one line on stderr, exit 2), never another exception, a hang or a
silent NaN. Reproducers of defects a fuzzing audit found; each must stay fixed (the C++
side of several is in cpp/tests/test_hardening.cpp)."""


import pytest

from kresling import Design


# 13. Fabrication without a size limit: 198 784 paths, a 41k x 181k px PNG.
def test_fabrication_has_a_size_limit(tmp_path):
    from kresling.fabrication import cut_sheet, write_pattern
    with pytest.raises(ValueError, match=r"spans .* mm: a cut sheet must be at most 5000 mm"):
        cut_sheet(Design(17, 0.82, 10000, 1621), "paper")
    with pytest.raises(ValueError, match=r"the sheet would hold \d+ cut paths: at most 50000; "
                                         r"lengthen the dashes \(dash_length = 0.001 mm"):
        cut_sheet(Design(10, 0.9, 15), "paper", dash_length=1e-3, tie_length=1e-3)
    with pytest.raises(ValueError, match=r"^dpi = 100000 is invalid for a .* sheet: the PNG "
                                         r"would have .* pixels; must be at most"):
        write_pattern(tmp_path / "big.png", Design(10, 0.9, 15), dpi=100_000)
