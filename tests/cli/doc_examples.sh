#!/usr/bin/env bash
# doc_examples.sh SOURCE_DIR PREIMAGE docs|help
#   docs: runs every command line of README.md and docs/*.md that sits in a ```sh block and
#         starts with `preimage ` or `build/preimage `;
#   help: runs every line under "Examples:" in the --help of every subcommand, and fails if
#         a subcommand has none.
# Each runs as written, in a scratch directory where examples/ is the checkout's and both
# `preimage` (on PATH) and build/preimage are the tool under test. A command fails the test
# if it exits non-zero or leaves empty a file it names after -o, --output, --svg, --cdf-svg,
# --log or a redirection. A line whose comment says "(suite: ARGS)" runs with ARGS added (a
# recipe that takes minutes as documented runs in seconds in the suite).
set -eu
src=$1 bin=$2 mode=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/build" "$work/bin"
ln -s "$bin" "$work/build/preimage"
ln -s "$bin" "$work/bin/preimage"
ln -s "$src/examples" "$work/examples"
export PATH="$work/bin:$PATH"
cd "$work"

commands() {
  if [ "$mode" = docs ]; then
    for f in "$src/README.md" "$src"/docs/*.md; do
      awk -v f="${f#"$src"/}" '/^```sh/{b=1;next} b&&/^```/{b=0} b&&/^(build\/)?preimage /{print f "\t" $0}' "$f"
    done
  else
    leaves() {  # leaves PATH...: every subcommand below "preimage PATH"
      local subs
      subs=$(preimage "$@" --help | awk '/^Subcommands:/{s=1;next} s&&/^  [a-z]/{print $1} s&&/^$/{s=0}')
      if [ -z "$subs" ]; then echo "$*"; return; fi
      for s in $subs; do leaves "$@" "$s"; done
    }
    for cmd in $(leaves | tr ' ' '+'); do
      cmd=${cmd//+/ }
      # shellcheck disable=SC2086
      lines=$(preimage $cmd --help | awk '/^Examples:/{e=1;next} e&&/^  preimage /{sub(/^  /,""); print}')
      [ -n "$lines" ] || { echo "doc_examples.sh: 'preimage $cmd --help' shows no example" >&2; exit 1; }
      while IFS= read -r l; do printf '%s\t%s\n' "preimage $cmd --help" "$l"; done <<<"$lines"
    done
  fi
}

n=0
list=$(commands)
while IFS=$'\t' read -r where line; do
  if [[ $line =~ \(suite:\ ([^\)]*)\) ]]; then line="${line%%#*} ${BASH_REMATCH[1]}"; fi
  echo "\$ $line    # $where"
  bash -c "$line" >out.txt 2>err.txt || { cat out.txt err.txt; echo "doc_examples.sh: $where: failed: $line" >&2; exit 1; }
  head -2 out.txt | cut -c1-160
  for file in $(awk '{for (i = 1; i < NF; ++i) if ($i ~ /^(-o|--output|--svg|--cdf-svg|--log|>)$/) print $(i + 1)}' <<<"$line"); do
    [ -s "$file" ] || { echo "doc_examples.sh: $where: $file not written by: $line" >&2; exit 1; }
  done
  n=$((n + 1))
done <<<"$list"
min=$([ "$mode" = docs ] && echo 20 || echo 32)
[ "$n" -ge "$min" ] || { echo "doc_examples.sh: found only $n commands ($mode), expected at least $min" >&2; exit 1; }
echo "$n $mode examples ran"
