"""The rest of Webots' Supervisor, Node and Field API over the scene tree of scene.py, added to
those classes (controller.py imports this module):

  Supervisor.setLabel(id, label, x, y, size, color, transparency=0, font='Arial')
      Webots' checks (x, y, size, transparency within [0, 1], an error line otherwise); the
      labels are kept (supervisor.labels: id -> (label, x, y, size, color, transparency, font)),
      not drawn: there is no 3D window.
  Supervisor.exportImage(filename, quality)
      the 3D view's stand-in: the world seen from above as a PNG (.png; JPEG is refused with
      an error line), 320 pixels on its longer side: the floor, the solids, the landmarks in
      their colour and the robot; quality checked as Webots checks it (1 to 100).
  Supervisor.worldReload()
      Webots reloads the world and starts the controller again; here the world is put back as
      simulationReset puts it, and the run ends: the controller's next step returns -1.
  Supervisor.getSelected()
      None: nothing is selected without a 3D window.
  Supervisor.getFromDevice(device)
      the device's node (its type Webots' node type: Lidar, RotationalMotor, ...), a child of
      the robot's node, the same Node each call.
  Node.getPose(from_node=None)
      the node's 4 x 4 transform (16 numbers, row by row; metres) in the world, or relative to
      from_node: inverse(from_node's) x node's. A device's node has the robot's pose.
  Node.getVelocity()
      [vx, vy, vz, wx, wy, wz] in the world (m/s, rad/s) over the last step: the robot's and its
      devices'; zeros for the solids, which do not move.
  Node.remove()
      takes a node of the root's children out of the tree and its solid out of the simulated
      world at once, as Webots does: the lidar, the distance sensors, the camera (recognition
      and getImage), the body and the pictures meet it no more. An Obstacle takes out what its
      box covers of the world's boxes and walls (with the runner's --world, the walls the
      course's library imports as Obstacles stand for the world file's own: removing one takes
      that wall out, a lattice's one cell side of a run of walls); a Landmark takes the
      cylinder at its centre (the world's landmarks are nodes from the start). Removing the
      root prints Webots' error; removing the robot or a device's node raises SceneError.
      simulationReset brings the world's removed nodes back, as it takes the imported ones.
  Node.getParentNode()
      the root for its children, the robot's node for a device's node, None for the root.
  Node.resetPhysics()
      nothing to stop: the body has no momentum of its own here (its wheels drive it).
  Field.getType(), Field.SF_BOOL ... MF_NODE
      Webots' field type codes.
  Field.getSFFloat(), getSFInt32()
      the value of an SFFloat or SFInt32 field; the nodes modelled have none, so another field
      raises SceneError naming its type, as every getter here does.
  Field.removeMF(index)
      removes an item (index from 0; -1 the last): a node of the root's children (as
      Node.remove), a colour of a landmark's recognitionColors (the camera stops recognising it
      when none is left).
"""

import math
import sys

from . import scene as _scene
from .scene import Field, Node, SceneError

FIELD_TYPES = {"SFBool": 0x01, "SFInt32": 0x02, "SFFloat": 0x03, "SFVec2f": 0x04, "SFVec3f": 0x05,
               "SFRotation": 0x06, "SFColor": 0x07, "SFString": 0x08, "SFNode": 0x09,
               "MFBool": 0x11, "MFInt32": 0x12, "MFFloat": 0x13, "MFVec2f": 0x14, "MFVec3f": 0x15,
               "MFRotation": 0x16, "MFColor": 0x17, "MFString": 0x18, "MFNode": 0x19}
for _kind, _code in FIELD_TYPES.items():
    setattr(Field, _kind[:2].upper() + "_" + _kind[2:].upper(), _code)
Field.NO_FIELD = 0x00

# The node type of each device class (Webots' node names).
_DEVICE_NODE_TYPES = {"Lidar": "Lidar", "Motor": "RotationalMotor", "PositionSensor": "PositionSensor",
                      "InertialUnit": "InertialUnit", "GPS": "GPS", "DistanceSensor": "DistanceSensor",
                      "TouchSensor": "TouchSensor", "Camera": "Camera", "Display": "Display"}


def _field_get_type(field):
    return FIELD_TYPES[field._kind]


def _field_remove_mf(field, index):
    if not field._kind.startswith("MF"):
        raise SceneError(f"the field {field._name} is an {field._kind}, not a multiple field (MF...)")
    items = field._node._values[field._name]
    count = len(items)
    position = index + count if index < 0 else index
    if not 0 <= position < count:
        print(f"Error: wb_supervisor_field_remove_mf() called with an out-of-bound index: {index} "
              f"(should be between {-count} and {count - 1}).", file=sys.stderr)
        return
    if field._kind == "MFNode":
        _remove(items[position])
        return
    if field._kind == "MFColor" and field._name == "recognitionColors":
        del items[position]
        for landmark in _scene.current.landmarks:
            if landmark.node is field._node:
                landmark.colors = [c for colour in items for c in colour]
        return
    raise SceneError(f"removing from {field._node._type}.{field._name} is not modelled")


Field.getType = _field_get_type
Field.getSFFloat = lambda field: field._get("SFFloat")
Field.getSFInt32 = lambda field: field._get("SFInt32")
Field.removeMF = _field_remove_mf


# ---- nodes ----

def _yaw_and_position(node):
    """(yaw, [x, y, z]) of a node in the world."""
    if node is node._scene.root:
        return 0.0, [0.0, 0.0, 0.0]
    if getattr(node, "_device", None) is not None or node is node._scene.robot:
        x, y, z, yaw = node._scene.simulation.pose
        return yaw, [x, y, z]
    yaw = _scene.yaw_of_rotation(node._values["rotation"], f"{node._type}.rotation")
    return yaw, list(node._values["translation"])


def _matrix(yaw, position):
    c, s = math.cos(yaw), math.sin(yaw)
    return [c, -s, 0.0, position[0], s, c, 0.0, position[1], 0.0, 0.0, 1.0, position[2], 0.0, 0.0, 0.0, 1.0]


def _get_pose(node, from_node=None):
    yaw, position = _yaw_and_position(node)
    if from_node is None:
        return _matrix(yaw, position)
    base_yaw, base = _yaw_and_position(from_node)
    c, s = math.cos(base_yaw), math.sin(base_yaw)
    dx, dy, dz = (position[i] - base[i] for i in range(3))
    return _matrix(yaw - base_yaw, [c * dx + s * dy, -s * dx + c * dy, dz])


def _get_velocity(node):
    from .controller import Robot
    robot = Robot.created
    moving = node is node._scene.robot or getattr(node, "_device", None) is not None
    if not moving or robot is None or robot._before is None or not getattr(robot, "_step_s", 0.0) > 0.0:
        return [0.0] * 6
    x0, y0, z0, yaw0 = robot._before  # the pose when the last step began
    x1, y1, z1, yaw1 = node._scene.simulation.pose
    dt = robot._step_s
    turn = math.atan2(math.sin(yaw1 - yaw0), math.cos(yaw1 - yaw0))
    return [(x1 - x0) / dt, (y1 - y0) / dt, (z1 - z0) / dt, 0.0, 0.0, turn / dt]


def _parent(node):
    scene = node._scene
    if node is scene.root:
        return None
    if getattr(node, "_device", None) is not None:
        return scene.robot
    return scene.root if any(child is node for child in scene.root._values["children"]) else None


def _remove(node):
    scene = node._scene
    if node is scene.root:
        print("Error: wb_supervisor_node_remove() called with a NULL or invalid 'node' argument.", file=sys.stderr)
        return
    if node is scene.robot:
        raise SceneError("removing the robot's own node is not modelled (in Webots it ends its controller)")
    children = scene.root._values["children"]
    if getattr(node, "_device", None) is not None or not any(child is node for child in children):
        raise SceneError(f"removing {node!r} is not modelled: only the root's children can be removed")
    _remove_solid(node)
    children[:] = [child for child in children if child is not node]


def _remove_solid(node):
    """Takes the node's solid out of the simulated world (none there: nothing to take)."""
    scene = node._scene
    x, y, _ = node._values["translation"]
    if node._type == "Obstacle":
        yaw = _scene.yaw_of_rotation(node._values["rotation"], "Obstacle.rotation")
        across, along, _ = node._values["size"]
        scene.simulation.remove_box(x, y, along / 2.0, across / 2.0, yaw + math.pi / 2.0)
    elif node._type == "Landmark":
        scene.simulation.remove_cylinder(x, y)
        scene.landmarks[:] = [landmark for landmark in scene.landmarks if landmark.node is not node]


Node.getPose = _get_pose
Node.getVelocity = _get_velocity
Node.getParentNode = _parent
Node.remove = _remove
Node.resetPhysics = lambda node: None


# ---- the supervisor ----

def set_label(supervisor, label_id, label, x, y, size, color, transparency=0, font="Arial"):
    for name, value in (("x", x), ("y", y), ("size", size), ("transparency", transparency)):
        if not 0 <= value <= 1:
            print(f"Error: wb_supervisor_set_label() called with {name} parameter outside of [0,1] range.",
                  file=sys.stderr)
            return
    supervisor.__dict__.setdefault("labels", {})[int(label_id)] = (str(label), x, y, size, int(color), transparency,
                                                                   font)


def get_from_device(supervisor, device):
    scene = supervisor._scene()
    if device is None or getattr(device, "getName", None) is None:
        print("Error: wb_supervisor_node_get_from_device() called with an invalid 'tag' argument.", file=sys.stderr)
        return None
    nodes = scene.__dict__.setdefault("device_nodes", {})
    name = device.getName()
    if name not in nodes:
        kind = getattr(device, "NODE_TYPE", "") or _DEVICE_NODE_TYPES.get(type(device).__name__, "Device")
        node = Node(scene, scene._new_id(), kind, kind, "", {"name": name}, {"name": "SFString"})
        node._device = device
        nodes[name] = node
    return nodes[name]


def world_reload(supervisor):
    scene = supervisor._scene()
    scene.reset()
    scene.simulation.request_stop()


def export_image(supervisor, filename, quality):
    if not filename:
        print("Error: wb_supervisor_export_image() called with NULL or empty 'filename' argument.", file=sys.stderr)
        return
    if not 1 <= quality <= 100:
        print(f"Error: wb_supervisor_export_image(): 'quality' argument ({quality}) must be between 1 and 100.",
              file=sys.stderr)
        return
    if not filename.lower().endswith(".png"):
        print(f"Error: Supervisor.exportImage(): {filename}: the embedded simulator writes PNG (.png) only",
              file=sys.stderr)
        return
    from ._png import write_png
    from .overhead import overhead_view
    try:
        write_png(filename, overhead_view(supervisor._scene()))
    except OSError as e:
        print(f"Error: Supervisor.exportImage(): cannot write {filename}: {e.strerror}", file=sys.stderr)


def add_supervisor_methods(supervisor_class):
    supervisor_class.setLabel = set_label
    supervisor_class.exportImage = export_image
    supervisor_class.worldReload = world_reload
    supervisor_class.getSelected = lambda supervisor: None
    supervisor_class.getFromDevice = get_from_device
