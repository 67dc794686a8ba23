"""The rest of Webots' Python API a student reaches for, each against Webots' reference:
Compass, Accelerometer, Gyro and LED (the runner's --device), the Supervisor's, Node's and
Field's methods, and the simulator's own devices' further methods."""

import math
import struct

from conftest import run_controller, summary_of

HEADER = """
import math
from controller import Supervisor, Field, GPS, Keyboard
robot = Supervisor()
step = int(robot.getBasicTimeStep())
left, right = robot.getDevice("left motor"), robot.getDevice("right motor")
def drive(l, r, steps):
    left.setPosition(float("inf")); right.setPosition(float("inf"))
    left.setVelocity(l); right.setVelocity(r)
    for _ in range(steps):
        robot.step(step)
"""


def _run(controller_file, body, *args):
    status, out, err = run_controller(controller_file(HEADER + body), *args)
    assert status == 0, err
    return out.split("\n\n")[0].splitlines(), err


def _numbers(line):
    return [float(v) for v in line.split()[1:]]


def test_motion_sensors_read_the_simulated_pose_in_webots_axes(controller_file):
    body = """
compass, gyro, accel = robot.getDevice("compass"), robot.getDevice("gyro"), robot.getDevice("accelerometer")
imu = robot.getDevice("imu")
print("disabled", *compass.getValues())
for device in (compass, gyro, accel, imu):
    device.enable(step)
robot.step(step)
print("north", *compass.getValues())
print("rest", *accel.getValues(), *gyro.getValues())
drive(-4, 4, 10)
yaw0 = imu.getRollPitchYaw()[2]
robot.step(step)
yaw1 = imu.getRollPitchYaw()[2]
print("spin", *gyro.getValues(), (yaw1 - yaw0) / (step / 1000))
print("heading", *compass.getValues(), math.sin(yaw1), math.cos(yaw1))
drive(4, 6, 20)
x0, y0 = robot.getSelf().getPosition()[:2]
yaw0 = imu.getRollPitchYaw()[2]
robot.step(step)
x1, y1 = robot.getSelf().getPosition()[:2]
yaw1 = imu.getRollPitchYaw()[2]
v = math.hypot(x1 - x0, y1 - y0) / (step / 1000)
w = (yaw1 - yaw0) / (step / 1000)
print("arc", *accel.getValues(), v * w)
"""
    lines, _ = _run(controller_file, body, "--device", "compass", "--device", "gyro", "--device", "accelerometer")
    values = {line.split()[0]: _numbers(line) for line in lines}
    assert all(math.isnan(v) for v in values["disabled"])
    assert values["north"] == [1.0, 0.0, 0.0] or max(abs(a - b) for a, b in zip(values["north"], [1, 0, 0])) < 1e-9
    assert values["rest"] == [0.0, 0.0, 9.81, 0.0, 0.0, 0.0]
    wx, wy, wz, imu_rate = values["spin"]
    assert wx == wy == 0.0 and wz > 1.0 and abs(wz - imu_rate) < 1e-6
    nx, ny, nz, sin_yaw, cos_yaw = values["heading"]
    assert abs(nx - sin_yaw) < 1e-9 and abs(ny - cos_yaw) < 1e-9 and nz == 0.0
    ax, ay, az, centripetal = values["arc"]
    assert abs(ax) < 1e-6 and az == 9.81  # a steady arc: no speed change ahead
    assert ay > 0.01 and abs(ay - centripetal) < 0.02 * centripetal  # v * w towards the turn (left)


def test_a_robot_has_only_the_devices_its_file_and_the_runner_give_it(controller_file):
    body = """
print(robot.getDevice("compass"))
"""
    lines, err = _run(controller_file, body)
    assert lines == ["None"] and err == 'Device "compass" was not found on robot "hambot"\n'
    body = """
led = robot.getDevice("status")
print(led.get(), led.getName())
led.set(2)
print(led.get())
"""
    lines, _ = _run(controller_file, body, "--device", "led:status")
    assert lines == ["0 status", "2"]


def test_motor_and_encoder_methods_follow_webots(controller_file):
    body = """
print(left.getTargetPosition())
left.setPosition(1.5)
print(left.getTargetPosition())
left.setPosition(float("inf"))
print(left.getTargetPosition())
print(left.getPositionSensor().getName(), right.getPositionSensor().getName())
print(robot.getDevice("left wheel encoder").getMotor().getName())
"""
    lines, _ = _run(controller_file, body)
    assert lines == ["0.0", "1.5", "inf", "left wheel encoder right wheel encoder", "left motor"]


def test_lidar_gps_and_camera_methods_follow_webots(controller_file, tmp_path):
    body = f"""
lidar, gps, camera = robot.getDevice("lidar"), robot.getDevice("gps"), robot.getDevice("camera")
print(lidar.getVerticalFov(), lidar.getMinFrequency(), lidar.getMaxFrequency())
lidar.setFrequency(30)
lidar.setFrequency(5)
print(gps.getCoordinateSystem(), GPS.LOCAL, GPS.WGS84)
print(camera.getMinFov(), camera.getMaxFov())
camera.setFov(0.5)
camera.setFov(camera.getFov())
print(camera.saveImage({str(tmp_path / "before.png")!r}, 100))
camera.enable(step)
robot.step(step)
print(camera.saveImage({str(tmp_path / "view.png")!r}, 100), camera.saveImage({str(tmp_path / "view.jpg")!r}, 90))
"""
    lines, err = _run(controller_file, body)
    assert lines[:3] == ["0.2 1.0 25.0", "0 0 1", "0.7854 0.7854"]
    assert lines[3:] == ["-1", "0 -1"]
    assert err.splitlines() == [
        "Error: wb_lidar_set_frequency() out of frequency range [1.000000, 25.000000].",
        "Warning: Lidar.setFrequency(5): lidar is a fixed lidar: it has no head to turn, the call changes nothing",
        "Error: wb_camera_set_fov() out of zoom range [0.785400, 0.785400].",
        "Error: Camera.saveImage(): no image: enable the camera first",
        f"Error: Camera.saveImage(): {tmp_path / 'view.jpg'}: JPEG is not written by the embedded simulator: "
        "use a .png name"]
    data = (tmp_path / "view.png").read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and struct.unpack(">II", data[16:24]) == (224, 224)
    assert not (tmp_path / "view.jpg").exists()


def test_set_frequency_turns_a_rotating_lidar_s_head_at_the_new_frequency_from_where_it_stands(controller_file):
    # Webots' reference (lidar.md): setFrequency sets the rotating head's frequency, within
    # [minFrequency, maxFrequency]; getFrequency returns it; the head turns once enabled.
    body = """
lidar = robot.getDevice("lidar")
def swept():
    return sum(1 for r in lidar.getRangeImage() if r != 0.0)  # a beam the head has not passed reads 0
print(lidar.getFrequency(), lidar.getMinFrequency(), lidar.getMaxFrequency())
lidar.setFrequency(26)
lidar.setFrequency(2)
print(lidar.getFrequency())
lidar.enable(step)
robot.step(step)
first = swept()
for _ in range(4):
    robot.step(step)
five = swept()
lidar.setFrequency(10)
robot.step(step)
print(first, five, swept(), lidar.getFrequency())
for _ in range(3):
    robot.step(step)
print(swept())
"""
    lines, err = _run(controller_file, body, "--robot", "hambot-2025")
    assert lines[0] == "12.0 1.0 25.0" and lines[1] == "2.0"
    first, five, six, frequency = lines[2].split()
    # 2 Hz x 32 ms: 0.064 of a turn a step (23 of 360 beams), 0.32 in five steps (115); then
    # 10 Hz: 0.32 a step more, on from there (not from ahead again: 115 would be swept again)
    assert abs(int(first) - 23) <= 1 and abs(int(five) - 115) <= 1 and abs(int(six) - 230) <= 1, lines
    assert frequency == "10.0" and lines[3] == "360"
    assert err.splitlines() == ["Error: wb_lidar_set_frequency() out of frequency range [1.000000, 25.000000]."]


def test_removing_a_world_s_landmark_and_a_wall_takes_them_out_of_the_lidar_and_camera(controller_file):
    # Webots' Node.remove takes the node out of the scene: nothing sees or meets it any more.
    body = """
lidar, camera = robot.getDevice("lidar"), robot.getDevice("camera")
lidar.enable(step)
camera.enable(step)
camera.recognitionEnable(step)
n = lidar.getHorizontalResolution()
def look(what):
    robot.step(step)
    image = lidar.getRangeImage()
    ahead = min(image[n // 2 - 2:n // 2 + 3])
    behind = min(image[:3] + image[-3:])
    pixels = camera.getImage()
    yellow = sum(1 for i in range(0, len(pixels), 4)
                 if pixels[i + 2] > 200 and pixels[i + 1] > 200 and pixels[i] < 60)  # BGRA
    print(what, round(ahead, 2), round(behind, 2), camera.getRecognitionNumberOfObjects(), yellow > 0)
children = robot.getRoot().getField("children")
look("before")
# the west wall's metre beside the robot, as the course's library imports a wall (two decimals)
children.importMFNodeFromString(-1, 'DEF W Obstacle { translation -2.00 0.50 0.25 rotation 0.00 0.00 1.00 0.00 '
                                    'size 0.01 1.00 0.50 }')
robot.getFromDef("W").remove()
landmark = [children.getMFNode(i) for i in range(children.getCount())
            if children.getMFNode(i).getTypeName() == "Landmark"][0]
landmark.remove()
look("after")
robot.simulationReset()
robot.step(step)
print([children.getMFNode(i).getTypeName() for i in range(children.getCount())])
"""
    start = ["--world", "python/tests/course_shape/WebotsSim/worlds/bug0_landmark.xml", "--start", "pos:1"]
    lines, err = _run(controller_file, body, *start)
    before, after = lines[0].split(), lines[1].split()
    # from (-1.5, 0.1) facing east: the landmark (radius 0.25) at (1.5, 0) ahead, the west wall behind
    assert before[0] == "before" and abs(float(before[1]) - 2.75) < 0.03 and abs(float(before[2]) - 0.49) < 0.03
    assert before[3:] == ["1", "True"]
    assert after[0] == "after" and float(after[1]) > 3.4 and float(after[2]) > 2.0  # the wall behind: inf or far
    assert after[3:] == ["0", "False"]
    assert lines[2] == "['HamBot', 'Landmark']"  # the reset brings the world's landmark back


def test_supervisor_labels_selection_images_and_devices(controller_file, tmp_path):
    body = f"""
robot.setLabel(0, "hello", 0.1, 0.2, 0.1, 0xff0000)
robot.setLabel(1, "off", 1.5, 0.2, 0.1, 0xff0000)
print(robot.labels)
print(robot.getSelected())
node = robot.getFromDevice(robot.getDevice("lidar"))
print(node.getTypeName(), node.getParentNode() == robot.getSelf(), robot.getFromDevice(robot.getDevice("lidar")) is node)
print(robot.getFromDevice(left).getTypeName(), robot.getSelf().getParentNode() is robot.getRoot())
print(robot.getRoot().getParentNode())
robot.exportImage({str(tmp_path / "world.png")!r}, 100)
robot.exportImage({str(tmp_path / "world.jpg")!r}, 100)
robot.exportImage({str(tmp_path / "q.png")!r}, 0)
"""
    lines, err = _run(controller_file, body, "--world", "worlds/lab4x4.txt")
    assert lines == ["{0: ('hello', 0.1, 0.2, 0.1, 16711680, 0, 'Arial')}", "None", "Lidar True True",
                     "RotationalMotor True", "None"]
    assert err.splitlines() == [
        "Error: wb_supervisor_set_label() called with x parameter outside of [0,1] range.",
        f"Error: Supervisor.exportImage(): {tmp_path / 'world.jpg'}: the embedded simulator writes PNG (.png) only",
        "Error: wb_supervisor_export_image(): 'quality' argument (0) must be between 1 and 100."]
    data = (tmp_path / "world.png").read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and struct.unpack(">II", data[16:24]) == (320, 320)


def test_node_pose_and_velocity_are_webots_matrices_and_vectors(controller_file):
    body = """
me = robot.getSelf()
robot.getRoot().getField("children").importMFNodeFromString(-1,
    'DEF BOX Obstacle { translation 2 1 0.25 rotation 0 0 1 1.5707963267948966 size 0.1 1 0.5 }')
box = robot.getFromDef("BOX")
print(*[round(v, 6) for v in box.getPose()])
print(*[round(v, 6) for v in box.getPose(me)])
print(*box.getVelocity())
drive(5, 5, 10)
gps = robot.getDevice("gps"); gps.enable(step); robot.step(step)
print(*[round(v, 9) for v in me.getVelocity()])
print(*[round(v, 9) for v in gps.getSpeedVector()])
me.resetPhysics()
"""
    lines, _ = _run(controller_file, body)
    # The robot starts at the origin facing north: the box at (2, 1) is 1 m ahead and 2 m to its right.
    assert _numbers("p " + lines[0]) == [0, -1, 0, 2, 1, 0, 0, 1, 0, 0, 1, 0.25, 0, 0, 0, 1]
    assert _numbers("p " + lines[1]) == [1, 0, 0, 1, 0, 1, 0, -2, 0, 0, 1, 0.25, 0, 0, 0, 1]
    assert _numbers("v " + lines[2]) == [0.0] * 6
    vx, vy, vz, wx, wy, wz = _numbers("v " + lines[3])
    assert [vx, vy, vz] == _numbers("v " + lines[4]) and vy > 0.2 and wz == 0.0


def test_fields_have_webots_type_codes_and_remove_items(controller_file):
    body = """
root = robot.getRoot().getField("children")
root.importMFNodeFromString(-1, 'DEF L Landmark { translation 0 3 0.75 color 1 0 0 recognitionColors [1 0 0] }')
landmark = robot.getFromDef("L")
print(root.getType() == Field.MF_NODE, root.getType(), landmark.getField("translation").getType(),
      landmark.getField("name").getType(), landmark.getField("recognitionColors").getType())
try:
    landmark.getField("translation").getSFFloat()
except ValueError as e:
    print(e)
camera = robot.getDevice("camera")
camera.recognitionEnable(step)
robot.step(step)
print(camera.getRecognitionNumberOfObjects())
landmark.getField("recognitionColors").removeMF(-1)
robot.step(step)
print(camera.getRecognitionNumberOfObjects(), landmark.getField("recognitionColors").getCount())
root.removeMF(5)
lidar = robot.getDevice("lidar")
lidar.enable(step)
robot.step(step)
print(round(lidar.getRangeImage()[180], 2))
landmark.remove()
robot.step(step)
print(lidar.getRangeImage()[180], robot.getFromDef("L"), root.getCount())
"""
    lines, err = _run(controller_file, body)
    assert lines[0] == "True 25 5 8 23"
    assert lines[1] == "the field translation is an SFVec3f, not an SFFloat"
    assert lines[2:4] == ["1", "0 0"]
    assert abs(float(lines[4]) - 2.75) < 0.03  # the landmark 3 m ahead, radius 0.25
    assert lines[5] == "inf None 1"  # removed: the empty floor has no edge
    assert err == ("Error: wb_supervisor_field_remove_mf() called with an out-of-bound index: 5 "
                   "(should be between -2 and 1).\n")


def test_a_node_imported_beside_a_world_file_is_removed(controller_file):
    body = """
root = robot.getRoot().getField("children")
root.importMFNodeFromString(-1, 'DEF B Obstacle { translation 0 0 0.1 size 0.1 0.1 0.1 }')
print(root.getCount(), robot.getFromDef("B").getParentNode() is robot.getRoot())
robot.getFromDef("B").remove()
print(root.getCount(), robot.getFromDef("B"))
robot.getRoot().remove()
"""
    lines, err = _run(controller_file, body, "--world", "worlds/lab4x4.txt")
    assert lines == ["2 True", "1 None"]
    assert err.splitlines()[-1] == "Error: wb_supervisor_node_remove() called with a NULL or invalid 'node' argument."


def test_world_reload_puts_the_world_back_and_ends_the_run(controller_file):
    body = """
drive(5, 5, 20)
print(robot.getSelf().getPosition()[1] > 0.1)
robot.worldReload()
print(robot.step(step), robot.getSelf().getPosition())
"""
    status, out, err = run_controller(controller_file(HEADER + body))
    assert status == 0, err
    assert out.splitlines()[:2] == ["True", "-1 [0.0, 0.0, 0.0]"]
    assert summary_of(out)["end"] == "controller finished"
