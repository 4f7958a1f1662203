#!/usr/bin/env bash
# browser_check.sh PAGE.html
# Loads PAGE in headless Chromium with "#selftest" (the report's script then zooms and
# resets every figure and moves every step slider) and fails unless the script ran to its
# end without an error and its self-test passed. Chromium comes from scripts/install-deps.
set -u
page=$(realpath "$1")
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "browser_check.sh: chromium is not installed (scripts/install-deps --test installs it)" >&2; exit 1; }
dom=$(timeout 120 "$browser" --headless --no-sandbox --disable-gpu --no-first-run --virtual-time-budget=10000 \
      --dump-dom "file://$page#selftest" 2>/dev/null)
body=$(printf '%s' "$dom" | grep -o '<body[^>]*>' | head -n1)
echo "$body"
case "$body" in *data-script-errors=*) echo "browser_check.sh: script error in $1" >&2; exit 1 ;; esac
case "$body" in *'data-ready="yes"'*) ;; *) echo "browser_check.sh: the script did not run to its end in $1" >&2; exit 1 ;; esac
case "$body" in *'data-selftest="ok'*) ;; *) echo "browser_check.sh: self-test failed in $1" >&2; exit 1 ;; esac
