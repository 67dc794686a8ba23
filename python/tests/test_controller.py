"""Webots' Python controller API over the embedded simulator, run by maze_mapper.run."""

import math

import pytest

from conftest import run_controller, summary_of

DEVICES = '''
import math
from controller import Robot, Lidar, Motor, PositionSensor, InertialUnit, GPS

robot = Robot()
ts = int(robot.getBasicTimeStep())
lidar = robot.getDevice("lidar")
left, right = robot.getDevice("left motor"), robot.getDevice("right motor")
enc = robot.getDevice("left wheel encoder")
imu, gps = robot.getDevice("imu"), robot.getDevice("gps")
assert isinstance(lidar, Lidar) and isinstance(left, Motor) and isinstance(enc, PositionSensor)
assert isinstance(imu, InertialUnit) and isinstance(gps, GPS)
for s in (lidar, enc, imu, gps):
    s.enable(ts)
assert lidar.getSamplingPeriod() == ts
left.setPosition(math.inf); right.setPosition(math.inf)  # as in Webots: at max velocity until set
left.setVelocity(0.0); right.setVelocity(0.0)
robot.step(ts)
print("names", robot.getName(), robot.getNumberOfDevices(), lidar.getName())
print("lidar", lidar.getHorizontalResolution(), lidar.getNumberOfLayers(), round(lidar.getFov(), 6))
x, y, z = gps.getValues()
print("start", round(x, 3), round(y, 3), round(math.degrees(imu.getRollPitchYaw()[2])))
left.setVelocity(5.0); right.setVelocity(5.0)
for _ in range(20):
    robot.step(ts)
print("moved", gps.getValues()[1] > y + 0.1, enc.getValue() > 3.0, round(robot.getTime(), 3))
image = lidar.getRangeImage()
import numpy as np
a = np.asarray(image)
print("image", len(image), type(image[0]).__name__, a.dtype, a is image.array, min(image) > 0,
      image[178:181] == [float(r) for r in a[178:181]], len(image[0:2] + image[358:]), image.index(image[90]) <= 90)
'''


def test_a_webots_controller_runs_unchanged(controller_file):
    status, out, err = run_controller(controller_file(DEVICES), "--world", "worlds/lab4x4.txt")
    assert status == 0, err
    lines = out.splitlines()
    assert "names hambot 10 lidar" in lines  # with the course HamBot's camera and two displays
    assert "lidar 360 1 6.283185" in lines
    assert "start 0.5 0.5 90" in lines
    assert "moved True True 0.672" in lines
    assert "image 360 float float32 True True True 4 True" in lines
    summary = summary_of(out)
    assert summary["end"] == "controller finished" and summary["steps"] == "21"
    assert summary["grid"].startswith("none kept")


def test_a_missing_device_gets_webots_message_and_a_non_zero_exit(controller_file):
    source = 'from controller import Robot\nrobot = Robot()\nspeaker = robot.getDevice("speaker")\nspeaker.enable(32)\n'
    status, out, err = run_controller(controller_file(source), "--world", "worlds/lab4x4.txt")
    assert status == 1
    assert err.splitlines()[0] == 'Device "speaker" was not found on robot "hambot"'
    assert "AttributeError: 'NoneType' object has no attribute 'enable'" in err
    assert summary_of(out)["end"] == "controller failed"


def test_a_device_of_another_robot(controller_file):
    source = ('from controller import Robot\nr = Robot()\nb = r.getDevice("bumper front")\nb.enable(32)\n'
              'r.step(32)\nprint("pressed", b.getValue())\nprint(r.getDevice("lidar"))\n')
    status, out, err = run_controller(controller_file(source), "--world", "worlds/lab4x4.txt",
                                      "--robot", "bumper-depth")
    assert status == 0, err
    assert "pressed 0.0" in out.splitlines() and "None" in out.splitlines()
    assert err == 'Device "lidar" was not found on robot "bumper-depth"\n'


def test_what_webots_has_and_we_do_not_is_named(controller_file):
    status, _, err = run_controller(controller_file("from controller import Speaker\n"),
                                    "--world", "worlds/lab4x4.txt")
    assert status == 1
    assert ("ImportError: maze_mapper's controller module has no Speaker: the embedded simulator offers "
            "Robot, Supervisor, Keyboard, Lidar, Motor, PositionSensor, InertialUnit, GPS, DistanceSensor, "
            "TouchSensor, Camera, Display, Compass, Accelerometer, Gyro, LED") in err


def test_step_returns_minus_one_when_the_simulation_ends(controller_file):
    source = ('import sys\nfrom controller import Robot\nr = Robot()\nn = 0\nwhile r.step(32) != -1:\n    n += 1\n'
              'print("steps", n, sys.argv[1:])\nwhile True:\n    r.step(32)\n')
    status, out, err = run_controller(controller_file(source), "--world", "worlds/lab4x4.txt",
                                      "--max-steps", "50", "--", "--size", "4x4")
    assert status == 0, err
    assert "steps 49 ['--size', '4x4']" in out.splitlines()
    summary = summary_of(out)
    assert summary["end"] == "max steps" and summary["steps"] == "50"


@pytest.mark.parametrize("runner_options", [[], ["--max-steps", "20"]])
def test_everything_after_the_first_double_dash_is_the_controllers(controller_file, runner_options):
    source = 'import sys\nprint("args", sys.argv[1:])\n'
    status, out, err = run_controller(controller_file(source), *runner_options, "--", "a", "--b", "--", "c")
    assert status == 0, err
    assert "args ['a', '--b', '--', 'c']" in out.splitlines()


def test_a_runner_option_after_the_controllers_arguments_is_refused_with_where_they_go(controller_file):
    status, _, err = run_controller(controller_file("print('ran')\n"), "--bogus")
    assert status == 2
    assert err.strip() == "error: unrecognized arguments: --bogus (controller arguments follow --)"


def test_the_truth_is_not_in_the_controllers_reach(controller_file):
    source = ('import controller, maze_mapper\nfrom controller import Robot\nr = Robot()\n'
              'print(sorted(n for n in dir(r) if not n.startswith("__")))\n'
              'print(maze_mapper._kept)\n')
    status, out, err = run_controller(controller_file(source), "--world", "worlds/lab4x4.txt")
    assert status == 0, err
    names = out.splitlines()[0]
    for word in ("world", "maze", "truth", "pose", "simulation"):
        assert word not in names


def test_only_one_robot(controller_file):
    source = 'from controller import Robot\nRobot()\nRobot()\n'
    status, _, err = run_controller(controller_file(source), "--world", "worlds/lab4x4.txt")
    assert status == 0
    assert err == "Error: only one Robot instance can be created per controller process.\n"


ARENA = '''<world>
  <wall x1="-1" y1="-1" x2="1" y2="-1"/><wall x1="1" y1="-1" x2="1" y2="1"/>
  <wall x1="1" y1="1" x2="-1" y2="1"/><wall x1="-1" y1="1" x2="-1" y2="-1"/>
  <startPositions><pos x="0.25" y="0" theta="1.5707963267948966"/></startPositions>
</world>
'''


def test_the_course_robots_helpers(controller_file):
    controller_file(ARENA, "Lab1_Task1.xml")
    source = '''
from fairis_lib.robot_lib.hambot import HamBot
robot = HamBot()
robot.load_environment("Lab1_Task1.xml")
robot.move_to_start()
print("compass", robot.get_compass_reading(), robot.get_encoder_readings())
robot.set_left_motor_velocity(-30)
robot.set_right_motor_velocity(30, suppress=True)
for _ in range(10):
    robot.step(robot.timestep)
print("turned", robot.get_compass_reading() > 90, robot.get_left_motor_encoder_reading() < 0)
robot.stop()
print("ranges", len(robot.get_lidar_range_image()), robot.max_motor_velocity, robot.wheel_radius, robot.axel_length)
print("walls all round", max(robot.get_lidar_range_image()) < 1.6)
'''
    status, out, err = run_controller(controller_file(source), "--noise", "0")
    assert status == 0, err
    lines = out.splitlines()
    assert "compass 90 [0.0, 0.0]" in lines  # the file's start, read from the controller's folder
    assert "turned True True" in lines
    assert "ranges 360 20.0 0.045 0.184" in lines
    assert "walls all round True" in lines  # the file's walls as solids: the farthest corner is 1.6 m away
    assert err == "motor velocity -30 is beyond the maximum: set to -20.0\n"


def test_bad_runner_input_is_one_error_line(controller_file, tmp_path):
    path = controller_file("print('never')\n")
    for args, message in [
        (["--world", "no/such.txt"], "error: cannot read no/such.txt: No such file or directory"),
        (["--world", "worlds/lab4x4.txt", "--robot", "rover"], "error: "),
        (["--world", "worlds/lab4x4.txt", "--max-steps", "0"], "error: --max-steps must be at least 1 (got 0)"),
        (["--world", "worlds/lab4x4.txt", "--frobnicate"], "error: unrecognized arguments: --frobnicate"),
    ]:
        status, out, err = run_controller(path, *args)
        assert status == 2, args
        assert out == "" and len(err.splitlines()) == 1 and err.startswith(message), err
    status, _, err = run_controller(tmp_path / "missing.py", "--world", "worlds/lab4x4.txt")
    assert status == 2 and err.startswith("error: cannot read ")
