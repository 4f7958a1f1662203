#!/usr/bin/env python3
"""translation_invariance.py PREIMAGE SCENE WORKDIR

Runs every geometric command (decompose with each method, gvd, plan, cover with each
pattern, online and with a turning radius, visibility, visibility-graph) on a real floor
plan at the origin and shifted by 5e5, 4e6, 2e7 (UTM, Web Mercator) and 1e10, and checks that every answer is the
origin's, moved: the same counts, cells and structure, areas and lengths equal, and every
coordinate equal to the origin's plus the shift, within what the shifted coordinates
resolve. A shift to 1e12 must be refused with a clear error (the supported range ends
there), and a shift to just inside it must still agree.

The plan is snapped to a 2^-10 grid in its own coordinates, so that every shift is exact and
the shifted plans are the same plan. Its bounding box is not at (0, 0): the reference run is
then in a translated frame too, which is how merged bends were caught depending on the frame
(office 302 as is and shifted by 4e6 got 1,834 and 1,748 path points)."""
import json
import math
from fractions import Fraction
import os
import subprocess
import sys

cli, scene_path, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
scene = json.load(open(scene_path))
env = scene["environment"]
rings = [env["boundary"]] + env.get("obstacles", [])
q = 1024.0
x0 = min(p[0] for r in rings for p in r)
y0 = min(p[1] for r in rings for p in r)
snap = lambda p: [math.floor(p[0] * q + 0.5) / q, math.floor(p[1] * q + 0.5) / q]
X0, Y0 = snap([x0, y0])
base = {"environment": {"boundary": [snap(p) for p in env["boundary"]],
                        "obstacles": [[snap(p) for p in r] for r in env.get("obstacles", [])]}}
ext = max(max(p[0] - X0 for p in base["environment"]["boundary"]), max(p[1] - Y0 for p in base["environment"]["boundary"]))
far = max(max(abs(p[0]), abs(p[1])) for p in base["environment"]["boundary"])

# Points inside the plan (relative to its box), chosen once at the origin.
START, GOAL, FROM = (2.0, 1.0), (44.0, 9.0), (20.0, 6.0)


def shifted(off):
    s = lambda p: [p[0] + off, p[1] + off]
    return {"environment": {"boundary": [s(p) for p in base["environment"]["boundary"]],
                            "obstacles": [[s(p) for p in r] for r in base["environment"]["obstacles"]]}}


def pt(p, off):
    return "%.17g,%.17g" % (p[0] + X0 + off, p[1] + Y0 + off)


COMMANDS = {
    "decompose trapezoidal": lambda o: ["decompose"],
    "decompose boustrophedon 30": lambda o: ["decompose", "--method", "boustrophedon", "--angle", "30"],
    "decompose circular": lambda o: ["decompose", "--method", "circular"],
    "decompose spike": lambda o: ["decompose", "--method", "spike"],
    "decompose squarel": lambda o: ["decompose", "--method", "squarel"],
    "decompose brushfire": lambda o: ["decompose", "--method", "brushfire"],
    "decompose wavefront": lambda o: ["decompose", "--method", "wavefront", "--start", pt(START, o)],
    "gvd": lambda o: ["gvd"],
    "plan shortest": lambda o: ["plan", "--start", pt(START, o), "--goal", pt(GOAL, o), "--radius", "0.25"],
    "plan trapezoidal": lambda o: ["plan", "--method", "trapezoidal", "--start", pt(START, o), "--goal", pt(GOAL, o)],
    "visibility": lambda o: ["visibility", "--from", pt(FROM, o)],
    "visibility-graph": lambda o: ["visibility-graph"],
}
for pattern in ["boustrophedon", "spiral", "concentric", "spike", "squarel", "brushfire", "wavefront"]:
    COMMANDS["cover " + pattern] = (lambda pat: lambda o: ["cover", "--radius", "0.25", "--pattern", pat, "--start", pt(START, o)])(pattern)
COMMANDS["cover boustrophedon 30"] = lambda o: ["cover", "--radius", "0.25", "--angle", "30", "--start", pt(START, o)]
COMMANDS["cover min-turn-radius"] = lambda o: ["cover", "--radius", "0.25", "--angle", "0", "--min-turn-radius", "0.3", "--start", pt(START, o)]
COMMANDS["cover online"] = lambda o: ["cover", "--radius", "0.25", "--online", "--start", pt(START, o)]

IGNORED = {"scene"}


def ulp(x):
    x = abs(x)
    return math.ulp(x) if x > 0 else 0.0


def compare(a, b, off, path, errs, tol):
    """tol = (relative tolerance of measures, absolute tolerance of coordinates)."""
    if isinstance(a, dict):
        if not isinstance(b, dict) or set(a) != set(b):
            errs.append("%s: keys differ" % path)
            return
        for k in a:
            if k not in IGNORED:
                compare(a[k], b[k], off, path + "." + k, errs, tol)
    elif isinstance(a, list):
        if not isinstance(b, list) or len(a) != len(b):
            errs.append("%s: %s items at the origin, %s shifted" % (path, len(a), len(b) if isinstance(b, list) else "not a list"))
            return
        for i, (x, y) in enumerate(zip(a, b)):
            compare(x, y, off, "%s[%d]" % (path, i), errs, tol)
    elif isinstance(a, str) and isinstance(b, str) and "/" in a and a != b:
        # An exact rational coordinate: the origin's plus the shift, exactly.
        try:
            if Fraction(b) - Fraction(a) != Fraction(off) and Fraction(b) != Fraction(a):
                errs.append("%s: %s at the origin, %s shifted" % (path, a, b))
        except ValueError:
            errs.append("%s: %r at the origin, %r shifted" % (path, a, b))
    elif isinstance(a, bool) or isinstance(a, str) or a is None:
        if a != b:
            errs.append("%s: %r at the origin, %r shifted" % (path, a, b))
    elif isinstance(a, (int, float)):
        if not isinstance(b, (int, float)):
            errs.append("%s: not a number shifted" % path)
            return
        # A measure unchanged (raster metrics to a few samples), or a coordinate moved by the shift.
        rel, coord = tol
        if ".metrics." in path and abs(b - a) <= 2e-3:
            return
        if abs(b - a) <= rel * max(1.0, abs(a)) or abs(b - off - a) <= coord:
            return
        errs.append("%s: %.17g at the origin, %.17g shifted by %g" % (path, a, b, off))


def run(args, scene_file):
    p = subprocess.run([cli] + args[:1] + [scene_file] + args[1:] + ["--json"], capture_output=True, text=True, timeout=300)
    return p.returncode, p.stdout, p.stderr


failures = 0
origin_file = os.path.join(work, "origin.json")
json.dump(shifted(0), open(origin_file, "w"))
origin = {}
for name, make in COMMANDS.items():
    rc, out, err = run(make(0), origin_file)
    if rc != 0:
        print("FAIL %s at the origin: %s" % (name, err.strip()))
        failures += 1
        continue
    origin[name] = json.loads(out)

for off in [5e5, 4e6, 2e7, 1e10, 1e12 - 2 * far - 64]:
    f = os.path.join(work, "shift_%g.json" % off)
    json.dump(shifted(off), open(f, "w"))
    # Constructed coordinates are rounded to the shifted plan's doubles, and path points that
    # rounding took within r of a wall are pushed up to 8 margins out (geometry::LocalFrame:
    # a margin is 4 ulps of the coordinates plus 2^-36 of the extent).
    margin = 4 * ulp(off) + ext * 2.0 ** -36
    tol = (1e-6 + 1024 * ulp(off) / ext, 16 * margin + 4 * ulp(off))
    for name, make in COMMANDS.items():
        if name not in origin:
            continue
        rc, out, err = run(make(off), f)
        if rc != 0:
            print("FAIL %s shifted by %g: exit %d: %s" % (name, off, rc, err.strip()))
            failures += 1
            continue
        errs = []
        compare(origin[name], json.loads(out), off, name, errs, tol)
        if errs:
            failures += 1
            print("FAIL %s shifted by %g: %d differences, first: %s" % (name, off, len(errs), "; ".join(errs[:3])))
        else:
            print("ok   %s shifted by %g" % (name, off))

# Beyond the supported range: refused, naming the coordinate.
f = os.path.join(work, "shift_1e12.json")
json.dump(shifted(1e12), open(f, "w"))
for name in ["cover boustrophedon", "decompose trapezoidal", "gvd"]:
    rc, out, err = run(COMMANDS[name](1e12), f)
    if rc == 0 or "outside the supported range" not in err:
        print("FAIL %s shifted by 1e12: expected a clear refusal, got exit %d: %s" % (name, rc, err.strip()))
        failures += 1
    else:
        print("ok   %s shifted by 1e12 refused: %s" % (name, err.strip()))

print("%d failures" % failures)
sys.exit(1 if failures else 0)
