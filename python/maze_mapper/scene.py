"""The scene tree a Webots supervisor sees, over the embedded simulator: the root's children,
the robot's node with its pose fields, and the nodes a supervisor imports as the course's
environment writes them (`Obstacle` and `Landmark`, with DEF names). maze_mapper.run makes one
Scene a run (`scene.current`); controller.Supervisor and the camera read it.

An imported node becomes a solid of the simulated world at once, seen by the lidar and the
camera and met by the body (and Node.remove takes it out again: supervision.py):

    Obstacle { translation X Y Z rotation 0 0 1 A size SX SY SZ }
        a box SX across (its local x) and SY along (its local y) turned A about the vertical,
        centred on (X, Y), its top at Z + SZ / 2 (the simulator's solids stand on the floor up
        to their top: a beam or a line of sight above it passes over)
    Landmark { translation X Y Z color R G B recognitionColors [R G B] size H RADIUS _ }
        an upright cylinder RADIUS round (X, Y), H tall centred at height Z, its top at Z + H / 2
        (the course's Landmark PROTO reads size.x as the height and size.y as the radius),
        recognised by the camera when recognitionColors is not empty

Any other node type, a field these types lack, a rotation about another axis than the
vertical, or a solid no world holds (a size, or a translation's x or y, beyond the 1000 m of
the longest world side) raises SceneError naming it. With the runner's --world the world is that file: the
nodes a controller imports are kept in the tree (getFromDef finds them) but add no solid, and
the runner says so once.
"""

import math
import re
import sys
import types

from . import _native


class SceneError(ValueError):
    """A node or field the embedded simulator cannot model; the message names it."""


# The field types of the nodes a supervisor may import, and their defaults (the course's
# PROTO files: WorldObjects/Obstacle.proto, WorldObjects/Landmark.proto).
_NODE_FIELDS = {
    "Obstacle": {
        "translation": ("SFVec3f", [0.0, 0.0, 0.05]),
        "rotation": ("SFRotation", [0.0, 0.0, 1.0, 0.0]),
        "size": ("SFVec3f", [0.012, 0.18, 0.1]),
        "name": ("SFString", "Obstacle"),
        "contactMaterial": ("SFString", "default"),
        "enableBoundingObject": ("SFBool", True),
        "castShadows": ("SFBool", True),
    },
    "Landmark": {
        "translation": ("SFVec3f", [0.0, 0.0, 0.75]),
        "rotation": ("SFRotation", [0.0, 0.0, 1.0, 0.0]),
        "size": ("SFVec3f", [1.5, 0.25, 0.249]),
        "name": ("SFString", "Landmark"),
        "color": ("SFColor", [1.0, 0.0, 0.0]),
        "enableBoundingObject": ("SFBool", True),
        "castShadows": ("SFBool", True),
        "recognitionColors": ("MFColor", []),
    },
}
_WIDTHS = {"SFVec3f": 3, "SFColor": 3, "SFRotation": 4}

_TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|[\[\]{}]|[^\s\[\]{},]+')


def _tokens(text):
    return _TOKEN.findall(text.replace(",", " "))


def _number(token, what):
    try:
        value = float(token)
    except ValueError:
        raise SceneError(f"{what}: expected a number, got {token!r}") from None
    if not math.isfinite(value):
        raise SceneError(f"{what}: {token} is not a finite number")
    return value


def _read_value(tokens, at, kind, what):
    """Reads one value of a field type from tokens[at:]; returns (value, next index)."""
    if kind in _WIDTHS:
        n = _WIDTHS[kind]
        if at + n > len(tokens):
            raise SceneError(f"{what}: expected {n} numbers")
        return [_number(t, what) for t in tokens[at:at + n]], at + n
    if kind == "SFString":
        token = tokens[at] if at < len(tokens) else ""
        if not (len(token) >= 2 and token[0] == token[-1] == '"'):
            raise SceneError(f"{what}: expected a quoted string, got {token!r}")
        return token[1:-1], at + 1
    if kind == "SFBool":
        token = tokens[at] if at < len(tokens) else ""
        if token not in ("TRUE", "FALSE"):
            raise SceneError(f"{what}: expected TRUE or FALSE, got {token!r}")
        return token == "TRUE", at + 1
    # MFColor: [r g b, r g b ...] or a single colour
    if at < len(tokens) and tokens[at] == "[":
        end = tokens.index("]", at) if "]" in tokens[at:] else -1
        if end < 0:
            raise SceneError(f"{what}: a '[' without its ']'")
        numbers = [_number(t, what) for t in tokens[at + 1:end]]
        if len(numbers) % 3:
            raise SceneError(f"{what}: colours come in threes (got {len(numbers)} numbers)")
        return [numbers[i:i + 3] for i in range(0, len(numbers), 3)], end + 1
    colour, at = _read_value(tokens, at, "SFColor", what)
    return [colour], at


def parse_node(text):
    """(def_name or '', type name, {field: value}) of one node in VRML syntax; SceneError for
    a node type other than Obstacle and Landmark or a field it lacks."""
    tokens = _tokens(text)
    at = 0
    def_name = ""
    if tokens[:1] == ["DEF"]:
        if len(tokens) < 2:
            raise SceneError("DEF without a name")
        def_name, at = tokens[1], 2
    if at >= len(tokens):
        raise SceneError("no node in the string")
    type_name = tokens[at]
    if type_name not in _NODE_FIELDS:
        known = " and ".join(_NODE_FIELDS)
        raise SceneError(f"node type {type_name} is not modelled by the embedded simulator (it builds {known} nodes)")
    schema = _NODE_FIELDS[type_name]
    if tokens[at + 1:at + 2] != ["{"]:
        raise SceneError(f"{type_name}: expected '{{' after the type name")
    at += 2
    fields = {name: (list(default) if isinstance(default, list) else default)
              for name, (_, default) in schema.items()}
    while at < len(tokens) and tokens[at] != "}":
        name = tokens[at]
        if name not in schema:
            raise SceneError(f"{type_name} has no field {name} here (its fields: {', '.join(schema)})")
        fields[name], at = _read_value(tokens, at + 1, schema[name][0], f"{type_name}.{name}")
    if at >= len(tokens):
        raise SceneError(f"{type_name}: '{{' without its '}}'")
    if at + 1 != len(tokens):
        raise SceneError(f"text after the {type_name} node: {' '.join(tokens[at + 1:])}")
    return def_name, type_name, fields


def check_extent(type_name, fields):
    """SceneError for a solid no world holds (its picture would never end)."""
    for name, value in [("size", v) for v in fields["size"]] + [("translation", v) for v in fields["translation"][:2]]:
        if abs(value) > _native.MAX_ARENA_SIDE_M:
            raise SceneError(f"{type_name}.{name}: {value:g} m is beyond any world (at most "
                             f"{_native.MAX_ARENA_SIDE_M:g} m a side)")


def yaw_of_rotation(rotation, what):
    """The angle about the vertical of an axis-angle rotation [x, y, z, angle]; SceneError for
    a rotation that tips the node over (the simulator is flat)."""
    x, y, z, angle = rotation
    norm = math.sqrt(x * x + y * y + z * z)
    if angle == 0.0 or norm == 0.0:
        return 0.0
    if abs(x) > 1e-9 * norm or abs(y) > 1e-9 * norm:
        raise SceneError(f"{what}: a rotation about the axis ({x:g}, {y:g}, {z:g}) is not modelled: "
                         "only turns about the vertical (0 0 1)")
    return angle if z > 0 else -angle


class Field:
    """A field of a node (Webots' Field): its value read and, for the robot's translation and
    rotation, set (a teleport)."""

    def __init__(self, node, name, kind):
        self._node = node
        self._name = name
        self._kind = kind

    def getName(self):
        return self._name

    def getTypeName(self):
        return self._kind

    def getCount(self):
        return len(self._node._values[self._name]) if self._kind.startswith("MF") else -1

    def _get(self, kind):
        if self._kind != kind:
            raise SceneError(f"the field {self._name} is an {self._kind}, not an {kind}")
        return self._node._value(self._name)

    def getSFVec3f(self):
        return list(self._get("SFVec3f"))

    def getSFRotation(self):
        return list(self._get("SFRotation"))

    def getSFColor(self):
        return list(self._get("SFColor"))

    def getSFString(self):
        return self._get("SFString")

    def getSFBool(self):
        return self._get("SFBool")

    def getMFColor(self, index):
        return list(self._get("MFColor")[index])

    def getMFNode(self, index):
        return self._get("MFNode")[index]

    def setSFVec3f(self, values):
        self._node._set(self._name, "SFVec3f", [float(v) for v in values])

    def setSFRotation(self, values):
        self._node._set(self._name, "SFRotation", [float(v) for v in values])

    def importMFNodeFromString(self, position, node_string):
        if self._kind != "MFNode":
            raise SceneError(f"the field {self._name} is an {self._kind}, not an MFNode")
        self._node._scene.import_node(self._node, position, node_string)


class Node:
    """A node of the scene tree (Webots' Node)."""

    def __init__(self, scene, node_id, type_name, base_type, def_name, values, kinds):
        self._scene = scene
        self._id = node_id
        self._type = type_name
        self._base = base_type
        self._def = def_name
        self._values = values
        self._kinds = kinds

    def getId(self):
        return self._id

    def getDef(self):
        return self._def

    def getTypeName(self):
        return self._type

    def getBaseTypeName(self):
        return self._base

    def getField(self, name):
        if name not in self._kinds:
            print(f'Error: Node.getField(): field "{name}" not found in {self._type} node', file=sys.stderr)
            return None
        return Field(self, name, self._kinds[name])

    def _value(self, name):
        return self._values[name]

    def _set(self, name, kind, value):
        if self._kinds.get(name) != kind:
            raise SceneError(f"the field {name} is an {self._kinds.get(name)}, not an {kind}")
        raise SceneError(f"setting {self._type}.{name} after import is not modelled: the solid stays where it was built")

    def getPosition(self):
        return list(self._values["translation"])

    def getOrientation(self):
        yaw = yaw_of_rotation(self._values["rotation"], f"{self._type}.rotation")
        c, s = math.cos(yaw), math.sin(yaw)
        return [c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0]

    def __repr__(self):
        return f"<Node {self._def or self._type} id={self._id}>"


class RobotNode(Node):
    """The robot's own node (getSelf()): translation and rotation read the simulated pose, and
    setting them teleports the robot."""

    def _value(self, name):
        x, y, z, yaw = self._scene.simulation.pose
        if name == "translation":
            return [x, y, z]
        if name == "rotation":
            return [0.0, 0.0, 1.0, yaw]
        return self._values[name]

    def _set(self, name, kind, value):
        if self._kinds.get(name) != kind or name not in ("translation", "rotation"):
            return super()._set(name, kind, value)
        x, y, z, yaw = self._scene.simulation.pose
        if name == "translation":
            x, y, z = value
        else:
            yaw = yaw_of_rotation(value, "the robot's rotation")
        self._scene.simulation.teleport(x, y, z, yaw)
        self._scene.teleported = True
        self._scene.goal.look_for_controller_goals(None, self._scene.simulation)

    def getPosition(self):
        return self._value("translation")

    def getOrientation(self):
        yaw = self._scene.simulation.pose[3]
        c, s = math.cos(yaw), math.sin(yaw)
        return [c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0]


class Landmark:
    """A landmark cylinder as the camera sees it (world frame, metres)."""

    __slots__ = ("node", "x", "y", "z", "radius", "height", "yaw", "colors")

    def __init__(self, node, x, y, z, radius, height, yaw, colors):
        self.node, self.x, self.y, self.z = node, x, y, z
        self.radius, self.height, self.yaw, self.colors = radius, height, yaw, colors


# How near the robot's centre comes to a goal point for the goal to count as reached, m: a
# landmark standing on the point (the course's cylinders, 0.25 m round) is then within 0.16 m
# of HamBot's body (0.09 m round).
GOAL_RADIUS_M = 0.5


class Goal:
    """The run's goal: a maze's goal cells (reached when the robot's centre is in one), or goal
    points (reached within GOAL_RADIUS_M of one): an arena file's, or on the course's empty
    floor the ones the controller's library read with its world (the course's HamBot keeps them
    as maze.goal_locations, maze_mapper's stand-in as goal_locations: items with x and y),
    looked for when the controller imports a node or teleports the robot, and at the end. The
    simulation checks it after every control step."""

    def __init__(self, cells=(), cell_size_m=1.0, origin=(0.0, 0.0), points=(), from_controller=False):
        self.cells = list(cells)
        self.cell_size_m = cell_size_m
        self.origin = tuple(origin)
        self.points = list(points)
        self.from_controller = from_controller
        self.namespace = {}  # the controller's globals (controller.Robot sets them)

    def attach(self, simulation):
        """Hands the goal to the simulation, which checks it every step."""
        if self.cells or self.points:
            simulation.set_goal(cells=self.cells, cell_size_m=self.cell_size_m, origin=self.origin,
                                points=self.points, radius_m=GOAL_RADIUS_M)

    def look_for_controller_goals(self, robot, simulation):
        """On the empty floor: the goals of the world the controller's library read, once found."""
        if not self.from_controller or self.points:
            return
        holder = self._find_holder(robot)
        if holder is not None:
            self.points = [(g.x, g.y) for g in holder.goal_locations]
            self.attach(simulation)

    def exists(self):
        return bool(self.cells or self.points)

    def _find_holder(self, robot):
        """The object whose goal_locations (non-empty) are the world's goals: the robot, or
        among the controller's globals (the course's HamBot is not the Supervisor it steps
        with), itself or its maze."""
        for value in [robot, *self.namespace.values()]:
            if callable(value) or isinstance(value, types.ModuleType):
                continue  # functions, classes, modules: no world's goals
            for candidate in (value, getattr(value, "maze", None)):
                goals = getattr(candidate, "goal_locations", None)
                if isinstance(goals, list) and goals:
                    return candidate
        return None


class Scene:
    """The world of one run: the simulation (maze_mapper._native.Simulation), the root's
    children, DEF names, and the landmarks the camera can recognise. world_file: the runner's
    --world (imports then add no solid), or None for the course's empty floor."""

    def __init__(self, simulation, robot_type="HamBot", world_file=None, goal=None):
        self.simulation = simulation
        self.world_file = world_file
        self.goal = goal if goal is not None else Goal()
        self.goal.attach(simulation)
        self.landmarks = []
        # (x_min, x_max, y_min, y_max) of the walls (Obstacle nodes) the controller built, m;
        # None before the first: where a grader lays the course's cells on its empty floor.
        self.walls_extent_m = None
        self.teleported = False  # since the last step (the path length leaves teleports out)
        self.reset_requested = False  # Supervisor.simulationReset, done at the end of the next step
        self._warned = False
        self._next_id = 1
        self.root = Node(self, 0, "Group", "Group", "", {"children": []}, {"children": "MFNode"})
        self.robot = RobotNode(self, self._new_id(), robot_type, "Robot", "",
                               {"name": robot_type}, {"translation": "SFVec3f", "rotation": "SFRotation",
                                                      "name": "SFString"})
        self.root._values["children"].append(self.robot)
        self._initial_children = list(self.root._values["children"])
        self._initial_landmarks = []

    def _new_id(self):
        node_id = self._next_id
        self._next_id += 1
        return node_id

    def from_def(self, name):
        for node in self.root._values["children"]:
            if node._def == name:
                return node
        return None

    def from_id(self, node_id):
        if node_id == 0:
            return self.root
        for node in self.root._values["children"]:
            if node._id == node_id:
                return node
        return None

    def import_node(self, parent, position, node_string):
        if parent is not self.root:
            raise SceneError(f"importing into a {parent._type} node is not modelled: only into the root's children")
        def_name, type_name, fields = parse_node(node_string)
        check_extent(type_name, fields)
        kinds = {name: kind for name, (kind, _) in _NODE_FIELDS[type_name].items()}
        node = Node(self, self._new_id(), type_name, "Solid", def_name, fields, kinds)
        yaw = yaw_of_rotation(fields["rotation"], f"{type_name}.rotation")
        self._build(type_name, fields, yaw, node)
        self.goal.look_for_controller_goals(None, self.simulation)
        children = self.root._values["children"]
        children.insert(len(children) if position == -1 or position >= len(children) else position, node)

    def add_world_landmarks(self, landmarks):
        """The landmarks the --world file states ((x, y, height, (r, g, b)) each): Landmark
        nodes among the root's children from the start, recognised by the camera in their
        colour; their cylinders are the world's solids already."""
        schema = _NODE_FIELDS["Landmark"]
        for x, y, height, colour in landmarks:
            fields = {name: (list(default) if isinstance(default, list) else default)
                      for name, (_, default) in schema.items()}
            radius = _native.LANDMARK_RADIUS_M
            fields.update(translation=[x, y, height / 2.0], size=[height, radius, radius], color=list(colour),
                          recognitionColors=[list(colour)])
            node = Node(self, self._new_id(), "Landmark", "Solid", "",
                        fields, {name: kind for name, (kind, _) in schema.items()})
            self.root._values["children"].append(node)
            self.landmarks.append(Landmark(node, x, y, height / 2.0, radius, height, 0.0, list(colour)))
        self._initial_children = list(self.root._values["children"])
        self._initial_landmarks = list(self.landmarks)

    def _build(self, type_name, fields, yaw, node):
        """Adds the node's solid to the simulated world (with --world: nothing, said once)."""
        if self.world_file is not None:
            if not self._warned:
                print(f"warning: the world is {self.world_file} (--world): the nodes the controller imports "
                      "add no solid", file=sys.stderr)
                self._warned = True
            return
        x, y, z = fields["translation"]
        if type_name == "Obstacle":
            across, along, height = fields["size"]
            self.simulation.add_box(x, y, along / 2.0, across / 2.0, yaw + math.pi / 2.0, height_m=z + height / 2.0)
            self._extend_walls(x, y, along / 2.0, across / 2.0, yaw + math.pi / 2.0)
        else:
            height, radius, _ = fields["size"]
            colour = fields.get("color")
            self.simulation.add_cylinder(x, y, radius, height_m=z + height / 2.0,
                                         colour=None if colour is None else list(colour))
            colors = [c for colour in fields["recognitionColors"] for c in colour]
            self.landmarks.append(Landmark(node, x, y, z, radius, height, yaw, colors))

    def _extend_walls(self, x, y, half_length, half_width, yaw):
        c, s = math.cos(yaw), math.sin(yaw)
        xs = [x + i * half_length * c - j * half_width * s for i in (-1, 1) for j in (-1, 1)]
        ys = [y + i * half_length * s + j * half_width * c for i in (-1, 1) for j in (-1, 1)]
        old = self.walls_extent_m or (math.inf, -math.inf, math.inf, -math.inf)
        self.walls_extent_m = (min(old[0], *xs), max(old[1], *xs), min(old[2], *ys), max(old[3], *ys))

    def reset(self):
        """Webots' reset from a supervisor (its Supervisor reference's reset matrix): the nodes
        imported since the start are gone, those of the world removed since are back, the robot is back at its start with its motors and
        encoders at 0, and the simulated time is 0 again. The controller is not restarted, and
        the run's limits count its whole time."""
        self.root._values["children"][:] = self._initial_children
        self.landmarks[:] = self._initial_landmarks
        self.walls_extent_m = None
        self.simulation.reset_world()
        self.teleported = True
        self.reset_requested = False


# The scene of the run in progress (maze_mapper.run sets it), else None.
current = None
