#!/usr/bin/env python3
"""json_expect.py CHECK -- COMMAND...

Runs COMMAND, which must exit 0 with stdout that is one JSON document and nothing else;
CHECK is a Python expression over that document, `d`, which must hold. For CLI tests of
--json outputs (issue 25: every --json output parses and carries what the text says)."""
import json
import subprocess
import sys

check = sys.argv[1]
assert sys.argv[2] == "--", "usage: json_expect.py CHECK -- COMMAND..."
run = subprocess.run(sys.argv[3:], capture_output=True, text=True)
sys.stdout.write(run.stdout[:2000])
sys.stderr.write(run.stderr)
if run.returncode != 0:
    sys.exit(f"json_expect.py: exit code {run.returncode}, expected 0")
try:
    d = json.loads(run.stdout)
except json.JSONDecodeError as e:
    sys.exit(f"json_expect.py: stdout is not JSON: {e}")
if not eval(check, {"d": d}):
    sys.exit(f"json_expect.py: check failed: {check}")
