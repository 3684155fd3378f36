"""Every notebook in notebooks/ executes without error (small sizes; they double as examples)."""

import re
from pathlib import Path

import nbformat
import pytest
from nbclient import NotebookClient

NOTEBOOKS = sorted((Path(__file__).resolve().parents[1] / "notebooks").glob("*.ipynb"))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_runs(path, tmp_path):
    notebook = nbformat.read(path, as_version=4)
    client = NotebookClient(notebook, timeout=600, kernel_name="python3",
                            resources={"metadata": {"path": str(tmp_path)}})
    client.execute()
    errors = [out for cell in notebook.cells if cell.cell_type == "code"
              for out in cell.get("outputs", []) if out.get("output_type") == "error"]
    assert not errors


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_is_named_by_its_thesis_chapter(path):
    """``NN_topic.ipynb``: NN is the thesis chapter the notebook's title names."""
    match = re.fullmatch(r"0([2-5])_[a-z_]+\.ipynb", path.name)
    assert match, f"{path.name}: name it NN_topic.ipynb, NN the thesis chapter (02-05)"
    title = nbformat.read(path, as_version=4).cells[0].source.splitlines()[0]
    assert re.search(rf"\b{match[1]}(\.\d+)?\b", title), (path.name, title)
