#!/usr/bin/env bash
# readme.sh SOURCE_DIR PREIMAGE: runs every `build/preimage ...` line of README.md's
# "Using it" block as written, in a scratch directory where build/preimage and examples/
# are what the checkout has; fails on the first command that fails or writes nothing.
set -eu
src=$1 bin=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/build"
ln -s "$bin" "$work/build/preimage"
ln -s "$src/examples" "$work/examples"
cd "$work"
n=0
while IFS= read -r line; do
  echo "\$ $line"
  bash -c "$line" >out.txt 2>err.txt || { cat out.txt err.txt; echo "readme.sh: failed: $line" >&2; exit 1; }
  head -3 out.txt
  n=$((n + 1))
done < <(awk '/^## Using it/{u=1} u&&/^```sh/{b=1;next} b&&/^```/{exit} b&&/^build\/preimage /' "$src/README.md")
[ "$n" -ge 6 ] || { echo "readme.sh: found only $n commands in README.md" >&2; exit 1; }
for f in vis.svg house.json house.svg plan.svg cover.svg; do [ -s "$f" ] || { echo "readme.sh: $f not written" >&2; exit 1; }; done
echo "$n README commands ran"
