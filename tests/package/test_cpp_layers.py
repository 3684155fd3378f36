"""Includes go one way in the C++ core: every ``#include "kresling/<folder>/..."`` of every
file under cpp/kresling is checked against the folder table of docs/architecture.md
('The C++ layers'), as tests/package/test_architecture.py checks the Python imports."""

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CORE = ROOT / "cpp" / "kresling"
ARCHITECTURE = ROOT / "docs" / "architecture.md"

# Each folder and the other folders its files may include (a folder may always include
# itself): the table of docs/architecture.md, encoded once here. Change the two together.
CPP_LAYERS = {
    "core": set(),
    "geometry": {"core"},
    "kinematics": {"core"},
    "elements": {"core"},
    "contact": {"core"},
    "model": {"core", "geometry", "elements", "contact"},
    "assembly": {"core", "geometry", "elements", "contact", "model"},
    "solvers": {"core", "geometry", "elements", "contact", "model", "assembly"},
    "analyses": {"core", "geometry", "elements", "contact", "model", "assembly", "solvers"},
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"kresling/(\w+)/[^"]*"', re.MULTILINE)


def violations(files=None):
    """'path:line: <folder> may not include <other> (...)' for every include that goes up or
    sideways; a folder missing from the table is reported too."""
    found = []
    for path in files if files is not None else sorted(CORE.glob("*/*.[ch]pp")):
        folder = path.parent.name
        text = path.read_text(encoding="utf-8")
        if folder not in CPP_LAYERS:
            found.append(f"{path.relative_to(ROOT)}: folder '{folder}' is not in the C++ layer "
                         "table: add it to docs/architecture.md and to CPP_LAYERS")
            continue
        for match in INCLUDE.finditer(text):
            other = match.group(1)
            if other != folder and other not in CPP_LAYERS[folder]:
                line = text.count("\n", 0, match.start()) + 1
                found.append(f"{path.relative_to(ROOT)}:{line}: {folder} may not include "
                             f"{other} ({match.group(0).strip()})")
    return found


def test_every_include_goes_down():
    assert violations() == []


def test_the_table_is_the_one_in_docs():
    text = ARCHITECTURE.read_text(encoding="utf-8")
    section = text.split("## The C++ layers", 1)[1].split("\n## ", 1)[0]
    rows = re.findall(r"^\| `(\w+)` \| ([^|]*) \|", section, flags=re.MULTILINE)
    documented = {name: {x.strip(" `") for x in deps.split(",") if x.strip(" `-")}
                  for name, deps in rows}
    assert documented == CPP_LAYERS


@pytest.mark.parametrize("folder, include, message", [
    ("elements", '#include "kresling/model/model.hpp"\n', "elements may not include model"),
    ("model", '#include "kresling/assembly/workspace.hpp"\n', "model may not include assembly"),
    ("assembly", '#include "kresling/solvers/newton.hpp"\n', "assembly may not include solvers"),
    ("kinematics", '#include "kresling/model/arm.hpp"\n', "kinematics may not include model"),
    ("contact", '#include "kresling/elements/bar.hpp"\n', "contact may not include elements"),
    ("elements", '#include "kresling/contact/contact_ccd.hpp"\n', "elements may not include contact"),
])
def test_an_include_that_goes_up_is_caught(tmp_path, folder, include, message):
    # A file planted in `folder` (a copy of the tree's layout under tmp_path).
    probe = tmp_path / "cpp" / "kresling" / folder / "probe.cpp"
    probe.parent.mkdir(parents=True)
    probe.write_text('#include "kresling/core/types.hpp"\n' + include, encoding="utf-8")
    global ROOT
    saved, ROOT = ROOT, tmp_path
    try:
        found = violations([probe])
    finally:
        ROOT = saved
    assert len(found) == 1 and message in found[0] and found[0].endswith(include.strip() + ")")
    assert ":2:" in found[0]
