"""The README says true things: its first example runs and prints what it shows, the
geometry it shows is what ``kresling design`` prints, the system libraries it lists are the
ones the build needs, and its links resolve. (The quick report's table it shows is compared
with a real run in test_report_browser.py, which makes that report anyway.)"""

import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text(encoding="utf-8")


def block_after(marker: str, language: str) -> str:
    """The first fenced block of ``language`` after the text ``marker``."""
    start = README.index(marker)
    match = re.compile(rf"^```{language}\n(.*?)^```", re.S | re.M).search(README, start)
    assert match, f"no ```{language} block after {marker!r}"
    return match.group(1)


def test_the_first_example_runs_and_prints_what_the_readme_shows():
    code = block_after("## A first example", "python")
    assert len(code.strip().splitlines()) <= 10, "the first example is ten lines at most"
    shown = block_after("## A first example", "text")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                            timeout=300, cwd=ROOT)
    assert result.returncode == 0, result.stderr
    assert result.stdout == shown


def test_the_geometry_shown_is_what_kresling_design_prints():
    shown = block_after("prints the\ngeometry of the thesis's optimal design", "text")
    result = subprocess.run([sys.executable, "-m", "kresling", "design", "--n", "10", "--lam",
                             "0.9", "--Lc", "15", "--R", "30"], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    printed = [line.rstrip() for line in result.stdout.splitlines()]
    lines = [line.rstrip() for line in shown.splitlines() if line.strip() != "..."]
    assert lines and all(line in printed for line in lines), (lines, printed)
    positions = [printed.index(line) for line in lines]
    assert positions == sorted(positions)  # in the order printed


def test_the_system_libraries_listed_are_those_the_build_needs():
    makefile = (ROOT / "Makefile").read_text()
    apt = re.search(r"^APT_PACKAGES := (.*)$", makefile, re.M).group(1).split()
    quick_start = README[README.index("## Quick start"):README.index("## Installing")]
    install = README[README.index("## Installing"):README.index("## A first example")]
    for package in apt:  # named where make demo installs them, and in the pip table
        assert f"`{package}`" in quick_start, package
        assert f"`{package}`" in install, package
    cmake = (ROOT / "cmake" / "KreslingDependencies.cmake").read_text()
    libraries = re.search(r"foreach\(lib ([a-z ]+)\)", cmake).group(1).split()
    table = install.lower().replace("_", "")
    for library in libraries:  # cholmod ... suitesparseconfig
        assert library in table, library
    for found in re.findall(r'kresling_missing\("([^"]+)"', cmake):
        assert found.split()[0].lower() in table, found


def test_the_readme_links_resolve():
    links = re.findall(r"\]\(([^)#]+)(?:#[^)]*)?\)", README)
    local = [link for link in links if "://" not in link]
    assert len(local) >= 10
    missing = [link for link in local if not (ROOT / link).exists()]
    assert not missing, missing
