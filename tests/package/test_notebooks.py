"""Every notebook in notebooks/ executes without error (small sizes; they double as examples)."""

import re
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest
from nbclient import NotebookClient

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_runs(path, tmp_path):
    notebook = nbformat.read(path, as_version=4)
    client = NotebookClient(notebook, timeout=600, kernel_name="python3",
                            resources={"metadata": {"path": str(tmp_path)}})
    client.execute()
    errors = [out for cell in notebook.cells if cell.cell_type == "code"
              for out in cell.get("outputs", []) if out.get("output_type") == "error"]
    assert not errors


def test_notebooks_are_numbered_in_reading_order():
    """``NN_topic.ipynb``, NN = 01, 02, ... without gaps; the first designs a cell."""
    names = [path.name for path in NOTEBOOKS]
    for k, name in enumerate(names, start=1):
        assert re.fullmatch(rf"{k:02d}_[a-z0-9_]+\.ipynb", name), \
            f"{name}: the notebooks are numbered 01, 02, ... in reading order ({names})"
    assert names[0] == "01_design_your_own_cell.ipynb"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_is_stored_without_outputs(path):
    """Outputs are made where the notebooks are run (the docs build, this test), never stored."""
    notebook = nbformat.read(path, as_version=4)
    stored = [k for k, cell in enumerate(notebook.cells) if cell.cell_type == "code"
              and (cell.get("outputs") or cell.get("execution_count") is not None)]
    assert not stored, f"{path.name}: cells {stored} hold outputs; clear them before committing"


def test_every_notebook_named_in_the_documentation_exists():
    """References in the README, the docs, the notebooks and the Makefile follow renames."""
    names = {path.stem for path in NOTEBOOKS}
    texts = [ROOT / "README.md", ROOT / "Makefile", *sorted((ROOT / "docs").rglob("*.md")),
             *NOTEBOOKS]
    found = set()
    for text_path in texts:
        if "_build" in text_path.parts:
            continue
        for name in re.findall(r"\b(\d\d_[a-z0-9_]+?)(?:\.ipynb|`|\b)",
                               text_path.read_text(encoding="utf-8")):
            found.add(name)
            assert name in names, f"{text_path.relative_to(ROOT)} names notebook {name!r}"
    assert found, "no notebook reference found: the pattern is wrong"


def test_jupyter_nbconvert_comes_with_the_test_extra():
    """``jupyter nbconvert --execute`` is how users run a notebook from the shell."""
    try:
        import tomllib
    except ImportError:  # Python < 3.11
        tomllib = pytest.importorskip("tomli")
    extra = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"][
        "optional-dependencies"]["test"]
    assert any(re.match(r"nbconvert\b", requirement) for requirement in extra)
    jupyter = Path(sys.executable).parent / "jupyter"
    result = subprocess.run([str(jupyter), "nbconvert", "--version"], capture_output=True,
                            text=True)
    assert result.returncode == 0 and re.fullmatch(r"\d+\.\d+.*", result.stdout.strip()), \
        result.stderr
