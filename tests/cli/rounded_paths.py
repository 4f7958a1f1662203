#!/usr/bin/env python3
"""rounded_paths.py all|start < PURSUE_JSON > PATHS_JSON

Reads the output of `preimage wallfollow pursue --json` and writes a `pursuit check --path`
file with its executed path rounded to doubles: every point (`all`, the `paths_rounded`
field), or only the start (`start`; the other points stay exact rational strings). JSON
numbers carry the doubles exactly, so the checker sees the rounded points themselves."""
import json
import sys

d = json.load(sys.stdin)
exact, rounded = d["paths"], d["paths_rounded"]
if sys.argv[1] == "all":
    paths = rounded
elif sys.argv[1] == "start":
    paths = [[r[0]] + e[1:] for e, r in zip(exact, rounded)]
else:
    sys.exit("rounded_paths.py: expected all or start")
json.dump({"paths": paths}, sys.stdout)
