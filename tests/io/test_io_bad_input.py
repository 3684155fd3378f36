"""Bad input to the io: a ValueError naming the parameter, the value and what is allowed
(the command line: one line on stderr, exit 2), never another exception, a hang or a
silent NaN. Reproducers of defects a fuzzing audit found; each must stay fixed (the C++
side of several is in cpp/tests/test_hardening.cpp)."""


import pytest



# Found by the fuzz suite (tests/fuzz): each a reproducer.
def test_fold_coordinates_beyond_the_float_range(tmp_path):
    from kresling.io import read_fold
    path = tmp_path / "big.fold"
    path.write_text('{"vertices_coords": [[0, 0], [1, 0], [' + "9" * 400 + ', 1]], '
                    '"faces_vertices": [[0, 1, 2]]}')
    with pytest.raises(ValueError, match=r"big.fold: key 'vertices_coords'\[2\]"):
        read_fold(path)
