# SPDX-License-Identifier: Apache-2.0
"""examples/batch/batch.py on a LocalCluster: the same rows as a serial loop, one per task."""
import csv
import os
import subprocess
import sys

EXAMPLES = os.environ["PREIMAGE_EXAMPLES"]


def test_batch_on_a_local_cluster_matches_the_serial_loop(tmp_path):
    out = tmp_path / "batch.csv"
    plans = [os.path.join(EXAMPLES, "floorplans", f) for f in ("house_expo_room_0000.json", "house_expo_room_1451.json")]
    log = os.path.join(EXAMPLES, "tracking", "corridor_scans.txt")
    run = subprocess.run([sys.executable, os.path.join(EXAMPLES, "batch", "batch.py"), "--plans", *plans, "--logs", log,
                          "--angles", "0", "90", "--chunk", "5", "--workers", "2", "--serial", "--out", str(out)],
                         capture_output=True, text=True, timeout=300, env=os.environ)
    assert run.returncode == 0, run.stderr
    assert "results identical" in run.stdout
    rows = list(csv.DictReader(open(out)))
    assert [r["kind"] for r in rows] == ["cover"] * 4 + ["replay"] * 3  # 15 lines in chunks of 5
    assert sum(int(r["items"]) for r in rows if r["kind"] == "replay") == 12  # every scan of the log, once
    assert all(float(r["covered"]) > 0.99 for r in rows if r["kind"] == "cover")
