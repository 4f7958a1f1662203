#!/usr/bin/env bash
# non_utf8_name.sh PREIMAGE FIXTURES OUTDIR: scene and plan files whose names hold a byte
# that is not UTF-8 (0xFF). The names go into JSON output (validate --json, and the scene
# name import writes): they must come out as valid JSON, never an internal error (exit 3,
# issue 26: "[json.exception.type_error.316] invalid UTF-8 byte").
set -u
preimage=$1 fix=$2 out=$3
mkdir -p "$out"
bad=$(printf 'scene\377name')
cp "$fix/visilibity/room_with_pillar.txt" "$out/$bad.txt"
cp "$fix/houseexpo/l_shape.json" "$out/$bad.house.json"
fail() { echo "non_utf8_name.sh: $*" >&2; exit 1; }
check_json() { python3 -c 'import json, sys; json.load(open(sys.argv[1], encoding="utf-8"))' "$1" || fail "$2: not valid UTF-8 JSON"; }

"$preimage" import "$out/$bad.txt" --from visilibity -o "$out/$bad.json" || fail "import --from visilibity: exit $?"
check_json "$out/$bad.json" "the imported VisiLibity scene"
"$preimage" import "$out/$bad.house.json" --from houseexpo -o "$out/$bad.2.json" || fail "import --from houseexpo: exit $?"
check_json "$out/$bad.2.json" "the imported HouseExpo scene"
"$preimage" validate "$out/$bad.json" --json >"$out/validate.json" || fail "validate --json: exit $?"
check_json "$out/validate.json" "validate --json"
grep -Eq '"scene": ?".*scene(\\ufffd|�)name' "$out/validate.json" || fail "validate --json does not name the file"
"$preimage" validate "$out/$bad.json" | grep -q "^ok: " || fail "validate: no ok line"
echo "non-UTF-8 file names: import and validate give valid JSON"
