#!/usr/bin/env python3
"""pattern_completeness.py PREIMAGE WORKDIR PLAN...

Every coverage pattern covers at least 99.5 % of the configuration space component it runs
in, checked independently of the library: shapely (GEOS) erodes the plan by r (arcs of 64
segments a quarter), buffers the path by w/2 and compares exact polygon areas. On the given
floor plans at W = 0.3 and 0.5 (r = W/2; the offices at 0.5 only, the wave front's slowest
case), on 6 random rooms with 2-5 holes, and with the variable-slice patterns' centre
outside the free space (in a hole, outside the boundary).

A robot that cannot turn in place (--min-turn-radius) is held to the same floor on the house
plans and the random rooms, and every arc it drives — the exact circle about the arc's
centre, 32 points per chord — must keep r from the walls (numpy distances to every wall
segment) and start inside the plan."""
import json
import math
import os
import random
import subprocess
import sys

import numpy
from shapely.geometry import LineString, Point, Polygon, box
from shapely.affinity import rotate

cli, work, plans = sys.argv[1], sys.argv[2], sys.argv[3:]
os.makedirs(work, exist_ok=True)
# HouseExpo files (no "environment") are imported first.
for k, plan in enumerate(plans):
    if "environment" not in json.load(open(plan)):
        scene = os.path.join(work, os.path.basename(plan))
        subprocess.run([cli, "import", plan, "--from", "houseexpo", "-o", scene], check=True, capture_output=True)
        plans[k] = scene
PATTERNS = ["boustrophedon", "spiral", "concentric", "spike", "squarel", "brushfire", "wavefront"]
FLOOR = 0.995


def cspace(scene, r):
    e = scene["environment"]
    return Polygon(e["boundary"], e.get("obstacles", [])).buffer(-r, resolution=64)


def components(geom):
    return list(geom.geoms) if geom.geom_type == "MultiPolygon" else [geom]


def start_in(scene, w):
    # Inside the largest component, a little away from its boundary.
    return max(components(cspace(scene, w / 2 + 0.01)), key=lambda g: g.area).representative_point()


def covered(path, scene, w, pattern, extra=()):
    scene_obj = json.load(open(path))
    r = w / 2
    args = [cli, "cover", path, "--width", str(w), "--radius", str(r), "--pattern", pattern, "--json", *extra]
    if pattern == "wavefront":
        s = start_in(scene_obj, w)
        args += ["--start", "%.9g,%.9g" % (s.x, s.y)]
    p = subprocess.run(args, capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        return None, p.stderr.strip()
    d = json.loads(p.stdout)
    pts = d["path"]
    comp = min(components(cspace(scene_obj, r)), key=lambda g: g.distance(Point(pts[0])))
    tool = LineString(pts).buffer(w / 2, resolution=16) if len(pts) > 1 else Point(pts[0]).buffer(w / 2)
    if d.get("arcs"):
        # Distances to every wall segment (numpy, brute force): the circle points keep r, and
        # each arc starts inside the plan (so, never nearer than r to a wall, stays inside).
        e = scene_obj["environment"]
        plan = Polygon(e["boundary"], e.get("obstacles", []))
        rings = [e["boundary"]] + e.get("obstacles", [])
        A = numpy.array([p for ring in rings for p in ring], dtype=float)
        B = numpy.array([p for ring in rings for p in ring[1:] + ring[:1]], dtype=float)
        V = B - A
        L2 = numpy.maximum((V * V).sum(axis=1), 1e-300)
        for a in d["arcs"]:
            cx, cy = a["center"]
            if not plan.contains(Point(pts[a["first"]])):
                return None, "arc about (%.9g, %.9g) starts outside the plan" % (cx, cy)
            ts = []
            for k in range(a["first"], a["last"]):
                t0 = math.atan2(pts[k][1] - cy, pts[k][0] - cx)
                dt = math.remainder(math.atan2(pts[k + 1][1] - cy, pts[k + 1][0] - cx) - t0, 2 * math.pi)
                ts.extend(t0 + dt * j / 32 for j in range(33))
            ts = numpy.array(ts)
            Q = numpy.stack([cx + a["radius"] * numpy.cos(ts), cy + a["radius"] * numpy.sin(ts)], axis=1)
            W = Q[:, None, :] - A[None, :, :]
            t = numpy.clip((W * V[None, :, :]).sum(axis=2) / L2[None, :], 0, 1)
            D = numpy.sqrt(((W - t[:, :, None] * V[None, :, :]) ** 2).sum(axis=2)).min(axis=1)
            if D.min() < r - 1e-9:
                q = Q[D.argmin()]
                return None, "arc about (%.9g, %.9g) passes %.9g from a wall at (%.9g, %.9g)" % (cx, cy, D.min(), q[0], q[1])
    return comp.intersection(tool).area / comp.area, d.get("touch_ups", 0)


def random_room(seed):
    rng = random.Random(seed)
    W, H = rng.uniform(12, 20), rng.uniform(8, 12)
    room = box(0, 0, W, H)
    holes = []
    for _ in range(200):
        if len(holes) >= rng.randint(2, 5):
            break
        cx, cy = rng.uniform(1.5, W - 1.5), rng.uniform(1.5, H - 1.5)
        h = rotate(box(cx - rng.uniform(0.3, 1.5), cy - rng.uniform(0.3, 1.2), cx + rng.uniform(0.3, 1.5), cy + rng.uniform(0.3, 1.2)),
                   rng.choice([0, 0, 15, 30, 45, 60]), origin="centroid")
        if h.buffer(1.2).within(room) and all(h.distance(o) > 1.2 for o in holes):
            holes.append(h)
    ring = lambda g: [[round(x, 4), round(y, 4)] for x, y in list(g.exterior.coords)[:-1]]
    return {"name": "random room %d" % seed, "environment": {"boundary": ring(room), "obstacles": [ring(h) for h in holes]}}


cases = []
for plan in plans:
    widths = (0.5,) if "mlstruct" in plan or "office" in plan else (0.3, 0.5)
    for w in widths:
        for pattern in PATTERNS:
            cases.append((plan, w, pattern, ()))
for seed in range(6):
    f = os.path.join(work, "random_room_%d.json" % seed)
    json.dump(random_room(seed), open(f, "w"))
    for pattern in PATTERNS:
        cases.append((f, 0.4, pattern, ()))
    hole = json.load(open(f))["environment"]["obstacles"][0]
    inside_hole = Polygon(hole).representative_point()
    for pattern in ["spiral", "concentric", "spike", "squarel"]:
        for c in [(inside_hole.x, inside_hole.y), (-3.0, -2.0)]:
            cases.append((f, 0.4, pattern, ("--center", "%.9g,%.9g" % c)))

# Curvature-limited robots: turning radius W and 2W on the house plans, 0.6 in the rooms.
for plan in plans:
    if "mlstruct" not in plan and "office" not in plan:
        for w in (0.3, 0.5):
            for R in (w, 2 * w):
                cases.append((plan, w, "boustrophedon", ("--min-turn-radius", str(R))))
for seed in range(6):
    cases.append((os.path.join(work, "random_room_%d.json" % seed), 0.4, "boustrophedon", ("--min-turn-radius", "0.6")))

failures = 0
worst = 1.0
for plan, w, pattern, extra in cases:
    frac, info = covered(plan, None, w, pattern, extra)
    name = "%s W=%g %s %s" % (os.path.basename(plan), w, pattern, " ".join(extra))
    if frac is None:
        failures += 1
        print("FAIL %s: %s" % (name, info))
    elif frac < FLOOR:
        failures += 1
        print("FAIL %s: %.3f%% covered" % (name, 100 * frac))
    else:
        worst = min(worst, frac)
        print("ok   %s: %.3f%% covered (%d touch-ups)" % (name, 100 * frac, info))
print("%d cases, %d failures, worst %.3f%%" % (len(cases), failures, 100 * worst))
sys.exit(1 if failures else 0)
