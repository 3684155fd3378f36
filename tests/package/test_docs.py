"""The documentation site builds without a warning, and what its pages claim holds.

The build test runs Sphinx with warnings as errors on a copy of the sources (so that the
pages the build generates never mix with those of ``make docs``). It builds every page: the
Markdown guides, the API reference of every public package, the command-line reference, the
gallery's pages and the notebooks' pages, but executes neither the notebooks nor the
gallery's scripts (``-D nb_execution_mode=off -D plot_gallery=0``): that takes ~20 s instead
of ~70 s. ``make docs`` runs the full build (the notebooks also run in test_notebooks.py, the
gallery's scripts below). It is skipped, saying so, only when the ``docs`` extra is not
installed; ``make test`` installs it.
"""

from __future__ import annotations

import importlib.util
import re
import runpy
import shutil
import subprocess
import sys
from pathlib import Path

import matplotlib
import pytest

import kresling

matplotlib.use("Agg")

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
GALLERY = ROOT / "examples" / "gallery"
DOCS_EXTRA = ("sphinx", "myst_nb", "numpydoc", "pydata_sphinx_theme", "sphinx_gallery",
              "sphinxarg")
MISSING = [name for name in DOCS_EXTRA if importlib.util.find_spec(name) is None]
#: What the build writes into the source folder (left out of the copy).
GENERATED = ("_build", "_generated", "api", "auto_examples", "notebooks",
             "sg_execution_times.rst")


def _copy_sources(target: Path) -> Path:
    """docs/ and what its pages read from outside it, laid out as in the repository."""
    shutil.copytree(DOCS, target / "docs", ignore=lambda folder, names: [
        name for name in names if Path(folder) == DOCS and name in GENERATED
        or name == "__pycache__"])
    shutil.copytree(GALLERY, target / "examples" / "gallery",
                    ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copytree(ROOT / "notebooks", target / "notebooks",
                    ignore=shutil.ignore_patterns(".ipynb_checkpoints"))
    shutil.copy(ROOT / "CHANGELOG.md", target / "CHANGELOG.md")
    return target / "docs"


@pytest.mark.slow
@pytest.mark.skipif(bool(MISSING), reason=f"the 'docs' extra is not installed (missing: "
                    f"{', '.join(MISSING)}): pip install -e '.[docs]'")
def test_docs_build_without_warnings(tmp_path):
    source = _copy_sources(tmp_path / "src")
    out = tmp_path / "html"
    result = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html",
         "-D", "nb_execution_mode=off", "-D", "plot_gallery=0", str(source), str(out)],
        capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, f"Sphinx failed:\n{result.stderr[-6000:]}"
    for page in ("index", "getting_started", "concepts", "cli", "references", "changelog",
                 "howto/cut_file", "howto/bending_study", "howto/cluster_sweep",
                 "howto/own_pattern", "api/index", "auto_examples/index", "notebooks"):
        assert (out / f"{page}.html").is_file(), page
    # Every public package has its page, and every name of its __all__ a page of its own.
    sys.path.insert(0, str(DOCS))
    try:
        from _api_pages import PACKAGES, homes, public_names
    finally:
        sys.path.remove(str(DOCS))
    home = homes()
    for package in PACKAGES:
        assert (out / "api" / f"{package}.html").is_file(), package
        module = importlib.import_module(package)
        for name in public_names(module):
            where = home.get(id(getattr(module, name)), (package, name))
            assert (out / "api" / "generated" / f"{where[0]}.{where[1]}.html").is_file(), \
                f"{package}.{name}"
    # The command-line page lists every subcommand.
    cli = (out / "cli.html").read_text()
    from kresling.cli import _COMMANDS
    for command in _COMMANDS:
        assert f'<section id="kresling-{command}">' in cli, command
    # The notebooks' pages are there, one per notebook.
    for notebook in (ROOT / "notebooks").glob("*.ipynb"):
        assert (out / "notebooks" / f"{notebook.stem}.html").is_file(), notebook.name
    assert (out / "_images" / "kresling_cell.svg").is_file()  # the concepts page's diagram


@pytest.mark.parametrize("script", sorted(GALLERY.glob("plot_*.py")), ids=lambda p: p.name)
def test_gallery_script_runs(script, tmp_path, monkeypatch):
    """The gallery's scripts (executed by make docs, not by the build test above)."""
    import matplotlib.pyplot as plt

    monkeypatch.chdir(tmp_path)
    runpy.run_path(str(script), run_name="__main__")
    assert plt.get_fignums(), f"{script.name} drew nothing"
    plt.close("all")


def test_getting_started_example_prints_what_the_page_says(capsys):
    page = (DOCS / "getting_started.md").read_text()
    example = re.search(r"## A first example.*?```python\n(.*?)```.*?```text\n(.*?)```", page,
                        re.DOTALL)
    code, printed = example[1], example[2]
    assert len(code.strip().splitlines()) <= 12
    exec(compile(code, "getting_started.md", "exec"), {})
    assert capsys.readouterr().out == printed


def _version_in(path: Path, pattern: str) -> str:
    match = re.search(pattern, path.read_text(), re.MULTILINE)
    assert match, f"no version in {path.name}"
    return match[1]


def test_versions_agree():
    version = kresling.__version__
    assert _version_in(ROOT / "pyproject.toml", r'^version = "([^"]+)"') == version
    assert _version_in(ROOT / "CMakeLists.txt", r"^project\(kresling VERSION (\S+)") == version
    assert _version_in(ROOT / "CITATION.cff", r"^version: (\S+)") == version
    assert _version_in(ROOT / "CHANGELOG.md", r"^## (\S+)") == version


def test_licence_and_citation():
    licence = (ROOT / "LICENSE").read_text()
    assert licence.startswith("BSD 3-Clause License") and "kresling developers" in licence
    assert 'license = { text = "BSD-3-Clause" }' in (ROOT / "pyproject.toml").read_text()
    citation = (ROOT / "CITATION.cff").read_text()
    assert "cff-version: 1.2.0" in citation and "license: BSD-3-Clause" in citation
    title = ("Bistable generalized Kresling origami as a stiffness-switching joint for a "
             "tendon-driven soft manipulator")
    assert f'title: "{title}"' in citation
    assert title in (DOCS / "references.md").read_text().replace("\n", " ")
