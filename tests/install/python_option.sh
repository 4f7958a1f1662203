#!/usr/bin/env bash
# The Python module follows pybind11 at every configure (PREIMAGE_PYTHON=AUTO): a tree first
# configured without pybind11 (as `make demo` does on a fresh machine) builds the module once
# pybind11 is there (as after `make test` installs it). Caught: the option() cached OFF.
# Usage: python_option.sh SOURCE SCRATCH
set -euo pipefail
source=$1 scratch=$2
rm -rf "$scratch"
configure() { cmake -S "$source" -B "$scratch" -DPREIMAGE_BUILD_TESTS=OFF -DPREIMAGE_PCH=OFF "$@" 2>&1 | grep 'preimage: Python module'; }
has_target() { cmake --build "$scratch" --target help | grep 'preimage_python' >/dev/null; }
fail() { echo "python_option.sh: $*" >&2; exit 1; }

# 1. pybind11 hidden: AUTO resolves to OFF, no module target.
configure -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=ON | grep -q 'Python module OFF (PREIMAGE_PYTHON=AUTO' || fail "without pybind11: not OFF"
has_target && fail "without pybind11: a preimage_python target"
# 2. The same tree, pybind11 now found: the module is built.
configure -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=OFF | grep -q 'Python module ON (PREIMAGE_PYTHON=AUTO' || fail "with pybind11: not ON"
has_target || fail "with pybind11: no preimage_python target"
# 3. The user's OFF is kept although pybind11 is found.
configure -DPREIMAGE_PYTHON=OFF | grep -q 'Python module OFF (PREIMAGE_PYTHON=OFF' || fail "-DPREIMAGE_PYTHON=OFF not kept"
has_target && fail "-DPREIMAGE_PYTHON=OFF: a preimage_python target"
# 4. An older tree's cached option() default (OFF) becomes AUTO.
# (the entry's help comment, which CMake may wrap over several lines, replaced by the option's).
awk '/^\/\// { help = help $0 "\n"; next }
     /^PREIMAGE_PYTHON:/ { printf "//Build the Python module (needs pybind11)\nPREIMAGE_PYTHON:BOOL=OFF\n"; help = ""; next }
     { printf "%s", help; help = ""; print }' "$scratch/CMakeCache.txt" > "$scratch/CMakeCache.old" &&
  mv "$scratch/CMakeCache.old" "$scratch/CMakeCache.txt"
configure | grep -q 'Python module ON (PREIMAGE_PYTHON=AUTO' || fail "an older tree's cached OFF was not made AUTO"
echo "python option follows pybind11: ok"
