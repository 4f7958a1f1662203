# SPDX-License-Identifier: Apache-2.0
"""The Python module against the CLI on the shipped scenes: the same library, so the same
numbers (issue 22). Run by ctest (python.pytest) with PYTHONPATH=build/python."""
import json
import os
import subprocess

import numpy as np
import pytest

import preimage

CLI = os.environ["PREIMAGE_CLI"]
EXAMPLES = os.environ["PREIMAGE_EXAMPLES"]
GALLERY = os.path.join(EXAMPLES, "gallery.json")


def cli_json(*args):
    out = subprocess.run([CLI, *args, "--json"], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def test_visibility_matches_cli():
    env = preimage.load_scene(GALLERY).environment
    v = preimage.visibility(env, (1, 1))
    c = cli_json("visibility", GALLERY, "--from", "1,1")
    assert v["vertices"].shape == (len(c["vertices"]), 2)
    assert v["area"] == pytest.approx(c["area"], rel=1e-12)
    cli_vertices = np.array([(p["x"], p["y"]) for p in c["vertices"]], dtype=float)
    free = [e["kind"] == "free" for e in c["edges"]]
    assert v["free_edges"] == free
    assert np.allclose(v["vertices"], cli_vertices, rtol=0, atol=1e-12)


def test_plan_matches_cli_and_stays_in_free_space():
    scene = preimage.load_scene(GALLERY)
    p = preimage.plan(scene.environment, (0.5, 7.5), (11.5, 0.5), radius=0.2)
    c = cli_json("plan", GALLERY, "--start", "0.5,7.5", "--goal", "11.5,0.5", "--radius", "0.2")
    assert p["found"] and c["found"]
    assert p["length"] == pytest.approx(c["length"], rel=1e-12)
    assert np.array_equal(p["path"], np.array(c["path"], dtype=float))


def test_cover_matches_cli():
    scene = preimage.load_scene(GALLERY)
    r = preimage.cover(scene.environment, radius=0.2, angle=0, start=scene.start)  # the CLI starts at the scene's start
    c = cli_json("cover", GALLERY, "--radius", "0.2", "--angle", "0")
    assert r["length"] == pytest.approx(c["length"], rel=1e-12)
    assert r["moves"] == c["moves"]
    assert r["covered_fraction"] == pytest.approx(c["metrics"]["covered_fraction"])
    assert (r["merged_cells"], r["turned_cells"]) == (c["merged_cells"], c["turned_cells"])


def test_cover_with_a_turning_radius_matches_cli():
    scene = preimage.load_scene(GALLERY)
    r = preimage.cover(scene.environment, radius=0.2, angle=0, start=scene.start, min_turn_radius=0.4)
    c = cli_json("cover", GALLERY, "--radius", "0.2", "--angle", "0", "--min-turn-radius", "0.4")
    assert r["length"] == pytest.approx(c["length"], rel=1e-12)
    assert r["moves"] == c["moves"] and "turn" in r["moves"]
    assert r["arcs"] == len(c["arcs"]) > 0
    assert (r["shortened_laps"], r["skipped"]) == (c["shortened_laps"], c["skipped"])


@pytest.mark.parametrize("method", ["trapezoidal", "boustrophedon"])
def test_decompose_matches_cli(method):
    env = preimage.load_scene(GALLERY).environment
    cells = preimage.decompose(env, method)
    c = cli_json("decompose", GALLERY, "--method", method)
    assert len(cells) == len(c["cells"])
    for mine, theirs in zip(cells, c["cells"]):
        assert np.allclose(mine, np.array(theirs["polygon"], dtype=float), rtol=0, atol=1e-12)


def test_environment_from_shapely_style_rings_and_errors():
    # Closed rings, as Shapely's exterior.coords gives them.
    square = [(0, 0), (4, 0), (4, 4), (0, 4), (0, 0)]
    hole = [(1, 1), (1, 2), (2, 2), (2, 1), (1, 1)]
    env = preimage.Environment(np.array(square, dtype=float), [np.array(hole, dtype=float)])
    assert env.num_vertices == 8 and env.num_holes == 1
    assert preimage.visibility(env, (3, 3))["area"] < 16
    with pytest.raises(preimage.InputError, match=r"holes\[0\] edge .* touches boundary"):
        preimage.Environment(np.array(square, dtype=float), [np.array([(3, 1), (5, 1), (5, 2), (3, 1)], dtype=float)])
    with pytest.raises(ValueError, match="expected an \\(n, 2\\) array"):
        preimage.Environment(np.zeros((3, 3)))


def test_import_formats_agree():
    a = preimage.import_plan(os.path.join(EXAMPLES, "formats", "l_room.wkt"), "wkt").environment
    b = preimage.import_plan(os.path.join(EXAMPLES, "formats", "l_room.geojson"), "geojson").environment
    for ra, rb in zip(a.rings, b.rings):
        assert np.array_equal(ra, rb)
    assert json.loads(a.to_geojson())["features"][0]["geometry"]["type"] == "Polygon"


def test_beams_filter_matches_cli():
    scene_path = os.path.join(EXAMPLES, "beams", "fig01_six_beams.json")
    scene = preimage.load_scene(scene_path)
    for word in ["c b a", "a b a d e", ""]:
        mine = preimage.beams_filter(scene, word)
        theirs = cli_json("beams", "filter", scene_path, "--word", word)
        assert mine["consistent"] == theirs["consistent"], word
        assert mine["regions"] == theirs["regions"], word


def test_order_type_matches_brute_force_orientation():
    rng = np.random.default_rng(7)
    pts = rng.uniform(0, 10, size=(7, 2))
    t = preimage.order_type(pts)
    chi = t["chirotope"]
    for i in range(7):
        for j in range(7):
            for k in range(7):
                if len({i, j, k}) < 3:
                    assert chi[i, j, k] == 0
                    continue
                (ax, ay), (bx, by), (cx, cy) = pts[i], pts[j], pts[k]
                det = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
                assert chi[i, j, k] == (1 if det > 0 else -1)  # random doubles: far from zero
    assert len(t["hull"]) >= 3 and all(len(a) == 6 for a in t["around"])


def test_cut_ordering_matches_cli():
    path = os.path.join(EXAMPLES, "wallfollow", "fig03_two_reflex.json")
    mine = preimage.cut_ordering(preimage.load_scene(path).environment)
    theirs = cli_json("wallfollow", "cut-ordering", path)
    assert mine["ordering"] == theirs["true"] and mine["canonical"] == theirs["canonical"]


def test_replay_line_matches_cli():
    log = os.path.join(EXAMPLES, "tracking", "corridor_scans.txt")
    lines = [line for line in open(log) if not line.startswith("#")]
    out = subprocess.run([CLI, "track", "replay", log, "--json"], check=True, capture_output=True, text=True).stdout
    cli_rows = [json.loads(row) for row in out.splitlines()]
    mine = [preimage.replay_line(line) for line in lines]
    assert len(mine) == len(cli_rows)
    for a, b in zip(mine, cli_rows):
        assert (a["vertices"], a["target_rule"], a["escape_paths"]) == (b["vertices"], b["target_rule"], b.get("escape_paths", 0))
        assert len(a["points"]) == len(b["geometry"]["points"])


def test_pursuit_plan_matches_cli_and_clears():
    path = os.path.join(EXAMPLES, "pursuit", "pillar.json")
    scene = preimage.load_scene(path)
    mine = preimage.pursuit_plan(scene.environment, max_pursuers=2, start=scene.start)
    theirs = cli_json("pursuit", "plan", path, "--pursuers", "2")
    assert mine["outcome"] == "plan" and mine["pursuers"] == theirs["pursuers"] == 2
    assert mine["cleared"] and theirs["check"]["cleared"]
    assert mine["length"] == pytest.approx(theirs["plan"]["length"], rel=1e-12)
    for a, b in zip(mine["paths"], theirs["plan"]["paths"]):
        assert np.array_equal(a, np.array(b, dtype=float))
    one = preimage.pursuit_plan(scene.environment, max_pursuers=1, start=scene.start)
    assert one["outcome"] == "no plan" and "paths" not in one  # a pillar needs two (a proof: the search is complete)


def test_pursuit_check_matches_cli_with_and_without_range():
    fixtures = os.path.join(os.path.dirname(__file__), "..", "fixtures", "pursuit")
    scene_path = os.path.join(fixtures, "range_L.json")
    env = preimage.load_scene(scene_path).environment
    for name, cleared_with_range in (("range_L_both_arms.json", True), ("range_L_walk_back.json", False)):
        path_file = os.path.join(fixtures, name)
        with open(path_file) as f:
            paths = [np.array(json.load(f), dtype=float)]
        mine = preimage.pursuit_check(env, paths, range=1.5)
        theirs = cli_json("pursuit", "check", scene_path, "--path", path_file, "--range", "1.5")
        assert mine["cleared"] == theirs["cleared"] == cleared_with_range
        assert mine["moments"] == theirs["moments"]
        assert mine["contaminated_area"] == pytest.approx(theirs["contaminated_area"], rel=1e-12)
        assert preimage.pursuit_check(env, paths)["cleared"]  # unlimited, both clear the L
    with pytest.raises(Exception, match="range"):
        preimage.pursuit_check(env, paths, range=-1)


def test_track_game_matches_cli():
    path = os.path.join(EXAMPLES, "tracking", "box.json")
    scene = preimage.load_scene(path)
    mine = preimage.track_game(scene.environment, resolution=0.5, observer=(1, 3), target=(5.2, 3))
    theirs = cli_json("track", "game", path, "--resolution", "0.5")
    assert (mine["points"], mine["states"], mine["seen"], mine["kept"]) == (theirs["points"], theirs["states"], theirs["seen"], theirs["kept"])
    assert mine["escape_steps"] is None and theirs["start"]["kept"]  # the box's start is kept
    assert np.array_equal(mine["keeping_observers"], np.array(theirs["keeping_observers"], dtype=float))
    with pytest.raises(Exception, match="resolution"):
        preimage.track_game(scene.environment, resolution=0)
    # With the observer's velocity in the state (track game --accel): the same counts as the CLI.
    dyn = preimage.track_game(scene.environment, resolution=0.5, observer=(1, 3), target=(5.2, 3), accel=0.5)
    theirs = cli_json("track", "game", path, "--resolution", "0.5", "--accel", "0.5")
    for key in ("accel_steps", "velocities", "states", "seen", "kept", "kept_at_rest"):
        assert dyn["dynamics"][key] == theirs["dynamics"][key], key
    assert dyn["escape_steps_at_rest"] is None and theirs["dynamics"]["start"]["kept"]
    assert dyn["dynamics"]["kept"] < dyn["kept"] * dyn["dynamics"]["velocities"]  # the bound on acceleration costs states
    with pytest.raises(Exception, match="multiple of 0.25 m"):
        preimage.track_game(scene.environment, resolution=0.125, accel=0.5)
    # The constant-acceleration step: the CLI's counts, its own step.
    exact = preimage.track_game(scene.environment, resolution=0.5, accel=0.5, observer_step="constant-acceleration")
    theirs = cli_json("track", "game", path, "--resolution", "0.5", "--accel", "0.5", "--observer-step", "constant-acceleration")
    for key in ("accel_steps", "velocities", "states", "seen", "kept", "kept_at_rest", "step_time"):
        assert exact["dynamics"][key] == theirs["dynamics"][key], key
    assert exact["dynamics"]["step_time"] == pytest.approx(2 ** 0.5)
    with pytest.raises(Exception, match="observer_step"):
        preimage.track_game(scene.environment, resolution=0.5, accel=0.5, observer_step="euler")
