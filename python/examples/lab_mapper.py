"""A lab-style maze mapper: a Webots Python controller that explores a grid maze cell by cell,
builds the lab's 4D occupancy grid with NumPy from the lidar, prints each new cell's K x K
log-odds and the map, and hands its grid to the runner to be scored.

    python3 -m maze_mapper.run python/examples/lab_mapper.py --world worlds/lab4x4.txt \
        -- --size 4x4 [--subcells K] [--cell-size M] [--origin X,Y] [--save-scans F.npz] [--save-grid F.npz]

Its arguments are what a maze lab tells the student (Webots' controllerArgs): the maze's size
in cells, the cell size and where the maze's south-west corner is; never the walls.
The lab's rule, per side of the robot's cell, read from the median of the five beams within
2.5 degrees of the side's world direction: a return closer than the side plus a quarter cell
is a wall, and the whole band on that side gets l(0.6); the sub-cells between the centre and
the band get l(0.3); an opening frees the band's middle sub-cell and the path to it; the
centre is free. Each sub-cell gets one update a scan, occupied wins.
"""

import argparse
import math
import os
import sys

import numpy as np
from controller import Robot

import maze_mapper

P_FREE, P_OCC, PRIOR = 0.3, 0.6, 0.5
L_FREE = math.log(P_FREE / (1 - P_FREE)) - math.log(PRIOR / (1 - PRIOR))
L_OCC = math.log(P_OCC / (1 - P_OCC)) - math.log(PRIOR / (1 - PRIOR))
HALF_WINDOW = math.radians(2.5)
WALL_MARGIN = 0.25  # cells beyond the side that still count as the side's wall
# Headings: name, world yaw, step in cells (dx, dy), step in sub-cells (di from north, dj from west).
HEADINGS = {"N": (math.pi / 2, (0, 1), (-1, 0)), "E": (0.0, (1, 0), (0, 1)),
            "S": (-math.pi / 2, (0, -1), (1, 0)), "W": (math.pi, (-1, 0), (0, -1))}


def wrap(angle):
    return (angle + math.pi) % (2 * math.pi) - math.pi


def side_reading(ranges, yaw, world_angle, fov, min_range, max_range):
    """The lower and upper median range of the beams within 2.5 degrees of a world direction,
    or None when none is valid (no return counts as inf; left out when two beams return)."""
    n = len(ranges)
    step = fov / n
    centre = round((fov / 2 - wrap(world_angle - yaw)) / step) % n
    reach = int(HALF_WINDOW / step)
    window = ranges[[(centre + k) % n for k in range(-reach, reach + 1)]]
    valid = window[~np.isnan(window) & (window >= min_range)]
    valid = np.where(valid > max_range, np.inf, valid)
    if np.count_nonzero(np.isfinite(valid)) >= 2:
        valid = valid[np.isfinite(valid)]
    if valid.size == 0:
        return None
    ordered = np.sort(valid)
    return ordered[(ordered.size - 1) // 2], ordered[ordered.size // 2]


class LabMap:
    """The 4D grid, grid[y, x, i, j] (y from the south, i from the north), and the visits."""

    def __init__(self, width, height, k, cell_size, origin):
        self.k, self.cell_size, self.origin = k, cell_size, origin
        self.grid = np.zeros((height, width, k, k))
        self.visited = {}

    def cell_of(self, x, y):
        return (int((x - self.origin[0]) // self.cell_size), int((y - self.origin[1]) // self.cell_size))

    def sides(self, cell, position, yaw, ranges, lidar):
        """{heading: True (wall) | False (opening)} for the sides the scan decides."""
        cx, cy = cell
        half = self.cell_size / 2
        centre = (self.origin[0] + (cx + 0.5) * self.cell_size, self.origin[1] + (cy + 0.5) * self.cell_size)
        to_side = {"N": centre[1] + half - position[1], "S": position[1] - (centre[1] - half),
                   "E": centre[0] + half - position[0], "W": position[0] - (centre[0] - half)}
        found = {}
        for h, (angle, _, _) in HEADINGS.items():
            medians = side_reading(ranges, yaw, angle, lidar.getFov(), lidar.getMinRange(), lidar.getMaxRange())
            if medians is None:
                continue
            limit = to_side[h] + WALL_MARGIN * self.cell_size
            walls = [math.isfinite(r) and r < limit for r in medians]
            if walls[0] == walls[1]:
                found[h] = walls[0]
        return found

    def update(self, cell, sides):
        """One scan's update of the cell: gather the free and occupied sub-cells, then one
        update each, occupied winning."""
        k, m = self.k, self.k // 2
        free, occupied = {(m, m)}, set()
        for h, wall in sides.items():
            di, dj = HEADINGS[h][2]
            free |= {(m + di * n, m + dj * n) for n in range(1, m)}
            middle = (m + di * m, m + dj * m)
            if not wall:
                free.add(middle)
            elif di != 0:
                occupied |= {(middle[0], j) for j in range(k)}
            else:
                occupied |= {(i, middle[1]) for i in range(k)}
        x, y = cell
        for i, j in free - occupied:
            self.grid[y, x, i, j] += L_FREE
        for i, j in occupied:
            self.grid[y, x, i, j] += L_OCC


class Explorer:
    """Drives the robot cell by cell (depth first) with the motors, the GPS and the IMU."""

    def __init__(self, robot, lab):
        self.robot, self.lab = robot, lab
        self.ts = int(robot.getBasicTimeStep())
        self.left, self.right = robot.getDevice("left motor"), robot.getDevice("right motor")
        for motor in (self.left, self.right):
            motor.setPosition(math.inf)
            motor.setVelocity(0.0)
        self.lidar = robot.getDevice("lidar")
        self.gps = robot.getDevice("gps")
        self.imu = robot.getDevice("imu")
        for sensor in (self.lidar, self.gps, self.imu):
            sensor.enable(self.ts)
        self.max_speed = self.left.getMaxVelocity()
        self.scans = []
        self.running = True

    def step(self):
        if self.robot.step(self.ts) == -1:
            self.running = False
        return self.running

    def yaw(self):
        return self.imu.getRollPitchYaw()[2]

    def position(self):
        x, y, _ = self.gps.getValues()
        return x, y

    def wheels(self, left, right):
        self.left.setVelocity(max(-self.max_speed, min(self.max_speed, left)))
        self.right.setVelocity(max(-self.max_speed, min(self.max_speed, right)))

    def rest(self, steps):
        self.wheels(0.0, 0.0)
        for _ in range(steps):
            if not self.step():
                return

    def turn_to(self, heading):
        target = HEADINGS[heading][0]
        while self.running:
            error = wrap(target - self.yaw())
            if abs(error) < 0.002:
                break
            w = max(-6.0, min(6.0, 10.0 * error))
            self.wheels(-w, w)
            self.step()
        self.rest(1)

    def drive_to(self, cell):
        cs, (ox, oy) = self.lab.cell_size, self.lab.origin
        goal = (ox + (cell[0] + 0.5) * cs, oy + (cell[1] + 0.5) * cs)
        while self.running:
            x, y = self.position()
            yaw = self.yaw()
            ahead = (goal[0] - x) * math.cos(yaw) + (goal[1] - y) * math.sin(yaw)
            if ahead < 0.002:
                break
            steer = 4.0 * wrap(math.atan2(goal[1] - y, goal[0] - x) - yaw) if ahead > 0.05 else 0.0
            v = max(0.5, min(12.0, 40.0 * ahead))
            self.wheels(v - steer, v + steer)
            self.step()
        self.rest(1)

    def scan(self, cell):
        """A full lidar image from where the robot rests: a rotating head needs a turn."""
        frequency = self.lidar.getFrequency()
        self.rest(math.ceil(1000.0 / (frequency * self.ts)) + 1 if frequency > 0 else 1)
        ranges = np.asarray(self.lidar.getRangeImage(), dtype=np.float32)
        position, yaw = self.position(), self.yaw()
        self.scans.append((cell, position, yaw, ranges.copy()))
        return self.lab.sides(cell, position, yaw, ranges, self.lidar)


def explore(robot, lab):
    """Depth first: the first open, unvisited neighbour in the order N, E, S, W, else back."""
    ex = Explorer(robot, lab)
    ex.step()
    height, width = lab.grid.shape[:2]
    open_sides = {}

    def arrive(cell, heading):
        lab.visited[cell] = heading  # the map's arrow: the robot's last heading there
        if cell in open_sides:
            return
        sides = ex.scan(cell)
        lab.update(cell, sides)
        open_sides[cell] = [h for h, wall in sides.items() if not wall]
        print(f"cell ({cell[0]},{cell[1]}) log-odds, north row first:")
        print(maze_mapper.format_cell_matrix(lab.grid, *cell), end="")

    def neighbour(cell, h):
        dx, dy = HEADINGS[h][1]
        return cell[0] + dx, cell[1] + dy

    stack = [lab.cell_of(*ex.position())]
    arrive(stack[0], min(HEADINGS, key=lambda h: abs(wrap(HEADINGS[h][0] - ex.yaw()))))
    while stack and ex.running:
        cell = stack[-1]
        ahead = [h for h in "NESW" if h in open_sides[cell]
                 and 0 <= neighbour(cell, h)[0] < width and 0 <= neighbour(cell, h)[1] < height
                 and neighbour(cell, h) not in lab.visited]
        if ahead:
            heading = ahead[0]
            stack.append(neighbour(cell, heading))
        else:
            stack.pop()
            if not stack:
                break
            heading = next(h for h in "NESW" if neighbour(cell, h) == stack[-1])
        ex.turn_to(heading)
        ex.drive_to(stack[-1])
        if ex.running:
            arrive(stack[-1], heading)
    ex.wheels(0.0, 0.0)
    return ex.scans


def main():
    p = argparse.ArgumentParser(description="the lab's 4D grid mapper")
    p.add_argument("--size", default="4x4", help="the maze's size in cells, WxH")
    p.add_argument("--subcells", type=int, default=3, help="K, odd")
    p.add_argument("--cell-size", type=float, default=1.0, help="m")
    p.add_argument("--origin", default="0,0", help="the maze's south-west corner, m")
    # Paths typed on the runner's command line, taken from where it was typed (the controller
    # runs in its own folder), and checked before the run rather than after it.
    p.add_argument("--save-scans", type=maze_mapper.user_path,
                   help="write every scan (cell, position, yaw, ranges) to this .npz")
    p.add_argument("--save-grid", type=maze_mapper.user_path, help="write the grid and the visits to this .npz")
    args = p.parse_args()
    for flag, path in (("--save-grid", args.save_grid), ("--save-scans", args.save_scans)):
        if path and not os.path.isdir(os.path.dirname(path) or "."):
            p.error(f"{flag} {path}: no folder {os.path.dirname(path)} to write it in")
    width, height = (int(v) for v in args.size.split("x"))
    origin = tuple(float(v) for v in args.origin.split(","))

    robot = Robot()
    lab = LabMap(width, height, args.subcells, args.cell_size, origin)
    maze_mapper.keep_grid(lab.grid, lab.visited)
    scans = explore(robot, lab)
    print()
    print(maze_mapper.render(lab.grid, lab.visited), end="")

    visited = np.array([[x, y] for x, y in lab.visited], dtype=int).reshape(-1, 2)
    headings = np.array(list(lab.visited.values()), dtype="U1")
    if args.save_grid:
        np.savez(args.save_grid, grid=lab.grid, visited=visited, headings=headings)
    if args.save_scans:
        lidar = robot.getDevice("lidar")
        np.savez(args.save_scans,
                 cells=np.array([s[0] for s in scans], dtype=int).reshape(-1, 2),
                 positions=np.array([s[1] for s in scans]).reshape(-1, 2),
                 yaws=np.array([s[2] for s in scans]),
                 ranges=np.array([s[3] for s in scans], dtype=np.float32),
                 fov=lidar.getFov(), min_range=lidar.getMinRange(), max_range=lidar.getMaxRange(),
                 visited=visited, headings=headings, size=(width, height), subcells=args.subcells,
                 cell_size=args.cell_size, origin=origin)
    return 0


if __name__ == "__main__":
    sys.exit(main())
