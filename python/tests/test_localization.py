"""The localization lab's demos checked number by number: every probability `demo localize`
and `demo trilaterate` print is recomputed here with NumPy from the formulas alone (the
walls read from the world file), and maze_mapper.localization gives the same numbers."""

import math
import re

import numpy as np
import pytest

from conftest import program, world
from maze_mapper import localization

SIDES = "NESW"
STEP = [(-1, 0), (0, 1), (1, 0), (0, -1)]


def walls_of(path):
    """The walls of a text map, (rows, columns, 4), row 0 the north; read here, on its own."""
    lines = [line for line in open(path).read().splitlines() if line.strip()]
    rows, cols = (len(lines) - 1) // 2, (len(lines[0]) - 1) // 4
    lines = [line.ljust(4 * cols + 1) for line in lines]
    walls = np.zeros((rows, cols, 4), dtype=bool)
    for r in range(rows):
        for c in range(cols):
            walls[r, c] = [lines[2 * r][4 * c + 2] == "-", lines[2 * r + 1][4 * c + 4] == "|",
                           lines[2 * r + 2][4 * c + 2] == "-", lines[2 * r + 1][4 * c] == "|"]
    return walls


def correct(belief, walls, z, sensor):
    p_ww, p_ow, p_wo, p_oo = sensor
    post = belief.copy()
    for r, c in np.ndindex(belief.shape):
        for s in range(4):
            post[r, c] *= (p_ww if z[s] else p_ow) if walls[r, c, s] else (p_wo if z[s] else p_oo)
    return post / post.sum()


def predict(belief, walls, s, p):
    out = np.zeros_like(belief)
    for r, c in np.ndindex(belief.shape):
        if walls[r, c, s]:
            out[r, c] += belief[r, c]
        else:
            out[r, c] += (1 - p) * belief[r, c]
            out[r + STEP[s][0], c + STEP[s][1]] += p * belief[r, c]
    return out


def grid_after(lines, at, rows):
    return np.array([[float(v) for v in lines[at + 1 + k].split()] for k in range(rows)])


def parse_run(text, rows):
    """Each step: (move side or None, after-prediction grid, reading, after-correction grid,
    true cell after the step or None)."""
    lines = text.splitlines()
    steps, cur = [], None
    for i, line in enumerate(lines):
        if re.fullmatch(r"step \d+", line):
            cur = {"move": None, "pred": None, "true": None}
            steps.append(cur)
        elif line.startswith("move: "):
            cur["move"] = SIDES.index(line[6])
            m = re.search(r"to cell (\d+)\)|stays in cell (\d+)\)", line)
            cur["true"] = int(m.group(1) or m.group(2))
        elif line == "after prediction:":
            cur["pred"] = grid_after(lines, i, rows)
        elif line.startswith("reading: "):
            cur["z"] = [part.endswith(" wall") and not part.endswith("no wall") for part in line[9:].split(", ")]
        elif line == "after correction:":
            cur["post"] = grid_after(lines, i, rows)
            cur["best"] = tuple(map(float, re.match(r"most likely: cell (\d+) \((.*)\)", lines[i + 1 + rows]).groups()))
    return [step for step in steps if "z" in step]  # a last step of "no move left" has no reading


def recompute(text, walls, sensor=(0.8, 0.2, 0.4, 0.6), p_move=0.8):
    rows, cols, _ = walls.shape
    belief = np.full((rows, cols), 1.0 / (rows * cols))
    steps = parse_run(text, rows)
    assert steps
    for step in steps:
        if step["move"] is not None:
            before = belief
            belief = predict(belief, walls, step["move"], p_move)
            assert np.abs(step["pred"] - belief).max() <= 0.0005 + 1e-12
            assert np.allclose(localization.predict(before, walls, step["move"], p_move), belief, atol=1e-12)
        before = belief
        belief = correct(belief, walls, step["z"], sensor)
        assert np.abs(step["post"] - belief).max() <= 0.0005 + 1e-12
        assert np.allclose(localization.correct(before, walls, step["z"], sensor), belief, atol=1e-12)
        assert step["best"][0] == 1 + int(np.argmax(belief))
    return steps


def test_every_printed_belief_of_the_default_run_recomputes_from_the_formulas():
    walls = walls_of(world("loc5x5.txt"))
    _, out, _ = program("demo", "localize")
    steps = recompute(out, walls)
    assert len(steps) >= 2
    assert "localized after" in out


def test_every_printed_belief_with_given_moves_and_models_recomputes_and_the_module_predicts_the_same():
    walls = walls_of(world("loc5x5.txt"))
    _, out, _ = program("demo", "localize", "--start", "13", "--moves", "N,N,E,S,W,W",
                        "--motion", "0.7", "--sensor", "0.9,0.1,0.3,0.7", "--localized", "0.99")
    steps = recompute(out, walls, (0.9, 0.1, 0.3, 0.7), 0.7)
    belief = np.full((5, 5), 1 / 25)
    belief = localization.correct(belief, walls, steps[0]["z"], (0.9, 0.1, 0.3, 0.7))
    for step in steps[1:]:
        belief = localization.predict(belief, walls, SIDES[step["move"]], 0.7)
        assert np.abs(step["pred"] - belief).max() <= 0.0005 + 1e-12
        belief = localization.correct(belief, walls, step["z"], (0.9, 0.1, 0.3, 0.7))


def test_noisy_readings_with_a_seed_recompute_too():
    walls = walls_of(world("loc5x5.txt"))
    _, out, _ = program("demo", "localize", "--seed", "3", "--max-steps", "8")
    recompute(out, walls)


def ending(out):
    last = out.rstrip("\n").split("\n\n")[-1]
    m = re.match(r"localized after (\d+) moves: cell (\d+) holds ([\d.]+); the robot is in cell (\d+)", last)
    return m, last


def check_never_wrong(out, walls, start):
    steps = recompute(out, walls)
    where = start
    for step in steps:
        where = step["true"] or where
        if step["best"][1] >= 0.8:
            assert step["best"][0] == where


def test_every_start_of_loc5x5_localizes_within_4_moves_in_the_true_cell():
    walls = walls_of(world("loc5x5.txt"))
    for start in range(1, 26):
        _, out, _ = program("demo", "localize", "--start", str(start))
        m, last = ending(out)
        assert m, last
        assert int(m.group(1)) <= 4
        assert m.group(2) == m.group(4)
        check_never_wrong(out, walls, start)


@pytest.mark.parametrize("size,seed", [("5x5", 1), ("5x5", 2), ("5x5", 3), ("6x6", 4), ("6x6", 5), ("4x4", 6)])
def test_generated_mazes_localize_within_12_moves_or_name_the_alike_starts_never_a_wrong_cell(tmp_path, size, seed):
    _, text, _ = program("generate", size, "--seed", str(seed))
    path = tmp_path / "m.txt"
    path.write_text(text)
    walls = walls_of(path)
    cells = walls.shape[0] * walls.shape[1]
    for start in range(1, cells + 1):
        _, out, _ = program("demo", "localize", str(path), "--start", str(start))
        m, last = ending(out)
        if m:
            assert int(m.group(1)) <= 12
            assert m.group(2) == m.group(4)
        else:
            assert "do not tell these starts apart" in last, last
        check_never_wrong(out, walls, start)


def test_the_particle_filter_with_one_seed_prints_the_same_run_twice():
    _, once, _ = program("demo", "localize", "--particles", "--seed", "7")
    _, twice, _ = program("demo", "localize", "--particles", "--seed", "7")
    assert once == twice
    assert "particle filter (250 particles, seed 7)" in once
    _, other, _ = program("demo", "localize", "--particles", "--seed", "8")
    assert other != once


def test_trilateration_from_exact_distances_gives_the_pose_to_1e9():
    marks = localization.LANDMARKS
    for x, y in [(0.0, 0.0), (-2.2, 2.1), (1.37, -0.42), (2.4, -2.4)]:
        for names in [("yellow", "red", "green"), ("red", "blue", "green"), ("yellow", "green", "blue")]:
            pts = [marks[n] for n in names]
            d = [math.hypot(x - px, y - py) for px, py in pts]
            ex, ey, _ = localization.trilaterate(pts, d)
            assert abs(ex - x) < 1e-9 and abs(ey - y) < 1e-9


def numbers_after(label, text):
    return float(re.search(re.escape(label) + r" (-?[\d.]+)", text).group(1))


def test_demo_trilaterate_prints_the_closed_form_and_the_scores_the_formulas_give():
    x, y = 0.7, -1.3
    _, out, _ = program("demo", "trilaterate", "--pose", f"{x},{y}")
    pts = [localization.LANDMARKS[n] for n in ("yellow", "red", "green")]
    d = [math.hypot(x - px, y - py) for px, py in pts]
    ex, ey, (a, b, c, dd, e, f) = localization.trilaterate(pts, d)
    for label, value in [("A = 2 (x2 - x1) =", a), ("B = 2 (y2 - y1) =", b), ("D = 2 (x3 - x2) =", dd),
                         ("E = 2 (y3 - y2) =", e), ("y2^2 =", c), ("y3^2 =", f)]:
        assert abs(numbers_after(label, out) - value) <= 0.00005 + 1e-12, label
    xs = re.search(r"x = \(C E - F B\) / \(E A - B D\) = (-?[\d.]+) / (-?[\d.]+) = (-?[\d.]+) m", out).groups()
    assert abs(float(xs[2]) - x) < 1e-6
    assert abs(float(xs[0]) - (c * e - f * b)) <= 0.00005 and abs(float(xs[1]) - (e * a - b * dd)) <= 0.00005
    ys = re.search(r"y = \(C D - A F\) / \(B D - A E\) = (-?[\d.]+) / (-?[\d.]+) = (-?[\d.]+) m", out).groups()
    assert abs(float(ys[2]) - y) < 1e-6
    assert f"cell {5 * 3 + 3 + 1}" in out  # row 3 (y in [-1.5, -0.5]), column 3 (x in [0.5, 1.5])
    # The scores: N(distance; centre's distance, 1) over the four landmarks, normalised.
    lines = out.splitlines()
    at = next(i for i, line in enumerate(lines) if "normalised; north row first" in line)
    printed = np.array([[float(v) for v in lines[at + 1 + k].split()] for k in range(5)])
    scores = np.ones((5, 5))
    for r in range(5):
        for col in range(5):
            cx, cy = -2 + col, 2 - r
            for px, py in localization.LANDMARKS.values():
                mu = math.hypot(cx - px, cy - py)
                scores[r, col] *= math.exp(-0.5 * (math.hypot(x - px, y - py) - mu) ** 2) / math.sqrt(2 * math.pi)
    scores /= scores.sum()
    assert np.abs(printed - scores).max() <= 0.0005 + 1e-12
    full = {n: math.hypot(x - px, y - py) for n, (px, py) in localization.LANDMARKS.items()}
    assert np.allclose(localization.cell_scores(full), scores, atol=1e-12)
    best = int(np.argmax(scores)) + 1
    assert f"most likely: cell {best} ({scores.max():.3f})" in out


def parse_live_run(text, rows):
    """`run --localize`'s updates: (move side or None, reading, printed belief, most likely
    (cell, share)), and the summary's verdict."""
    lines = text.splitlines()
    updates = []
    for i, line in enumerate(lines):
        m = re.match(r"localize: (?:the start|move \d+ ([NESW])), the lidar reads (.*)", line)
        if not m:
            continue
        at = i + 2 * rows + 1  # the shaded map: 2 rows + 1 lines
        belief = np.array([[float(v) for v in lines[at + 1 + k].split()] for k in range(rows)])
        best = re.match(r"most likely: cell (\d+) \((.*)\)", lines[at + 1 + rows]).groups()
        z = [not part.endswith("no wall") for part in m.group(2).split(", ")]
        updates.append((SIDES.index(m.group(1)) if m.group(1) else None, z, belief, (int(best[0]), float(best[1]))))
    verdict = next(line for line in lines if line.startswith("localization: "))
    return updates, verdict


def check_live_run(path, x, y):
    """Runs `run PATH --localize --start X,Y` and recomputes every printed belief; returns the
    verdict line and the moves the first localization took (None when never)."""
    walls = walls_of(path)
    rows, cols, _ = walls.shape
    _, out, _ = program("run", str(path), "--localize", "--start", f"{x},{y}", "--noise", "0")
    updates, verdict = parse_live_run(out, rows)
    r, c = rows - 1 - y, x  # the run's cells count from the south-west, the lab's from the north-west
    belief = np.full((rows, cols), 1.0 / (rows * cols))
    first = None
    for move, (side, z, printed, best) in enumerate(updates):
        if side is not None:
            belief = predict(belief, walls, side, 0.8)
            r, c = r + STEP[side][0], c + STEP[side][1]
        assert z == list(walls[r, c]), (r, c)  # the lidar reads the walls exactly
        belief = correct(belief, walls, z, (0.8, 0.2, 0.4, 0.6))
        assert np.abs(printed - belief).max() <= 0.0005 + 1e-12
        assert best[0] == 1 + int(np.argmax(belief))
        if best[1] >= 0.8:
            assert best[0] == 1 + r * cols + c  # never a wrong cell at 0.8 with exact readings
            first = move if first is None else first
    assert verdict.endswith(f"the robot is in cell {1 + r * cols + c}"), verdict
    return verdict, first


def test_a_robot_run_with_localize_from_every_start_of_loc5x5_prints_beliefs_the_formulas_give():
    for x in range(5):
        for y in range(5):
            verdict, first = check_live_run(world("loc5x5.txt"), x, y)
            assert first is not None and first <= 8, verdict
            assert re.match(r"localization: cell \d+ holds [\d.]+ after \d+ moves, first localized at move "
                            + str(first), verdict), verdict


@pytest.mark.parametrize("size,seed", [("5x5", 1), ("6x6", 4), ("8x8", 9)])
def test_a_robot_run_with_localize_on_generated_mazes_is_never_sure_of_a_wrong_cell(tmp_path, size, seed):
    _, text, _ = program("generate", size, "--seed", str(seed))
    path = tmp_path / "m.txt"
    path.write_text(text)
    for x, y in [(0, 0), (1, 2), (3, 3)]:
        check_live_run(path, x, y)


def test_localize_refuses_a_lidar_that_does_not_see_all_four_sides(tmp_path):
    import json
    _, text, _ = program("robot", "hambot")
    robot = json.loads(text)
    robot["lidars"][0]["fov_rad"] = math.pi
    robot["lidars"][0]["horizontal_resolution"] = 180
    path = tmp_path / "half.json"
    path.write_text(json.dumps(robot))
    status, out, err = program("run", world("loc5x5.txt"), "--localize", "--robot", str(path), check=False)
    assert status == 2, out
    assert err.startswith("error: --localize reads the four sides with the lidar, and its field of view (180 degrees) "
                          "leaves out the"), err


def test_localize_options_without_localize_are_warned_about_and_bad_ones_refused():
    _, _, err = program("run", world("loc5x5.txt"), "--quiet", "--motion", "0.9")
    assert "warning: --motion has no effect without --localize" in err
    status, _, err = program("run", world("loc5x5.txt"), "--localize", "--sensor", "0.8,0.3,0.4,0.6", check=False)
    assert status == 2 and err.startswith("error: --sensor")
    status, _, err = program("run", world("loc5x5.txt"), "--localize", "--model", "bump", check=False)
    assert status == 2 and "--localize reads the walls with a lidar" in err
