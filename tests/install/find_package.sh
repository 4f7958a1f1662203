#!/usr/bin/env bash
# Installs preimage from BUILD into a scratch prefix, builds examples/consumer against it
# with find_package(preimage), and runs it on the gallery example.
set -euo pipefail
build=$1 source=$2 scratch=$3
rm -rf "$scratch"
cmake --install "$build" --prefix "$scratch/prefix" >/dev/null
cmake -S "$source/examples/consumer" -B "$scratch/consumer" -DCMAKE_PREFIX_PATH="$scratch/prefix" >/dev/null
cmake --build "$scratch/consumer" -j 2 >/dev/null
"$scratch/consumer/visible_area" "$source/examples/gallery.json" 1 1
# The Python module, when built, installs beside the library and imports from there.
if ls "$build"/python/preimage*.so >/dev/null 2>&1; then
  module=$(find "$scratch/prefix" -name 'preimage*.so' | head -n1)
  [ -n "$module" ] || { echo "find_package.sh: the Python module was built but not installed" >&2; exit 1; }
  PYTHONPATH=$(dirname "$module") /usr/bin/python3 -c "import preimage; print('python module:', preimage.__file__)"
fi
