# Two commands on a fresh Debian machine (run as root): `make demo` and `make test`
# (`make docs` builds the documentation site).
# Both install what is missing: Debian packages with apt-get, Python packages with pip into
# .venv/ at the repository root. Later runs only rebuild what changed.

SHELL := /bin/bash
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
BUILD_DIR := build/py
# libcairo2: cairosvg (the fabrication extra) renders the cut files' PNG previews with it.
APT_PACKAGES := g++ make libeigen3-dev libsuitesparse-dev liblapack-dev libgtest-dev libcairo2
# The CPUs this process may use: ctest's and pytest's workers.
JOBS := $(shell nproc 2>/dev/null || echo 2)
# pytest on every core (pytest-xdist), a file's tests on one worker (a module-scoped fixture
# is built once), the files in the order tests/conftest.py gives (the long ones first).
# `make test PYTEST_WORKERS=0` runs pytest in one process.
PYTEST_WORKERS ?= $(JOBS)
PYTEST_PARALLEL := -n $(PYTEST_WORKERS) --dist loadfile --no-loadscope-reorder
# Only for `make test`: the report is checked in a real browser (headless Chromium; about
# 20 s and 500 MB to install).
APT_TEST_PACKAGES := chromium
REPORT_DIR := report
DOCS_BUILD := docs/_build/html
# What the compiled extension depends on: any change reinstalls it (incrementally).
CORE_SOURCES := CMakeLists.txt pyproject.toml $(shell find cmake cpp -type f 2>/dev/null)

.PHONY: demo test test-fast test-cpp test-python install dev-deps system-deps test-deps benchmark docs fuzz \
        sanitize \
        clean help

help:
	@echo "make demo   - the optimal design's geometry, then reproduce the thesis: $(REPORT_DIR)/report.html"
	@echo "make test   - C++ unit tests (ctest) and the Python test suite (pytest, on every core)"
	@echo "make test-fast - the same without the slow (over 10 s each), browser and fuzz tests: for everyday work"
	@echo "make benchmark - solver speed and memory against MERLIN2, Miura sheets to 100,000 DOFs (prints tables)"
	@echo "make docs   - the documentation site: $(DOCS_BUILD)/index.html"
	@echo "make fuzz   - the fuzz suite at $(FUZZ_SCALE)x its test-suite examples, from random seeds"
	@echo "make sanitize - the C++ tests and a pytest subset under ASan and UBSan"
	@echo "make clean  - remove build/ and .venv/"

demo: install
	$(VENV)/bin/kresling design --n 10 --lam 0.9 --Lc 15 --R 30
	@echo
	$(VENV)/bin/kresling reproduce --quick --out $(REPORT_DIR)
	@echo
	@echo "Open $(REPORT_DIR)/report.html in a browser (report.json holds every check)."

test: dev-deps test-cpp test-python

# make test-fast: everything but the tests marked @pytest.mark.slow (those over 10 s; a test
# not marked that takes longer fails, see tests/slow_check.py), the tests that drive a
# browser and the fuzz suite (both marked by tests/conftest.py; make test runs them all).
test-fast: dev-deps test-cpp
	$(PY) -m pytest -q $(PYTEST_PARALLEL) -m "not slow and not browser and not fuzz"

# The C++ tests and benchmark programs are not built by the install (make demo does not run
# them): each target that runs them builds them first, incrementally.
test-cpp: install
	$(VENV)/bin/cmake --build $(BUILD_DIR) --target kresling_tests
	$(VENV)/bin/ctest --test-dir $(BUILD_DIR) --output-on-failure -j$(JOBS)

test-python: dev-deps test-deps
	$(PY) -m pytest -q $(PYTEST_PARALLEL)

# An editable install leaves the package's bytecode to be written on first import, which a
# shell with PYTHONDONTWRITEBYTECODE set never does: every command would compile each module
# it imports, every time (measured: about 17 ms for `kresling design`, 0.1 s for `kresling
# simulate`). Compiled here instead; a module edited later is recompiled by the next
# `make install`.
install: $(VENV)/.installed
	@$(PY) -m compileall -q kresling >/dev/null

# $(call apt_install,PACKAGES,WHAT-IF-MISSING-WITHOUT-ROOT): install the missing Debian
# packages as root; otherwise name them and run the second argument (exit 1 or carry on).
# A package counts as present only if installed (`dpkg -s` also knows removed packages).
define apt_install
	@if ! command -v dpkg >/dev/null 2>&1; then \
	  echo "note: not a Debian system; make sure these (or their equivalents) are installed: $(1)"; \
	else \
	  missing=""; \
	  for p in $(1); do \
	    dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" \
	      || missing="$$missing $$p"; \
	  done; \
	  if [ -n "$$missing" ]; then \
	    if [ "$$(id -u)" = 0 ]; then \
	      echo "Installing Debian packages:$$missing"; \
	      apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing >/dev/null; \
	    else \
	      echo "Missing Debian packages:$$missing" >&2; \
	      echo "Install them as root:  apt-get install$$missing" >&2; $(2); \
	    fi; \
	  fi; \
	fi
endef

system-deps:
	$(call apt_install,$(APT_PACKAGES),exit 1)

# Without root and without chromium the browser test is skipped (and says so).
test-deps:
	$(call apt_install,$(APT_TEST_PACKAGES),echo "the browser test of the report will be skipped" >&2)

$(VENV)/.venv-ready:
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip
	$(PY) -m pip install -q "scikit-build-core>=0.10" "pybind11>=2.12" cmake ninja
	touch $@

# Editable install with a persistent build directory: C++ rebuilds are incremental, and the
# same CMake build holds the GoogleTest suite and the benchmark programs for the targets that
# build them (test-cpp, benchmark). The demo needs the package and its fabrication extra
# (the report writes DXF cut files); the test and docs extras, which the demo does not use,
# are installed by the targets that do (dev-deps).
$(VENV)/.installed: $(VENV)/.venv-ready $(CORE_SOURCES) | system-deps
	$(PY) -m pip install -q --no-build-isolation \
	  -Cbuild-dir=$(BUILD_DIR) -Ccmake.define.KRESLING_BUILD_TESTS=ON \
	  -Ccmake.define.KRESLING_BUILD_BENCHMARKS=ON \
	  -e ".[fabrication]"
	touch $@

# The test and docs extras, read from pyproject.toml (installed without building the package
# again).
$(VENV)/.dev-deps: $(VENV)/.installed pyproject.toml
	$(PY) -c 'import tomllib; o = tomllib.load(open("pyproject.toml", "rb"))["project"]["optional-dependencies"]; print("\n".join(o["test"] + o["docs"]))' > $(VENV)/dev-requirements.txt
	$(PY) -m pip install -q -r $(VENV)/dev-requirements.txt
	touch $@

dev-deps: install $(VENV)/.dev-deps

# The fuzz suite (tests/fuzz/, run by tests/fuzz/test_fuzz.py) runs in `make test` with a few
# derandomized examples per target; here with FUZZ_SCALE times as many, from random seeds
# (a failure prints the failing example and a @reproduce_failure line that replays it).
FUZZ_SCALE ?= 50
# (KRESLING_SLOW_LIMIT=0: no check of the tests' time, which is FUZZ_SCALE times the usual.)
fuzz: dev-deps
	KRESLING_FUZZ_SCALE=$(FUZZ_SCALE) KRESLING_SLOW_LIMIT=0 $(PY) -m pytest -q tests/fuzz/test_fuzz.py

# The core under AddressSanitizer and UndefinedBehaviorSanitizer (build/sanitize): the
# GoogleTest suite, and a pytest subset through the extension built the same way.
# (KRESLING_SLOW_LIMIT=0: the sanitizers make the tests several times slower.)
sanitize: dev-deps
	KRESLING_SLOW_LIMIT=0 PY=$(abspath $(PY)) tests/sanitize.sh

benchmark: dev-deps
	$(VENV)/bin/cmake --build $(BUILD_DIR) --target solver_breakdown factorisation_cost contact_broad_phase
	$(PY) benchmarks/solver_speed.py
	$(PY) benchmarks/speed.py

# The documentation site, warnings as errors. Every page is rebuilt and the notebooks and
# the gallery's scripts run each time (under a minute), so no page shows stale output.
docs: dev-deps
	$(PY) -m sphinx -E -W --keep-going -q -b html docs $(DOCS_BUILD)
	@echo "Open $(DOCS_BUILD)/index.html in a browser."

clean:
	rm -rf build $(VENV)
