"""Bad input to the fits: a ValueError naming the parameter, the value and what is allowed
(the command line: one line on stderr, exit 2), never another exception, a hang or a
silent NaN. Reproducers of defects a fuzzing audit found; each must stay fixed (the C++
side of several is in cpp/tests/test_hardening.cpp)."""


import pytest



def test_a_run_list_cannot_point_outside_its_folder(tmp_path):
    from kresling.fits.crease_files import read_crease_runs
    secret = tmp_path / "secret.csv"
    secret.write_text("displacement (mm),force (N)\n0,0\n1,1\n")
    folder = tmp_path / "runs"
    folder.mkdir()
    header = ("sample,run,record,Lp_mm,W_mm,vertex_x1_px,vertex_y1_px,upper_x1_px,upper_y1_px,"
              "lower_x1_px,lower_y1_px,vertex_x2_px,vertex_y2_px,upper_x2_px,upper_y2_px,"
              "lower_x2_px,lower_y2_px\n")
    for record in ("../secret.csv", str(secret)):
        (folder / "runs.csv").write_text(header + f"1,1,{record},10,20" + ",1" * 12 + "\n")
        with pytest.raises(ValueError, match=r"column 'record': .* is invalid: must be a file "
                                             r"in the list's folder"):
            read_crease_runs(folder / "runs.csv")


def test_fits_that_overflow_name_the_file(tmp_path):
    from kresling.fits import fit_bending_files
    record = tmp_path / "huge.csv"
    record.write_text("# state: extended\n# module_length: 110 mm\ndisplacement (mm),force (N)\n"
                      "0,0\n1,1e308\n2,1e308\n")
    with pytest.raises(ValueError, match=r"huge.csv: the fitted K_B = .* is not finite"):
        fit_bending_files([record])
