"""The report's sections, one module per chapter, in thesis order: :mod:`.geometry`,
:mod:`.experiments`, :mod:`.analyses`, :mod:`.sweeps`, :mod:`.fabrication`,
:mod:`.manipulator`.

Each module provides ``reproduce(out_dir, quick=True) -> Section``: it runs the library on
the thesis's designs, compares the numbers with the thesis's (reference values and tolerances
in :mod:`kresling.report.thesis_values`) and writes its figures and tables into ``out_dir``.
The library never imports them; :data:`kresling.report.chapters.CHAPTERS` does.
"""
