"""Sphinx configuration of the kresling documentation (``make docs``).

The site is built from the Markdown pages of this folder (MyST), the API reference generated
from each public package's ``__all__`` (autodoc, autosummary, numpydoc), the command line's
own parser (sphinx-argparse), a gallery of short scripts in ``examples/gallery/``
(sphinx-gallery) and the notebooks of ``notebooks/`` executed at build time (myst-nb; no
outputs are stored in the repository).

Two switches, for a quick build that executes nothing (what the test suite builds)::

    sphinx-build -W --keep-going -D nb_execution_mode=off -D plot_gallery=0 docs OUT
"""

from __future__ import annotations

import filecmp
import os
import re
import shutil
import sys
from pathlib import Path

from sphinx.pycode import ModuleAnalyzer
from sphinx.util.docstrings import prepare_docstring

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
sys.path.insert(0, str(DOCS))  # _api_pages.py, beside this file

import kresling  # noqa: E402  (the installed package, as the pages document it)
from _api_pages import write_api_pages  # noqa: E402

# -- project ---------------------------------------------------------------------------------
project = "kresling"
author = "kresling developers"
copyright = "kresling developers"
release = kresling.__version__
version = release

# -- extensions ------------------------------------------------------------------------------
extensions = [
    "myst_nb",                     # Markdown (MyST) pages and notebooks
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
    "sphinx.ext.mathjax",
    "sphinxarg.ext",               # the command line reference
    "sphinx_gallery.gen_gallery",
]

root_doc = "index"
smartquotes = False  # "--option" and 'quotes' stay as typed (command lines, code in prose)
templates_path = ["_templates"]
exclude_patterns = ["_build", "Thumbs.db", ".DS_Store", "**.ipynb_checkpoints",
                    "auto_examples/*.ipynb", "auto_examples/*.py", "auto_examples/*.zip",
                    "auto_examples/*.json", "auto_examples/*.md5"]
source_suffix = {".rst": "restructuredtext", ".md": "myst-nb", ".ipynb": "myst-nb"}

# -- MyST and notebooks ----------------------------------------------------------------------
myst_enable_extensions = ["dollarmath", "colon_fence", "deflist"]
myst_heading_anchors = 3
# The notebooks are executed at every build, each in a fresh temporary folder (they write
# files); an error in a cell fails the build.
nb_execution_mode = "force"
nb_execution_in_temp = True
nb_execution_timeout = 600
nb_execution_raise_on_error = True
nb_execution_show_tb = True
# Plotly figures in the notebooks: plotly's JSON output is not rendered by Sphinx, so the
# kernels (which inherit this environment) show figures as HTML that loads plotly.js from
# plotly's CDN when the page is viewed.
os.environ["PLOTLY_RENDERER"] = "sphinx_gallery"

NOTEBOOKS_SOURCE = ROOT / "notebooks"
NOTEBOOKS_PAGES = DOCS / "notebooks"   # copies made here at build time (not committed)


def _copy_notebooks():
    """Copy ``notebooks/*.ipynb`` into the source tree (a file is rewritten only when it
    changed, so incremental builds stay incremental); copies of deleted notebooks go."""
    NOTEBOOKS_PAGES.mkdir(exist_ok=True)
    sources = {path.name: path for path in sorted(NOTEBOOKS_SOURCE.glob("*.ipynb"))}
    for name, source in sources.items():
        target = NOTEBOOKS_PAGES / name
        if not target.exists() or not filecmp.cmp(source, target, shallow=False):
            shutil.copyfile(source, target)
    for stale in NOTEBOOKS_PAGES.glob("*.ipynb"):
        if stale.name not in sources:
            stale.unlink()


_copy_notebooks()

# -- generated pages -------------------------------------------------------------------------
# What the build generates in this folder is written anew each time, so that pages of names
# or scripts that no longer exist do not linger (an orphan page is a warning, so an error).
for _generated in (DOCS / "api", DOCS / "auto_examples"):
    shutil.rmtree(_generated, ignore_errors=True)
(DOCS / "sg_execution_times.rst").unlink(missing_ok=True)

# -- API reference ---------------------------------------------------------------------------
write_api_pages(DOCS / "api")
autosummary_generate = True
autosummary_imported_members = True
autodoc_default_options = {"member-order": "bysource"}
autodoc_typehints = "none"          # the numpydoc sections say the types
autodoc_preserve_defaults = True
numpydoc_show_class_members = False  # members are documented by the class template
numpydoc_class_members_toctree = False
numpydoc_attributes_as_param_list = True

# -- gallery ---------------------------------------------------------------------------------
sphinx_gallery_conf = {
    "examples_dirs": str(ROOT / "examples" / "gallery"),
    "gallery_dirs": str(DOCS / "auto_examples"),
    "filename_pattern": r"/plot_",
    "download_all_examples": False,
    "remove_config_comments": True,
    "within_subsection_order": "FileNameSortKey",
    "matplotlib_animations": False,
    "image_scrapers": ("matplotlib",),
    "reset_modules": ("matplotlib",),
    "show_memory": False,
    "abort_on_example_error": True,
    "run_stale_examples": True,     # run every script each build: the output follows the code
}

# -- HTML ------------------------------------------------------------------------------------
html_theme = "pydata_sphinx_theme"
html_title = f"kresling {release}"
html_static_path = []
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "header_links_before_dropdown": 9,
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
}
html_show_sourcelink = False

# -- links to repository files outside the site ------------------------------------------------
# The Markdown guides are also read on their own (in the repository), where a link such as
# [examples/](../examples/README.md) leads to the file. The site holds only docs/, so such a
# link is rendered as its text.
_OUTSIDE_LINK = re.compile(r"(?<!!)\[([^\]]+)\]\((?!https?:|mailto:|#)([^)\s]+)\)")


def _unlink_outside(app, docname, source):
    page = Path(app.env.doc2path(docname)).resolve()
    if page.suffix != ".md":
        return

    def replace(match):
        target = match[2].split("#")[0]
        if not target:
            return match[0]
        resolved = (page.parent / target).resolve()
        return match[0] if resolved.is_relative_to(DOCS) else match[1]

    source[0] = _OUTSIDE_LINK.sub(replace, source[0])


# -- constants re-exported by a package --------------------------------------------------------
# A constant's documentation is its "#:" comment in the module that defines it; a package
# that re-exports it (kresling.analyses.PROTOCOLS, defined in kresling.analyses.bending) has no
# such comment, so the comment is looked up in the package's modules. (Without one, autodoc
# would show the docstring of the value's type, e.g. tuple's.)
def _constant_comment(app, what, name, obj, options, lines):
    if what != "data":
        return
    type_doc = prepare_docstring(type(obj).__doc__ or "")
    if lines and [line for line in lines if line] != [line for line in type_doc if line]:
        return  # a comment of its own
    attribute = name.rpartition(".")[2]
    for module_name, module in sorted(sys.modules.items()):
        if not module_name.startswith("kresling") or module is None:
            continue
        if vars(module).get(attribute, None) is not obj:
            continue
        try:
            comments = ModuleAnalyzer.for_module(module_name).find_attr_docs()
        except Exception:  # noqa: BLE001 - a compiled module has no source to read
            continue
        if ("", attribute) in comments:
            lines[:] = list(comments[("", attribute)])
            return
    lines[:] = []


def setup(app):
    app.connect("source-read", _unlink_outside)
    app.connect("autodoc-process-docstring", _constant_comment, priority=400)


# The concepts page draws its diagram with Matplotlib at build time.
import _diagrams  # noqa: E402

_diagrams.write_all(DOCS / "_generated")
