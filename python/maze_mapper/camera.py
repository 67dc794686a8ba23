"""The course HamBot's camera and display for Python controllers (Webots' Camera with a
Recognition node, and Display), computed from the run's scene (scene.current).

The camera, as the course's HamBot carries it: 224 x 224 pixels, horizontal field of view
0.7854 rad, 0.09 m ahead of the robot's origin and 0.08 m up, looking ahead, its Recognition
node Webots' defaults (maxRange 100 m, no object limit, occlusion 1).

Recognition follows Webots' Camera and Recognition reference:
  - only solids whose recognitionColors is not empty are recognised: here the course's
    Landmark nodes a supervisor imported;
  - an object is recognised when its projection meets the image, it is within maxRange, and
    it is not occluded. Occlusion is Webots' own test (occlusion TRUE; WbCamera.cpp and
    WbObjectDetection.cpp): one 3-D ray from the camera to the object's position (a
    landmark's centre, half its height up), collided with every other solid; each solid it
    enters gives the distance from that entry to the object's position, and the object is
    occluded when the largest exceeds half the object's size along the camera's axis (an
    upright cylinder seen level: its radius). The ray enters a solid only where it passes
    below the solid's top, so a tall landmark is seen over a lower wall when the line to its
    centre clears the wall, and hidden when that line meets it;
  - getPosition() is the object's centre in the camera's frame (x ahead, y left, z up, m);
    getOrientation() its rotation relative to the camera (axis-angle); getSize() its width and
    height as the camera sees them (y and z in the camera frame: a cylinder's diameter and
    height); getPositionOnImage() the centre of its bounding box on the image and
    getSizeOnImage() that box's size (pixels, the box clipped to the image);
  - getColors() the recognitionColors, flattened [r, g, b, ...]; getModel() the Solid's model
    field (the course's Landmark PROTO sets none: "").
Projection is the pinhole camera's, focal length width / 2 / tan(fov / 2) pixels, square
pixels. getImage() renders the world from the same pose as Webots' BGRA bytes: the floor,
every solid along each column of pixels from the floor to its top (walls grey, landmarks in
their colour), a nearer one drawn over a farther one, so what stands above a wall shows over
it; a solid whose world states no height is drawn 0.5 m tall (the course's walls) and hides
what is behind it; the sky above.
"""

import math

from . import scene as _scene
from .devices import _Device, _Sensor

WIDTH_PX = 224
HEIGHT_PX = 224
FOV_RAD = 0.7854
MOUNT_M = (0.09, 0.0, 0.08)  # ahead, left, up of the robot's origin
RECOGNITION_MAX_RANGE_M = 100.0
WALL_HEIGHT_M = 0.5

_FLOOR_BGRA = (110, 110, 110, 255)
_SKY_BGRA = (235, 206, 135, 255)
_WALL_BGRA = (200, 200, 200, 255)


class CameraRecognitionObject:
    """One recognised object (Webots' CameraRecognitionObject)."""

    def __init__(self, node_id, position, orientation, size, position_on_image, size_on_image, colors, model):
        self.id = node_id
        self.position = position
        self.orientation = orientation
        self.size = size
        self.position_on_image = position_on_image
        self.size_on_image = size_on_image
        self.colors = colors
        self.number_of_colors = len(colors) // 3
        self.model = model

    def getId(self):
        return self.id

    def getPosition(self):
        return list(self.position)

    def getOrientation(self):
        return list(self.orientation)

    def getSize(self):
        return list(self.size)

    def getPositionOnImage(self):
        return list(self.position_on_image)

    def getSizeOnImage(self):
        return list(self.size_on_image)

    def getNumberOfColors(self):
        return self.number_of_colors

    def getColors(self):
        return list(self.colors)

    def getModel(self):
        return self.model


def _camera_pose():
    """The camera's (x, y, z, yaw) in the world."""
    x, y, z, yaw = _scene.current.simulation.pose
    ahead, left, up = MOUNT_M
    c, s = math.cos(yaw), math.sin(yaw)
    return x + c * ahead - s * left, y + s * ahead + c * left, z + up, yaw


def focal_px():
    return WIDTH_PX / 2.0 / math.tan(FOV_RAD / 2.0)


def recognise(landmark, camera):
    """The recognition object of a landmark seen from the camera pose, or None."""
    cx, cy, cz, yaw = camera
    dx, dy = landmark.x - cx, landmark.y - cy
    c, s = math.cos(yaw), math.sin(yaw)
    ahead, left, up = c * dx + s * dy, -s * dx + c * dy, landmark.z - cz
    distance = math.hypot(ahead, left)
    if distance <= landmark.radius or ahead <= 0.0 or math.hypot(distance, up) > RECOGNITION_MAX_RANGE_M:
        return None
    f = focal_px()
    bearing = math.atan2(left, ahead)
    half = math.asin(landmark.radius / distance)
    if bearing + half >= math.pi / 2.0 or bearing - half <= -math.pi / 2.0:
        return None
    u0 = WIDTH_PX / 2.0 - f * math.tan(bearing + half)
    u1 = WIDTH_PX / 2.0 - f * math.tan(bearing - half)
    bottom, top = landmark.z - landmark.height / 2.0, landmark.z + landmark.height / 2.0
    v0 = HEIGHT_PX / 2.0 - f * (top - cz) / ahead
    v1 = HEIGHT_PX / 2.0 - f * (bottom - cz) / ahead
    u0, u1 = max(u0, 0.0), min(u1, float(WIDTH_PX))
    v0, v1 = max(v0, 0.0), min(v1, float(HEIGHT_PX))
    if u0 >= u1 or v0 >= v1:
        return None
    # Occlusion TRUE: Webots' ray test (see the module's description).
    if _scene.current.simulation.sight_blocked((cx, cy, cz), (landmark.x, landmark.y, landmark.z), landmark.radius):
        return None
    relative_yaw = math.atan2(math.sin(landmark.yaw - yaw), math.cos(landmark.yaw - yaw))
    orientation = [0.0, 0.0, 1.0, relative_yaw] if relative_yaw >= 0.0 else [0.0, 0.0, -1.0, -relative_yaw]
    return CameraRecognitionObject(
        landmark.node.getId(), [ahead, left, up], orientation, [2.0 * landmark.radius, landmark.height],
        [int((u0 + u1) / 2.0), int((v0 + v1) / 2.0)], [int(round(u1 - u0)), int(round(v1 - v0))],
        list(landmark.colors), "")


class Camera(_Sensor):
    """The course HamBot's camera (Webots' Camera, with recognition)."""

    def __init__(self, name="camera"):
        super().__init__(name)
        self._recognition_ms = 0

    def getWidth(self):
        return WIDTH_PX

    def getHeight(self):
        return HEIGHT_PX

    def getFov(self):
        return FOV_RAD

    def getFocalLength(self):
        return 0.0

    def hasRecognition(self):
        return True

    def recognitionEnable(self, sampling_period):
        self._recognition_ms = int(sampling_period)

    def recognitionDisable(self):
        self._recognition_ms = 0

    def recognitionGetSamplingPeriod(self):
        return self._recognition_ms

    def getRecognitionSamplingPeriod(self):
        return self._recognition_ms

    def getRecognitionObjects(self):
        """The landmarks in view (see the module's description); [] until recognitionEnable."""
        if self._recognition_ms <= 0 or _scene.current is None:
            return []
        camera = _camera_pose()
        found = (recognise(landmark, camera) for landmark in _scene.current.landmarks if landmark.colors)
        return [o for o in found if o is not None]

    def getRecognitionNumberOfObjects(self):
        return len(self.getRecognitionObjects())

    def getImage(self):
        """The image as Webots' BGRA bytes (rows top to bottom), None until enable."""
        if self._period_ms <= 0 or _scene.current is None:
            return None
        return render(_camera_pose()).tobytes()

    def getImageArray(self):
        """The image as Webots' getImageArray: [x][y] -> [r, g, b]."""
        image = self.getImage()
        if image is None:
            return None
        import numpy as np
        bgra = np.frombuffer(image, dtype=np.uint8).reshape(HEIGHT_PX, WIDTH_PX, 4)
        return bgra[:, :, 2::-1].transpose(1, 0, 2).tolist()

    @staticmethod
    def imageGetRed(image, width, x, y):
        return image[4 * (y * width + x) + 2]

    @staticmethod
    def imageGetGreen(image, width, x, y):
        return image[4 * (y * width + x) + 1]

    @staticmethod
    def imageGetBlue(image, width, x, y):
        return image[4 * (y * width + x)]

    @staticmethod
    def imageGetGray(image, width, x, y):
        i = 4 * (y * width + x)
        return (image[i] + image[i + 1] + image[i + 2]) // 3


def render(camera):
    """A HEIGHT_PX x WIDTH_PX x 4 uint8 BGRA image of the scene from the camera pose: one ray
    a column through the simulator's solids, each solid it enters drawn from the floor up to
    its top at its distance, the farthest first."""
    import numpy as np
    cx, cy, cz, yaw = camera
    f = focal_px()
    image = np.empty((HEIGHT_PX, WIDTH_PX, 4), dtype=np.uint8)
    image[:HEIGHT_PX // 2] = _SKY_BGRA
    image[HEIGHT_PX // 2:] = _FLOOR_BGRA
    simulation = _scene.current.simulation
    rows = np.arange(HEIGHT_PX) + 0.5
    for column in range(WIDTH_PX):
        offset = math.atan2(WIDTH_PX / 2.0 - (column + 0.5), f)
        hits = []
        for distance, top, colour in simulation.hits_along(cx, cy, yaw + offset, 1000.0):
            hits.append((distance, top if math.isfinite(top) else WALL_HEIGHT_M, colour))
            if not math.isfinite(top):
                break  # a solid of no stated height hides everything behind it
        for distance, top, colour in reversed(hits):
            depth = max(distance * math.cos(offset), 1e-6)
            v_top = HEIGHT_PX / 2.0 - f * (top - cz) / depth
            v_bottom = HEIGHT_PX / 2.0 + f * cz / depth
            image[(rows >= v_top) & (rows <= v_bottom), column] = _bgra(colour)
    return image


def _bgra(colour):
    """A landmark's (r, g, b) in [0, 1] as BGRA bytes; None: a wall's grey."""
    if colour is None:
        return _WALL_BGRA
    r, g, b = (min(255, int(round(255 * v))) for v in colour)
    return (b, g, r, 255)


class Display(_Device):
    """The course HamBot's "User Display" (Webots' Display, 64 x 64): it accepts every drawing
    call and shows nothing (there is no window here)."""

    RGB, RGBA, ARGB, BGRA, ABGR = 0x3, 0x4, 0x5, 0x6, 0x7

    def __init__(self, name="User Display", width=64, height=64):
        super().__init__(name)
        self._width, self._height = width, height

    def getWidth(self):
        return self._width

    def getHeight(self):
        return self._height

    def imageLoad(self, filename):
        return ImageRef(filename)

    def imageNew(self, data, format, width=None, height=None):
        return ImageRef(None)

    def imageCopy(self, x, y, width, height):
        return ImageRef(None)

    def __getattr__(self, name):
        # setOpacity, setColor, drawLine, imagePaste, imageDelete, ...: accepted, drawing nothing.
        if name.startswith(("set", "draw", "fill", "image", "attach", "detach")):
            return lambda *args, **kwargs: None
        raise AttributeError(name)


class ImageRef:
    """A display image (Webots' ImageRef); nothing is drawn here."""

    def __init__(self, source):
        self.source = source
