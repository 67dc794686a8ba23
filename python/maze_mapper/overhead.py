"""The world seen from above, as Supervisor.exportImage writes it: an RGB image of the floor
the robot stays on, the solids of the simulated world (grey), the landmarks in their colour
and the robot (a dark disc with a line to where it faces). Row 0 is the north edge."""

import math

SIDE_PX = 320  # pixels on the image's longer side

_FLOOR_RGB = (235, 235, 225)
_SOLID_RGB = (120, 120, 120)
_ROBOT_RGB = (30, 60, 160)


def _bounds(scene):
    """(x_min, x_max, y_min, y_max) of the floor, m."""
    built = scene.simulation.built_world()
    world = built if built is not None else getattr(scene, "world_read", None)
    if world is None:
        x, y = scene.simulation.pose[:2]
        return x - 5.0, x + 5.0, y - 5.0, y + 5.0
    return world.boundary


def overhead_view(scene):
    """The H x W x 3 uint8 image (see the module's description)."""
    import numpy as np
    x_min, x_max, y_min, y_max = _bounds(scene)
    metres_per_px = max(x_max - x_min, y_max - y_min) / SIDE_PX
    width = max(1, int(math.ceil((x_max - x_min) / metres_per_px)))
    height = max(1, int(math.ceil((y_max - y_min) / metres_per_px)))
    image = np.empty((height, width, 3), dtype=np.uint8)
    image[:] = _FLOOR_RGB
    cast = scene.simulation.cast
    xs = [x_min + (i + 0.5) * metres_per_px for i in range(width)]
    step = metres_per_px
    for row in range(height):
        y = y_max - (row + 0.5) * step
        # A pixel is a solid's when its middle lines, across and down, meet one (a ray cast
        # from inside a solid is 0 long): a wall thinner than a pixel is drawn too.
        hit = [cast(x - step / 2, y, 0.0, step) < step or cast(x, y + step / 2, -math.pi / 2, step) < step
               for x in xs]
        image[row, np.array(hit, dtype=bool)] = _SOLID_RGB
    grid_x = x_min + (np.arange(width) + 0.5) * metres_per_px
    grid_y = y_max - (np.arange(height) + 0.5) * metres_per_px
    for landmark in scene.landmarks:
        colour = landmark.node._values.get("color", [1.0, 1.0, 1.0])
        disc = (grid_x[None, :] - landmark.x) ** 2 + (grid_y[:, None] - landmark.y) ** 2 <= landmark.radius ** 2
        image[disc] = [min(255, int(round(255 * c))) for c in colour]
    _draw_robot(image, grid_x, grid_y, scene, metres_per_px)
    return image


def _draw_robot(image, grid_x, grid_y, scene, metres_per_px):
    import numpy as np
    x, y, _, yaw = scene.simulation.pose
    radius = max(0.09, 3 * metres_per_px)
    image[(grid_x[None, :] - x) ** 2 + (grid_y[:, None] - y) ** 2 <= radius ** 2] = _ROBOT_RGB
    for k in range(int(2 * radius / metres_per_px) + 1):
        px = x + math.cos(yaw) * k * metres_per_px
        py = y + math.sin(yaw) * k * metres_per_px
        column = int((px - grid_x[0]) / metres_per_px + 0.5)
        row = int((grid_y[0] - py) / metres_per_px + 0.5)
        if 0 <= row < image.shape[0] and 0 <= column < image.shape[1]:
            image[row, column] = (255, 255, 255)
