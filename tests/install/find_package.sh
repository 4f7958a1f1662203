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
