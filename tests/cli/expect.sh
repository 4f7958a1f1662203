#!/usr/bin/env bash
# expect.sh EXIT REGEX [FILE] -- COMMAND...
#   EXIT  0 (must succeed) or fail (must exit non-zero with exactly one line on stderr)
#   REGEX extended regex the combined output must match
#   FILE  optional file the command must have written (non-empty); "-" for none
set -u
want=$1 regex=$2 file=$3
shift 3
[ "$1" = "--" ] && shift
out=$(mktemp) err=$(mktemp)
"$@" >"$out" 2>"$err"
rc=$?
cat "$out" "$err"
fail() { echo "expect.sh: $*" >&2; rm -f "$out" "$err"; exit 1; }
if [ "$want" = 0 ]; then
  [ $rc -eq 0 ] || fail "exit code $rc, expected 0"
else
  [ $rc -ne 0 ] || fail "exit code 0, expected failure"
  [ $rc -lt 128 ] || fail "crashed (exit code $rc)"
  [ "$(wc -l <"$err")" -eq 1 ] || fail "stderr is not exactly one line"
fi
cat "$out" "$err" | grep -Eq -- "$regex" || fail "output does not match: $regex"
if [ "$file" != "-" ]; then [ -s "$file" ] || fail "file not written: $file"; fi
rm -f "$out" "$err"
