"""User-facing text refers to nothing the user cannot see: no issue numbers, no private files.

The text checked: README.md, CHANGELOG.md, every Markdown page of docs/, every docstring of
the package (modules, classes, functions, methods, properties; the compiled core's too) and
the help of the command line and of every subcommand. It must not mention issues ("issue 12",
"#12"), private notes ("NOTES", "MODEL.md"), or any document, notebook or script that is not
in the repository.
"""

from __future__ import annotations

import argparse
import importlib
import inspect
import pkgutil
import re
from pathlib import Path

import pytest

import kresling
from kresling.cli import build_parser

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
#: Folders of docs/ that the build writes (copies and generated pages), not written by hand.
GENERATED = {"_build", "_generated", "api", "auto_examples", "notebooks"}

#: What user-facing text must not contain, with what to say when it does.
FORBIDDEN = [
    (re.compile(r"\bissues?\b", re.IGNORECASE), "mentions an issue"),
    (re.compile(r"(?<![&\w])#\d+\b"), "refers to an issue number"),
    (re.compile(r"\bNOTES\b"), "refers to private notes"),
    (re.compile(r"\bprivate notes?\b", re.IGNORECASE), "refers to private notes"),
    (re.compile(r"\bMODEL\.md\b"), "refers to MODEL.md (the model is docs/model.md)"),
]
#: Documents, notebooks and scripts named in text: each must exist in the repository.
FILE_NAME = re.compile(r"(?<![\w/.<>-])((?:[\w.-]+/)*[\w-]+\.(?:md|ipynb|rst|py|cff))\b")


def _repository_files() -> set:
    skip = {".git", ".venv", "build", "_build", "__pycache__", ".pytest_cache", ".hypothesis"}
    files = set()
    for path in ROOT.rglob("*"):
        parts = path.relative_to(ROOT).parts
        if not any(part in skip for part in parts) and path.is_file():
            files.add(path.relative_to(ROOT).as_posix())
    return files


FILES = _repository_files()


def _exists(name: str, near: Path) -> bool:
    """Whether ``name`` is a file of the repository: relative to the text's own folder, to the
    root, to the package or to docs/, or the end of some file's path."""
    for base in (near, ROOT, ROOT / "kresling", DOCS):
        path = (base / name).resolve()
        if path.is_relative_to(DOCS) and path.relative_to(DOCS).parts[0] in GENERATED:
            return True  # a page the docs build writes
        if path.is_relative_to(ROOT) and path.relative_to(ROOT).as_posix() in FILES:
            return True
    return any(path == name or path.endswith("/" + name) for path in FILES)


def problems(text: str, near: Path = ROOT) -> list:
    """What is wrong with ``text``: each forbidden phrase and missing file it names."""
    found = [f"{why}: {match[0]!r}" for pattern, why in FORBIDDEN
             for match in pattern.finditer(text)]
    found += [f"names a file that is not in the repository: {match[1]!r}"
              for match in FILE_NAME.finditer(text) if not _exists(match[1], near)]
    return found


# -- the text ----------------------------------------------------------------------------------
def markdown_pages() -> list:
    pages = [ROOT / "README.md", ROOT / "CHANGELOG.md"]
    pages += sorted(path for path in DOCS.rglob("*.md")
                    if not GENERATED & set(path.relative_to(DOCS).parts[:-1]))
    return pages


def _members(obj):
    """Docstrings of a class's own methods and properties."""
    for name, member in vars(obj).items():
        if isinstance(member, (staticmethod, classmethod)):
            member = member.__func__
        if isinstance(member, property) or inspect.isroutine(member):
            yield f"{obj.__qualname__}.{name}", member.__doc__


def docstrings() -> dict:
    """Every docstring of the package, by dotted name."""
    names = {"kresling"} | {info.name for info in
                            pkgutil.walk_packages(kresling.__path__, "kresling.")}
    names.discard("kresling.__main__")  # runs the command line when imported
    found, seen = {}, set()

    def visit(module):
        if id(module) in seen:
            return
        seen.add(id(module))
        found[module.__name__] = module.__doc__
        for attribute, obj in vars(module).items():
            if inspect.ismodule(obj) and obj.__name__.startswith(module.__name__ + "."):
                visit(obj)  # the compiled core's submodules
            elif (inspect.isclass(obj) or inspect.isroutine(obj)) and \
                    getattr(obj, "__module__", None) == module.__name__:
                found[f"{module.__name__}.{attribute}"] = obj.__doc__
                if inspect.isclass(obj):
                    for name, doc in _members(obj):
                        found[f"{module.__name__}.{name}"] = doc

    for name in sorted(names):
        visit(importlib.import_module(name))
    return {name: doc for name, doc in found.items() if doc}


def command_help() -> dict:
    """``kresling --help`` and the help of every subcommand."""
    parser = build_parser()
    helps = {"kresling": parser.format_help()}
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, subparser in action.choices.items():
                helps[f"kresling {name}"] = subparser.format_help()
    return helps


# -- the tests ---------------------------------------------------------------------------------
@pytest.mark.parametrize("page", markdown_pages(), ids=lambda p: p.relative_to(ROOT).as_posix())
def test_markdown_page(page):
    assert problems(page.read_text(), page.parent) == []


def test_docstrings():
    found = {name: problems(doc) for name, doc in docstrings().items()}
    assert len(found) > 500, "the package's docstrings were not found"
    assert {name: what for name, what in found.items() if what} == {}


def test_command_help():
    helps = command_help()
    assert {"kresling design", "kresling simulate", "kresling reproduce"} <= set(helps)
    assert {name: problems(text) for name, text in helps.items() if problems(text)} == {}


@pytest.mark.parametrize("text, expected", [
    ("see issue 12 for the plan", "mentions an issue"),
    ("fixed in #12", "refers to an issue number"),
    ("as NOTES says", "refers to private notes"),
    ("the bars of MODEL.md", "refers to MODEL.md"),
    ("the private notes' bound", "refers to private notes"),
    ("see docs/nowhere.md", "not in the repository: 'docs/nowhere.md'"),
    ("run studies/missing_study.py", "not in the repository: 'studies/missing_study.py'"),
])
def test_the_check_finds(text, expected):
    """Negative controls: each kind of reference is caught."""
    assert any(expected in problem for problem in problems(text)), problems(text)


def test_the_check_passes_ordinary_text():
    text = ("See docs/model.md, docs/simulate.md and notebooks/03_solver.ipynb; open "
            "FILE.html#frame=K; colour #1f77b4; results.csv and problem.toml are yours; "
            "kresling/report/sections/<chapter>.py; ## 0.2.0")
    assert problems(text) == []
