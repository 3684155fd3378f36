# Two commands on a fresh Debian machine (run as root): `make demo` and `make test`.
# Both install what is missing: Debian packages with apt-get, Python packages with pip into
# .venv/ at the repository root. Later runs only rebuild what changed.

SHELL := /bin/bash
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
BUILD_DIR := build/py
# libcairo2: cairosvg (the fabrication extra) renders the cut files' PNG previews with it.
APT_PACKAGES := g++ make libeigen3-dev libsuitesparse-dev libgtest-dev libcairo2
# What the compiled extension depends on: any change reinstalls it (incrementally).
CORE_SOURCES := CMakeLists.txt pyproject.toml $(shell find cmake cpp -type f 2>/dev/null)

.PHONY: demo test test-cpp test-python install system-deps clean help

help:
	@echo "make demo   - reproduce the thesis's optimal design (and, as they land, its tables)"
	@echo "make test   - C++ unit tests (ctest) and the Python test suite (pytest)"
	@echo "make clean  - remove build/ and .venv/"

demo: install
	$(VENV)/bin/kresling design --n 10 --lam 0.9 --Lc 15 --R 30

test: install test-cpp test-python

test-cpp: install
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j2

test-python: install
	$(PY) -m pytest -q

install: $(VENV)/.installed

system-deps:
	@if ! command -v dpkg >/dev/null 2>&1; then \
	  echo "note: not a Debian system; make sure Eigen 3, SuiteSparse and GoogleTest are installed"; \
	else \
	  missing=""; \
	  for p in $(APT_PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	  if [ -n "$$missing" ]; then \
	    if [ "$$(id -u)" = 0 ]; then \
	      echo "Installing Debian packages:$$missing"; \
	      apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing >/dev/null; \
	    else \
	      echo "Missing Debian packages:$$missing" >&2; \
	      echo "Install them as root:  apt-get install$$missing" >&2; exit 1; \
	    fi; \
	  fi; \
	fi

$(VENV)/.venv-ready:
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip
	$(PY) -m pip install -q "scikit-build-core>=0.10" "pybind11>=2.12" cmake ninja
	touch $@

# Editable install with a persistent build directory: C++ rebuilds are incremental, and the
# same CMake build also compiles the GoogleTest suite for ctest.
$(VENV)/.installed: $(VENV)/.venv-ready $(CORE_SOURCES) | system-deps
	$(PY) -m pip install -q --no-build-isolation \
	  -Cbuild-dir=$(BUILD_DIR) -Ccmake.define.KRESLING_BUILD_TESTS=ON \
	  -e ".[test]"
	touch $@

clean:
	rm -rf build $(VENV)
