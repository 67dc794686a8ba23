#!/usr/bin/env python3
"""A floodfill micromouse algorithm for the mms protocol (standard library only).

It talks to the simulator on standard input and output, one command a line, exactly as it
would to mms (github.com/mackorone/mms), so it runs unchanged in mms and in

    maze_mapper mms worlds/classic16x16.txt --cell-size 0.18 -- python3 examples/mms/floodfill.py

It starts in cell (0,0) facing north, as mms's mice do, and searches for the centre: in each
cell it asks for the walls around it, marks them (setWall), floods the distances to the
centre through the walls it knows (unknown sides count as open), shows them (setText), and
moves to a neighbour one step closer. It exits once it stands in the centre. Log lines go
to standard error, which maze_mapper passes through, as mms shows them in its log.
"""

import collections
import sys

# ---- the mms protocol -------------------------------------------------------------------


class MouseCrashedError(Exception):
    pass


def command(text, answered=True):
    sys.stdout.write(text + "\n")
    sys.stdout.flush()
    if not answered:
        return None
    answer = sys.stdin.readline()
    if not answer:
        sys.exit("the simulator closed the conversation")
    return answer.strip()


def maze_width():
    return int(command("mazeWidth"))


def maze_height():
    return int(command("mazeHeight"))


def wall_front():
    return command("wallFront") == "true"


def wall_right():
    return command("wallRight") == "true"


def wall_left():
    return command("wallLeft") == "true"


def move_forward():
    if command("moveForward") == "crash":
        raise MouseCrashedError()


def turn_right():
    command("turnRight")


def turn_left():
    command("turnLeft")


def set_wall(x, y, side):
    command("setWall {} {} {}".format(x, y, side), answered=False)


def set_color(x, y, color):
    command("setColor {} {} {}".format(x, y, color), answered=False)


def set_text(x, y, text):
    command("setText {} {} {}".format(x, y, text), answered=False)


def log(text):
    sys.stderr.write(text + "\n")
    sys.stderr.flush()


# ---- the algorithm ----------------------------------------------------------------------

SIDES = "nesw"
STEP = {"n": (0, 1), "e": (1, 0), "s": (0, -1), "w": (-1, 0)}


def turned(heading, quarter_turns):
    return SIDES[(SIDES.index(heading) + quarter_turns) % 4]


class Mouse:
    def __init__(self):
        self.width = maze_width()
        self.height = maze_height()
        self.x, self.y, self.heading = 0, 0, "n"
        self.walls = set()  # (x, y, side), both sides of each wall
        self.shown = {}  # the distance each cell's text shows
        xs = range((self.width - 1) // 2, self.width // 2 + 1)
        ys = range((self.height - 1) // 2, self.height // 2 + 1)
        self.goals = {(x, y) for x in xs for y in ys}

    def add_wall(self, x, y, side):
        dx, dy = STEP[side]
        self.walls.add((x, y, side))
        self.walls.add((x + dx, y + dy, turned(side, 2)))
        set_wall(x, y, side)

    def open(self, x, y, side):
        dx, dy = STEP[side]
        inside = 0 <= x + dx < self.width and 0 <= y + dy < self.height
        return inside and (x, y, side) not in self.walls

    def sense(self):
        for ask, quarter_turns in ((wall_front, 0), (wall_right, 1), (wall_left, -1)):
            if ask():
                self.add_wall(self.x, self.y, turned(self.heading, quarter_turns))

    def flood(self):
        distance = {goal: 0 for goal in self.goals}
        queue = collections.deque(self.goals)
        while queue:
            x, y = queue.popleft()
            for side in SIDES:
                if not self.open(x, y, side):
                    continue
                dx, dy = STEP[side]
                cell = (x + dx, y + dy)
                if cell not in distance:
                    distance[cell] = distance[(x, y)] + 1
                    queue.append(cell)
        return distance

    def face(self, side):
        quarter_turns = (SIDES.index(side) - SIDES.index(self.heading)) % 4
        if quarter_turns == 3:
            turn_left()
        else:
            for _ in range(quarter_turns):
                turn_right()
        self.heading = side

    def step(self):
        self.sense()
        distance = self.flood()
        for cell, d in distance.items():
            if self.shown.get(cell) != d:
                set_text(cell[0], cell[1], str(d))
                self.shown[cell] = d
        here = distance.get((self.x, self.y))
        if here is None:
            raise RuntimeError("no way to the centre from ({},{})".format(self.x, self.y))
        # The open neighbour closest to the centre, straight ahead first.
        best = None
        for quarter_turns in (0, 1, -1, 2):
            side = turned(self.heading, quarter_turns)
            if not self.open(self.x, self.y, side):
                continue
            dx, dy = STEP[side]
            d = distance.get((self.x + dx, self.y + dy))
            if d is not None and (best is None or d < best[0]):
                best = (d, side)
        self.face(best[1])
        move_forward()
        dx, dy = STEP[self.heading]
        self.x += dx
        self.y += dy
        set_color(self.x, self.y, "G")

    def run(self):
        log("floodfill: {}x{} maze, searching for the centre".format(self.width, self.height))
        moves = 0
        while (self.x, self.y) not in self.goals:
            self.step()
            moves += 1
        log("floodfill: reached the centre ({},{}) in {} moves".format(self.x, self.y, moves))


if __name__ == "__main__":
    Mouse().run()
