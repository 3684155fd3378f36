"""Imports go one way: every import in the package is checked against the layer table of
docs/architecture.md.

Every module of ``kresling`` is parsed with ``ast``; every ``import x`` and ``from x import
y`` in it, at the top of the module or inside a function or class (``if TYPE_CHECKING`` too),
absolute or relative, is resolved to the layer it reaches. A layer is the top-level module or
subpackage of ``kresling`` a file belongs to (``kresling/analyses/bending.py`` is in
``analyses``, ``kresling/geometry.py`` in ``geometry``, ``kresling/__init__.py`` in the front
page ``kresling``).
"""

import ast
import re
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import pytest

import kresling

PACKAGE = Path(kresling.__file__).resolve().parent
ARCHITECTURE = PACKAGE.parent / "docs" / "architecture.md"


def layer_table(text: str) -> dict:
    """The layer table of docs/architecture.md, the one place it is written: each layer and
    the other layers its modules may import (a module may always import its own layer).

    Its "may import" column is read as written: ``-`` (none), ``F`` (the foundation the
    text names), layers in backquotes, ``everything `x` may, and ...`` (layer x's and the
    named ones) and ``every layer`` (every layer above it in the table, which goes from the
    bottom up; ``but `x``` leaves x out).
    """
    foundation = set(re.findall(r"`([^`]+)`", re.search(
        r"\*\*F\*\* is the foundation: (.*?)\.\n", text, re.S).group(1)))
    table = text.split("\n## The table\n", 1)[1].split("\n## ", 1)[0]
    rows = re.findall(r"^\| `([^`]+)` \| [^|]* \| ([^|]*) \|", table, re.M)
    layers = {}
    for layer, may in rows:
        may = may.strip()
        allowed = set()
        if may.startswith("every layer"):
            allowed = set(layers)
            may = may.removeprefix("every layer").strip()
            if may.startswith("but"):
                allowed -= set(re.findall(r"`([^`]+)`", may))
                may = ""
        elif may.startswith("everything"):
            base, _, may = may.partition(" may")
            allowed = set(layers[re.search(r"`([^`]+)`", base).group(1)])
        if re.match(r"F\b", may):
            allowed |= foundation
        allowed |= set(re.findall(r"`([^`]+)`", may))
        layers[layer] = allowed
    return layers


LAYERS = layer_table(ARCHITECTURE.read_text(encoding="utf-8"))
FOUNDATION = LAYERS["geometry"] - {"geometry"}

#: Layers that may import kresling.report: the report itself and the command line on top.
ABOVE_REPORT = {"report", "cli"}


def layer_of(path: Path) -> str:
    """The layer of a file of the package."""
    parts = path.relative_to(PACKAGE).parts
    if parts == ("__init__.py",):
        return "kresling"
    return parts[0].removesuffix(".py")


def _is_module(name: str) -> bool:
    """Whether ``kresling.<name>`` is a module or subpackage (not an attribute of the front
    page such as ``__version__`` or ``Design``)."""
    return (name in LAYERS or (PACKAGE / name).is_dir() or (PACKAGE / f"{name}.py").is_file()
            or any(PACKAGE.glob(f"{name}.*.so")) or any(PACKAGE.glob(f"{name}.*.pyd")))


def _package_of(path: Path) -> list:
    """The dotted parts of the package a file's relative imports start from: the package of
    a module, or the package itself for an ``__init__.py``."""
    return ["kresling", *path.relative_to(PACKAGE).with_suffix("").parts][:-1]


def imports(path: Path):
    """``(line, dotted name imported, layer reached)`` for every import of the package in a
    file; the layer is None for imports from outside the package."""
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                yield node.lineno, alias.name, _layer_of_name(alias.name.split("."))
        elif isinstance(node, ast.ImportFrom):
            module = _from_module(path, node)
            for alias in node.names:
                if module == ["kresling"] and _is_module(alias.name):
                    target = ["kresling", alias.name]
                else:
                    target = module
                yield node.lineno, ".".join(module + [alias.name]), _layer_of_name(target)


def _from_module(path: Path, node: ast.ImportFrom) -> list:
    """The dotted parts of the module ``from ... import`` reads, a relative one resolved
    from the file's package."""
    if node.level:
        base = _package_of(path)
        return base[:len(base) - (node.level - 1)] + (node.module.split(".") if node.module
                                                       else [])
    return node.module.split(".")


def _layer_of_name(parts: list):
    if parts[0] != "kresling":
        return None
    return "kresling" if len(parts) == 1 else parts[1]


def files():
    return sorted(p for p in PACKAGE.rglob("*.py") if "__pycache__" not in p.parts)


def violations():
    """One message per import the table does not allow, and per unknown layer."""
    found = []
    for path in files():
        where = path.relative_to(PACKAGE.parent)
        layer = layer_of(path)
        if layer not in LAYERS:
            found.append(f"{where}: top-level module {layer!r} is not in the layer table: add "
                         f"it to the table of docs/architecture.md")
            continue
        for line, name, target in imports(path):
            if target is None or target == layer:
                continue
            if target not in LAYERS:
                found.append(f"{where}:{line}: imports {name}, of {target!r}, which is not in "
                             f"the layer table: add it to the table of docs/architecture.md")
            elif target not in LAYERS[layer]:
                found.append(f"{where}:{line}: {layer} may not import {target} ({name}); "
                             f"see docs/architecture.md")
    return found


def test_every_import_follows_the_layer_table():
    found = violations()
    assert not found, "imports against docs/architecture.md:\n" + "\n".join(found)


def test_no_library_package_imports_the_report():
    found = [f"{path.relative_to(PACKAGE.parent)}:{line}: imports {name}"
             for path in files() if layer_of(path) not in ABOVE_REPORT
             for line, name, target in imports(path) if target == "report"]
    assert not found, "the report is the top layer; the library may not import it:\n" + \
        "\n".join(found)


def test_importing_the_library_does_not_load_the_report():
    # Every module outside the report and the command line, imported in a fresh interpreter.
    names = sorted(".".join(["kresling", *p.relative_to(PACKAGE).with_suffix("").parts])
                   .removesuffix(".__init__") for p in files()
                   if layer_of(p) not in ABOVE_REPORT | {"__main__"})
    code = ("import importlib, sys\n"
            f"for name in {names!r}:\n"
            "    importlib.import_module(name)\n"
            "print(sorted(m for m in sys.modules if m.startswith('kresling.report')))\n")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                            timeout=300)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "[]"


def test_the_table_is_read_as_written():
    # Rows of each kind of "may import", and the rules that matter most.
    assert LAYERS["_core"] == set() and LAYERS["laws"] == {"_core"}
    assert FOUNDATION == {"_core", "_validation", "_lazy", "data", "laws", "io"}
    assert LAYERS["simulate"] == LAYERS["analyses"] | {"analyses", "view"}
    assert LAYERS["cli"] == set(LAYERS) - {"cli", "__main__"}
    assert LAYERS["report"] == set(LAYERS) - {"report", "cli", "__main__"}
    assert LAYERS["__main__"] == {"cli"}
    assert all(allowed <= set(LAYERS) for allowed in LAYERS.values())
    assert not any("report" in LAYERS[layer] for layer in set(LAYERS) - ABOVE_REPORT)


@pytest.mark.parametrize("source, message", [
    ("import kresling.report\n", "analyses may not import report (kresling.report)"),
    ("from kresling.fits.plots import label_moment_angle_axes\n",
     "analyses may not import fits (kresling.fits.plots.label_moment_angle_axes)"),
    ("def f():\n    from ..fabrication import fold\n",
     "analyses may not import fabrication (kresling.fabrication.fold)"),
    ("from kresling import report\n", "analyses may not import report (kresling.report)"),
    ("from .. import report\n", "analyses may not import report (kresling.report)"),
    ("from . import bending\nfrom .plots import plot_snap_through\nfrom .. import sweeps\n",
     "analyses may not import sweeps (kresling.sweeps)"),
    ("import kresling.newthing\n", "'newthing', which is not in the layer table"),
])
def test_the_check_sees_every_kind_of_import(tmp_path, monkeypatch, source, message):
    # A module planted in analyses: absolute, from-, function-level and relative imports.
    fake = PACKAGE / "analyses" / "_architecture_probe.py"
    monkeypatch.setattr(sys.modules[__name__], "files", lambda: [fake])
    original = Path.read_text
    monkeypatch.setattr(Path, "read_text", lambda self, *a, **k: source if self == fake
                        else original(self, *a, **k))
    found = violations()
    assert len(found) == 1 and message in found[0]
    assert found[0].startswith("kresling/analyses/_architecture_probe.py:")


def test_an_unknown_top_level_module_is_reported(monkeypatch):
    fake = PACKAGE / "newthing.py"
    monkeypatch.setattr(sys.modules[__name__], "files", lambda: [fake])
    found = violations()
    assert found == ["kresling/newthing.py: top-level module 'newthing' is not in the layer "
                     "table: add it to the table of docs/architecture.md"]


# The binding layer mirrors the C++ core: cpp/python/<folder>/bind_<header>.cpp binds what
# cpp/kresling/<folder>/<header>.hpp declares, into the submodule kresling._core.<folder>.
CPP = PACKAGE.parent / "cpp"


def _declarations():
    """Each class, struct or enum declared in a header of cpp/kresling -> the headers
    ('<folder>/<header>') declaring it, and each header -> its text."""
    types, text = {}, {}
    for header in sorted((CPP / "kresling").glob("*/*.hpp")):
        source = header.read_text(encoding="utf-8")
        key = f"{header.parent.name}/{header.stem}"
        text[key] = source
        for name in re.findall(r"^\s*(?:struct|class|enum class|enum)\s+(\w+)\b[^;]*$", source,
                               flags=re.MULTILINE):
            types.setdefault(name, set()).add(key)
    return types, text


def _bindings():
    """Each binding file's '<folder>/<header>' -> (the types it binds, the free functions it
    binds by address)."""
    out = {}
    for path in sorted((CPP / "python").glob("*/bind_*.cpp")):
        source = path.read_text(encoding="utf-8")
        # An alias (`using R = analyses::BendingResult;`) stands for the type it names; a
        # template's parameter (`py::class_<Result>&` in a helper) is no type of its own.
        aliases = dict(re.findall(r"using (\w+) = ([\w:]+);", source))
        parameters = set(re.findall(r"typename (\w+)", source))
        types = [aliases.get(t, t).split("::")[-1]
                 for t in re.findall(r"py::(?:class_|enum_)<([\w:]+)", source)
                 if t not in parameters]
        # A function bound by address, unless it is the binding file's own adapter.
        functions = [f.split("::")[-1]
                     for f in re.findall(r"m\.def\(\s*\"\w+\",\s*&([\w:]+)", source)
                     if not re.search(rf"^[\w:<>, ]+\s{f}\(", source, flags=re.MULTILINE)]
        out[f"{path.parent.name}/{path.stem.removeprefix('bind_')}"] = (types, functions)
    return out


def test_the_binding_files_mirror_the_cpp_headers():
    from kresling import _core

    folders = {p.name for p in (CPP / "kresling").iterdir() if p.is_dir()}
    bindings = _bindings()
    bound_folders = {key.split("/")[0] for key in bindings}
    assert bound_folders <= folders, "a binding folder for no folder of cpp/kresling"
    submodules = {name for name in dir(_core) if isinstance(getattr(_core, name), ModuleType)}
    assert submodules == bound_folders, "kresling._core's submodules are not the binding folders"
    module = (CPP / "python" / "module.cpp").read_text(encoding="utf-8")
    for key in bindings:
        folder, header = key.split("/")
        assert re.search(rf'def_submodule\(\s*"{folder}",[^;]*;(\s*kresling::python::bind_\w+'
                         rf'\({folder}\);)*\s*kresling::python::bind_{header}\({folder}\);',
                         module), f"module.cpp does not call bind_{header}({folder})"

    types, text = _declarations()
    for key, (bound_types, functions) in bindings.items():
        file = "cpp/python/" + key.replace("/", "/bind_") + ".cpp"
        assert key in text, f"{file}: there is no cpp/kresling/{key}.hpp"
        for name in bound_types:
            assert key in types.get(name, set()), \
                f"{file} binds {name}, declared in {sorted(types.get(name, []))}"
        for name in functions:
            assert re.search(rf"\b{name}\(", text[key]), \
                f"{file} binds {name}(), not declared in cpp/kresling/{key}.hpp"
    # A type of a folder without binding files (`core`, which has nothing to bind) is bound
    # nowhere.
    for folder in folders - bound_folders:
        for bound_types, _ in bindings.values():
            assert not [t for t in bound_types
                        if types.get(t) and {k.split("/")[0] for k in types[t]} == {folder}], \
                f"types of cpp/kresling/{folder} bound outside cpp/python/{folder}"


def _module_name(path: Path) -> str:
    parts = ["kresling", *path.relative_to(PACKAGE).with_suffix("").parts]
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def import_graph() -> dict:
    """Module -> the package's modules it imports (anywhere in the file, at the top or
    inside a function); ``from a.b import c`` reaches ``a.b.c`` when that is a module,
    else ``a.b``. The compiled core is a module of its own."""
    modules = {_module_name(path): path for path in files()}
    known = set(modules) | {"kresling._core"}

    def module_of(dotted):
        while dotted and dotted not in known:
            dotted = dotted.rpartition(".")[0]
        return dotted or None

    graph = {}
    for name, path in modules.items():
        reached = {module_of(dotted) for _, dotted, layer in imports(path) if layer}
        graph[name] = sorted(reached - {None, name})
    return graph


def import_cycles(graph: dict) -> list:
    """The cycles of ``graph``: each strongly connected set of more than one module."""
    index, low, stack, on_stack, cycles = {}, {}, [], set(), []

    def visit(module):  # Tarjan's algorithm
        index[module] = low[module] = len(index)
        stack.append(module)
        on_stack.add(module)
        for other in graph.get(module, ()):
            if other not in index:
                visit(other)
                low[module] = min(low[module], low[other])
            elif other in on_stack:
                low[module] = min(low[module], index[other])
        if low[module] == index[module]:
            component = []
            while not component or component[-1] != module:
                component.append(stack.pop())
                on_stack.discard(component[-1])
            if len(component) > 1:
                cycles.append(sorted(component))

    for module in graph:
        if module not in index:
            visit(module)
    return cycles


def test_no_two_modules_import_each_other_even_inside_a_function():
    cycles = import_cycles(import_graph())
    assert not cycles, "modules that import each other (directly or around a loop):\n" + \
        "\n".join(" <-> ".join(cycle) for cycle in cycles)


def test_the_cycle_check_finds_a_loop_of_three_and_not_a_chain():
    assert import_cycles({"a": ["b"], "b": ["c"], "c": ["a"], "d": ["a"]}) == [["a", "b", "c"]]
    assert import_cycles({"a": ["b"], "b": ["c"], "c": []}) == []


def private_imports() -> list:
    """``file:line: name`` for every private name (``_x``, not a module) one module of the
    package imports from another: what a module keeps to itself stays there."""
    found = []
    for path in files():
        tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
        for node in ast.walk(tree):
            if not isinstance(node, ast.ImportFrom):
                continue
            module = _from_module(path, node)
            if module[0] != "kresling":
                continue
            for alias in node.names:
                name = alias.name
                folder = PACKAGE.joinpath(*module[1:])
                is_module = ((folder / name).is_dir() or (folder / f"{name}.py").is_file()
                             or (module == ["kresling"] and _is_module(name)))
                if name.startswith("_") and not name.startswith("__") and not is_module:
                    found.append(f"{path.relative_to(PACKAGE.parent)}:{node.lineno}: "
                                 f"{'.'.join(module)}.{name}")
    return found


def test_no_module_imports_another_modules_private_names():
    found = private_imports()
    assert not found, "private names imported across modules:\n" + "\n".join(found)


@pytest.mark.parametrize("source, found", [
    ("from kresling.io.pattern import _as_list\n", ["kresling.io.pattern._as_list"]),
    ("from ..assembly import _private, public\n", ["kresling.assembly._private"]),
    ("from kresling import _core\nfrom kresling.cli import _output\n", []),
])
def test_the_private_check_tells_names_from_modules(monkeypatch, source, found):
    fake = PACKAGE / "analyses" / "_architecture_probe.py"
    monkeypatch.setattr(sys.modules[__name__], "files", lambda: [fake])
    original = Path.read_text
    monkeypatch.setattr(Path, "read_text", lambda self, *a, **k: source if self == fake
                        else original(self, *a, **k))
    assert [line.split(": ", 1)[1] for line in private_imports()] == found
