#!/usr/bin/env bash
# make sanitize: the C++ core under AddressSanitizer and UndefinedBehaviorSanitizer.
#  1. the GoogleTest suite, built with both sanitizers (build/sanitize), run by ctest;
#  2. the Python extension built the same way, and a pytest subset that drives the core
#     through it (the hardening reproducers, the solver and model errors, the fuzz targets of
#     the core) under python with the ASan runtime preloaded.
# Any report of either sanitizer fails the run (halt_on_error).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
PY=${PY:-$ROOT/.venv/bin/python}
BUILD=${SANITIZE_BUILD:-$ROOT/build/sanitize}
FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g -O1"
export PATH="$(dirname "$PY"):$PATH"

cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="$FLAGS" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DKRESLING_BUILD_TESTS=ON -DKRESLING_BUILD_PYTHON=ON \
  -DPython_EXECUTABLE="$PY" \
  -Dpybind11_DIR="$("$PY" -c 'import pybind11; print(pybind11.get_cmake_dir())')" > /dev/null
cmake --build "$BUILD" --target kresling_tests _core -j "${SANITIZE_JOBS:-2}"

export ASAN_OPTIONS="detect_leaks=0:halt_on_error=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
echo "== the C++ tests under ASan + UBSan"
ctest --test-dir "$BUILD" --output-on-failure -j2

echo "== a pytest subset under ASan + UBSan"
# A package directory that is the source tree's kresling/ with the sanitized _core in it;
# python -S (no site: the editable install's finder would load the normal _core) and -P
# (the working directory's kresling/ is not on the path), the venv's packages by PYTHONPATH.
SITE="$BUILD/site"
rm -rf "$SITE" && mkdir -p "$SITE/kresling"
for entry in "$ROOT"/kresling/*; do ln -s "$entry" "$SITE/kresling/"; done
cp "$BUILD"/cpp/_core*.so "$SITE/kresling/"
PACKAGES=$("$PY" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
# The ASan runtime first; libstdc++ with it, or ASan finds no __cxa_throw to intercept (python
# itself does not link it) and aborts at the first C++ exception.
PRELOAD="$(g++ -print-file-name=libasan.so) $(g++ -print-file-name=libstdc++.so)"
LD_PRELOAD="$PRELOAD" PYTHONPATH="$SITE:$PACKAGES" \
  "$PY" -S -P -c 'import kresling._core as c, sys; assert c.__file__.startswith(sys.argv[1]), c.__file__' "$SITE"
LD_PRELOAD="$PRELOAD" PYTHONPATH="$SITE:$PACKAGES" \
  "$PY" -S -P -m pytest -q -p no:cacheprovider \
  tests/*/test_*_bad_input.py tests/solvers/test_solver_errors.py tests/model/test_model.py \
  tests/geometry/test_geometry_errors.py tests/analyses/test_analyses_snap_through.py tests/solvers/test_solver_golden.py \
  tests/solvers/test_solver_factorization.py \
  tests/fuzz/fuzz_geometry.py tests/fuzz/fuzz_model.py tests/fuzz/fuzz_solvers.py \
  tests/fuzz/fuzz_analyses.py tests/fuzz/fuzz_manipulator.py
echo "sanitize: clean"
