"""The course's code shape runs unchanged: a library that is a Supervisor and builds its world
with node strings, landmarks as solids the lidar and the camera see, Webots' API details."""

import json
import math
import os
import re

from conftest import png_pixels, program, run_controller, summary_of
from maze_mapper import _native

COURSE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "course_shape")
CONTROLLERS = os.path.join(COURSE, "WebotsSim", "controllers")


def run_course(path, *args):
    """Runs a controller with the course-shaped library on the path, as the course's venv puts it."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (env.get("PYTHONPATH", ""), COURSE) if p)
    return run_controller(path, *args, env=env)


def course_controller(controller_file, body):
    """A controller in the course's controllers folder shape: it loads ../../worlds/corners.xml."""
    return controller_file("from fairis_tools.my_robot import MyRobot\nimport math\nrobot = MyRobot()\n"
                           "robot.load_environment(" + repr(os.path.join(COURSE, "WebotsSim", "worlds", "corners.xml"))
                           + ")\nsup = robot.experiment_supervisor\n" + body)


def test_a_course_shaped_controller_loads_its_world_moves_to_a_random_start_and_drives_1_5_m_in_about_1_9_s():
    status, out, err = run_course(os.path.join(CONTROLLERS, "drive", "drive.py"), "--noise", "0")
    assert status == 0, err
    lines = out.splitlines()
    assert "drove 1.5 m by 1.952 s" in lines  # 2 calibration steps, one at rest, 58 at 0.81 m/s
    summary = summary_of(out)
    assert summary["world"] == "the course's empty floor (17 x 17 m)"
    assert summary["imported_nodes"] == "9"  # five walls, four landmarks
    assert summary["end"] == "controller finished"


def test_the_seed_draws_the_random_start_and_the_same_seed_the_same_start():
    starts = set()
    for seed in ("1", "2", "3", "4", "5", "6"):
        status, out, err = run_course(os.path.join(CONTROLLERS, "drive", "drive.py"), "--seed", seed)
        assert status == 0, err
        starts.add(out.splitlines()[0])
    assert len(starts) == 2
    again = [run_course(os.path.join(CONTROLLERS, "drive", "drive.py"), "--seed", "3")[1].splitlines()[0]
             for _ in range(2)]
    assert again[0] == again[1]


def test_the_course_library_on_the_path_is_used_and_the_stand_in_where_it_is_absent(controller_file):
    source = "from fairis_lib.robot_lib import hambot\nprint('fixture', getattr(hambot, 'FROM_THE_FIXTURE', False))\n"
    path = controller_file(source)
    status, out, err = run_course(path)
    assert status == 0, err
    assert "fixture True" in out.splitlines()
    status, out, err = run_controller(path)
    assert status == 0, err
    assert "fixture False" in out.splitlines()


def test_the_landmarks_appear_in_the_first_range_image_where_geometry_puts_them(controller_file):
    # At the origin facing north: the red landmark at (1.5, 1.5), 45 degrees right, its near
    # surface 1.5 * sqrt(2) - 0.25 away; beams 224 and 225 look 44.5 and 45.5 degrees right.
    body = ("robot.teleport_robot(0, 0, 0, math.pi / 2)\nr = robot.get_lidar_range_image()\n"
            "print('right45', round(r[224], 2), round(r[225], 2))\n"
            "print('left45', round(r[134], 2), round(r[135], 2))\n")
    status, out, err = run_course(course_controller(controller_file, body), "--noise", "0")
    assert status == 0, err
    expected = round(1.5 * math.sqrt(2) - 0.25, 2)
    right = out.splitlines()[0].split()
    assert right[0] == "right45" and all(abs(float(v) - expected) <= 0.011 for v in right[1:])
    left = out.splitlines()[1].split()  # the green one at (-1.5, 1.5), 45 degrees left, the wall x = 0 beside the ray
    assert left[0] == "left45" and all(abs(float(v) - expected) <= 0.011 for v in left[1:])


def test_the_robot_collides_with_a_landmark_beyond_the_maze_edge_of_its_walls(controller_file):
    # The yellow landmark stands at (2.5, -2.5), outside the walls: a robot teleported beside
    # it, driving into it, stops with its body (0.09 m) against the cylinder (0.25 m).
    body = ("robot.teleport_robot(3.5, -2.5, 0, math.pi)\n"
            "for _ in range(100):\n    robot.set_velocities(10, 10)\n    sup.step(robot.timestep)\n"
            "x, y, z = robot.gps.getValues()\nprint('stopped', round(x, 3), round(y, 3))\n")
    status, out, err = run_course(course_controller(controller_file, body), "--noise", "0")
    assert status == 0, err
    assert "stopped 2.84 -2.5" in out.splitlines()
    assert summary_of(out)["collisions"] == "1"  # pressing on against it is the same collision


def test_recognition_colours_and_distances_match_a_hand_worked_case_and_occluded_ones_are_absent(controller_file):
    # At (-1.5, -0.25) facing north: the green landmark at (-1.5, 1.5) straight ahead, its centre
    # 1.75 - 0.09 m from the camera (0.09 m ahead, 0.08 m up) and 0.75 - 0.08 m above it; the
    # red one at (1.5, 1.5) is out of the field of view; the blue one is behind.
    body = ("robot.teleport_robot(-1.5, -0.25, 0, math.pi / 2)\n"
            "for o in robot.camera.getRecognitionObjects():\n"
            "    print('seen', o.getId() > 0, [round(v, 3) for v in o.getPosition()], o.getColors(),\n"
            "          [round(v, 3) for v in o.getSize()], o.getPositionOnImage(), o.getSizeOnImage(), repr(o.getModel()))\n"
            "robot.teleport_robot(0.5, 1.0, 0, math.pi)\n"  # west, the wall x = 0 between it and green
            "print('behind the wall', len(robot.camera.getRecognitionObjects()))\n"
            "robot.teleport_robot(-0.5, -0.5, 0, 3 * math.pi / 4)\n"  # towards green, in the open
            "print('in the open', [o.getColors() for o in robot.camera.getRecognitionObjects()])\n")
    status, out, err = run_course(course_controller(controller_file, body), "--noise", "0")
    assert status == 0, err
    lines = out.splitlines()
    f = 112 / math.tan(0.7854 / 2)
    top = int(112 - f * (1.5 - 0.08) / 1.66)
    v = (max(top, 0) + int(112 + f * 0.08 / 1.66)) // 2
    seen = [line for line in lines if line.startswith("seen")]
    assert len(seen) == 1
    assert seen[0].startswith("seen True [1.66, 0.0, 0.67] [0.0, 1.0, 0.0] [0.5, 1.5] [112, ")
    assert f"[112, {v}]" in seen[0] or f"[112, {v + 1}]" in seen[0]
    assert "behind the wall 0" in lines
    assert "in the open [[0.0, 1.0, 0.0]]" in lines


def test_a_node_type_other_than_obstacle_and_landmark_is_refused_naming_it(controller_file):
    body = "robot.children_field.importMFNodeFromString(-1, 'DEF B Solid { translation 0 0 0 }')\n"
    status, out, err = run_course(course_controller(controller_file, body))
    assert status == 1
    assert "node type Solid is not modelled by the embedded simulator (it builds Obstacle and Landmark nodes)" in err


def test_a_supervisor_import_of_a_solid_larger_than_any_world_is_refused_at_once(controller_file, tmp_path):
    source = ("from controller import Supervisor\nrobot = Supervisor()\n"
              "robot.getRoot().getField('children').importMFNodeFromString(-1, 'Landmark { size 1 1e300 1 }')\n")
    status, stdout, err = run_controller(controller_file(source), "--out", str(tmp_path / "out"), timeout=60)
    assert status == 1
    assert "Landmark.size: 1e+300 m is beyond any world (at most 1000 m a side)" in err
    assert summary_of(stdout)["end"] == "controller failed"
    assert (tmp_path / "out" / "truth.png").exists()  # the floor drawn as it stands, at once


def test_get_from_def_finds_imported_nodes_and_the_robot_node_reads_its_pose(controller_file):
    body = ("print('def', sup.getFromDef('Obstacle_4').getTypeName(), sup.getFromDef('Obstacle'),\n"
            "      [round(v, 2) for v in sup.getFromDef('Landmark_0').getPosition()])\n"
            "robot.teleport_robot(1, -1, 0, 0)\n"
            "print('self', [round(v, 3) for v in robot.robot_translation_field.getSFVec3f()],"
            " [round(v, 3) for v in sup.getSelf().getOrientation()[:2]])\n"
            "sup.simulationReset()\nsup.step(robot.timestep)\n"
            "print('reset', sup.getFromDef('Obstacle_4'), [round(v, 3) for v in robot.gps.getValues()])\n")
    status, out, err = run_course(course_controller(controller_file, body), "--noise", "0")
    assert status == 0, err
    lines = out.splitlines()
    assert "def Obstacle None [1.5, 1.5, 0.75]" in lines
    assert "self [1.0, -1.0, 0.0] [1.0, -0.0]" in lines
    assert "reset None [0.0, 0.0, 0.0]" in lines


def test_webots_device_methods_the_course_uses_exist_as_webots_defines_them(controller_file):
    body = ("robot.teleport_robot(0, -1, 0.02, 0)\n"
            "r = robot.lidar.getRangeImage()\nr[0] = 7.0\ncopy = list(r)\n"
            "print('list', type(r).__mro__[1].__name__, json.dumps(r[:1]), copy[0], robot.lidar.getLayerRangeImage(0)[180] == r[180])\n"
            "cloud = robot.lidar.getPointCloud()\n"
            "print('cloud', len(cloud), round(cloud[180].x, 2), round(cloud[180].y, 2), cloud[180].layer_id)\n"
            "print('gps z', round(robot.gps.getValues()[2], 3))\n"
            "robot.set_velocities(10, 10)\nsup.step(robot.timestep)\n"
            "print('speed', round(robot.gps.getSpeed(), 3))\n"
            "imu = sup.getDevice('imu')\nimu.enable(robot.timestep)\n"
            "print('quaternion', [round(v, 3) for v in imu.getQuaternion()])\n"
            "robot.left_motor.setAcceleration(5)\nprint('acceleration', robot.left_motor.getAcceleration())\n"
            "pc = sup.getDevice('Place Cell Display')\npc.setOpacity(1.0)\n"
            "print('displays', sup.getDevice('User Display').getWidth(), pc.getWidth(), pc.getHeight())\n")
    source = course_controller(controller_file, body).read_text().replace("import math", "import math, json")
    status, out, err = run_course(controller_file(source, "device_check.py"), "--noise", "0")
    assert status == 0, err
    lines = out.splitlines()
    assert "list list [7.0] 7.0 True" in lines
    assert "cloud 360 1.99 -0.02 0" in lines  # beam 180 looks 0.5 degree right, to the wall face at x = 1.994
    assert "gps z 0.02" in lines
    assert "speed 0.45" in lines  # 10 rad/s x 0.045 m
    assert "quaternion [0.0, 0.0, 0.0, 1.0]" in lines
    assert "acceleration 5.0" in lines
    assert "displays 64 800 800" in lines  # the earlier course library opens 'Place Cell Display'


def test_the_camera_image_shows_a_landmark_in_its_colour(controller_file):
    body = ("robot.teleport_robot(-1.5, -0.25, 0, math.pi / 2)\nimage = robot.camera.getImage()\n"
            "w = robot.camera.getWidth()\n"
            "print('centre', len(image), robot.camera.imageGetRed(image, w, 112, 100),"
            " robot.camera.imageGetGreen(image, w, 112, 100), robot.camera.imageGetBlue(image, w, 112, 100))\n")
    status, out, err = run_course(course_controller(controller_file, body), "--noise", "0")
    assert status == 0, err
    assert "centre 200704 0 255 0" in out.splitlines()


def test_a_spinning_controller_ends_cleanly_at_the_time_limit(controller_file):
    path = controller_file("from controller import Robot\nr = Robot()\nwhile True:\n    r.step(32)\n")
    status, out, err = run_controller(path, "--time-limit", "2")
    assert status == 0, err
    summary = summary_of(out)
    assert summary["end"] == "time limit (2 s of simulated time)" and summary["sim_time_s"] == "2.016"


def test_a_controller_that_leaves_its_loop_at_the_time_limit_ends_there_as_every_run_does(controller_file):
    path = controller_file("from controller import Robot\nr = Robot()\nwhile r.step(32) != -1:\n    pass\n")
    status, out, err = run_controller(path, "--time-limit", "2")
    assert status == 0, err
    summary = summary_of(out)
    assert summary["end"] == "time limit (2 s of simulated time)" and summary["steps"] == "63"
    status, out, err = run_controller(path, "--max-steps", "10")
    assert status == 0, err
    assert summary_of(out)["end"] == "max steps"


def test_the_wall_clock_limit_ends_a_long_run(controller_file):
    path = controller_file("from controller import Robot\nr = Robot()\nwhile r.step(32) != -1:\n    pass\n")
    status, out, err = run_controller(path, "--wall-limit", "0.3", "--max-steps", "100000000")
    assert status == 0, err
    assert summary_of(out)["end"] == "wall-clock limit"


def test_an_arena_world_runs_in_the_python_runner(controller_file):
    source = ("from controller import Robot\nr = Robot()\nl = r.getDevice('lidar')\nl.enable(32)\nr.step(32)\n"
              "print('ranges', sum(1 for v in l.getRangeImage() if v < 20))\n")
    for world in ("worlds/thick_arena.xml", "worlds/obstacle_field.room"):
        status, out, err = run_controller(controller_file(source), "--world", world)
        assert status == 0, err
        summary = summary_of(out)
        assert summary["world"] == world and "arena" in summary
        assert int(out.splitlines()[0].split()[1]) > 180  # walls and obstacles within the lidar's 12 m


def test_with_a_world_file_the_nodes_a_controller_imports_add_no_solid(controller_file):
    body = "print('found', sup.getFromDef('Landmark_0') is not None, len(robot.camera.getRecognitionObjects()))\n"
    status, out, err = run_course(course_controller(controller_file, body), "--world", "worlds/lab4x4.txt")
    assert status == 0, err
    assert "found True 0" in out.splitlines()
    assert err == ("warning: the world is worlds/lab4x4.txt (--world): the nodes the controller imports "
                   "add no solid\n")


def test_with_a_world_file_its_landmarks_are_nodes_the_camera_recognises_in_their_colour(controller_file):
    # course_arena5_starts.xml: a 5 x 5 m frame, its four landmarks on the corners. From its
    # third start, (0, -2) facing north, the two northern corners (blue at (2.5, 2.5), yellow
    # at (-2.5, 2.5)) stand 29 degrees off the axis: outside the 45 degree field of view.
    # Turned towards the north-west corner, the yellow one is recognised.
    body = ("children = sup.getRoot().getField('children')\n"
            "print('landmarks', sum(children.getMFNode(i).getTypeName() == 'Landmark' for i in range(children.getCount())))\n"
            "robot.teleport_robot(0, -2, 0, math.atan2(4.5, -2.5))\n"
            "print('seen', [o.getColors() for o in robot.camera.getRecognitionObjects()])\n")
    controller = controller_file("from fairis_tools.my_robot import MyRobot\nimport math\nrobot = MyRobot()\n"
                                 "sup = robot.experiment_supervisor\n" + body)
    status, out, err = run_course(controller, "--world", "tests/data/worlds/course_arena5_starts.xml",
                                  "--start", "pos:3", "--noise", "0")
    assert status == 0, err
    lines = out.splitlines()
    assert "landmarks 4" in lines
    assert "seen [[1.0, 1.0, 0.0]]" in lines


def test_every_world_of_the_repository_runs_in_the_python_runner_mazes_and_arenas_alike(controller_file):
    from conftest import WORLDS
    path = controller_file("from controller import Robot\nr = Robot()\nr.step(32)\n")
    fixtures = os.path.join(os.path.dirname(WORLDS), "tests", "data", "worlds")
    names = [f"worlds/{n}" for n in sorted(os.listdir(WORLDS)) if not n.endswith(".md")]
    names += [f"tests/data/worlds/{n}" for n in sorted(os.listdir(fixtures)) if n.startswith("course_")]
    assert len(names) >= 15
    for name in names:
        status, out, err = run_controller(path, "--world", name)
        assert status == 0, (name, err)
        assert summary_of(out)["end"] == "controller finished", name


def test_start_chooses_a_maze_worlds_start_position_as_run_does(controller_file):
    source = ("from controller import Robot\nr = Robot()\ng = r.getDevice('gps')\ng.enable(32)\nr.step(32)\n"
              "print('at', [round(v, 2) for v in g.getValues()[:2]])\n")
    path = controller_file(source)
    world = "tests/data/worlds/course_arena5_starts.xml"
    seen = {}
    for start in ("pos:1", "pos:2", "pos:7"):
        status, out, err = run_controller(path, "--world", world, "--start", start)
        assert status == 0, err
        seen[start] = out.splitlines()[0]
    assert seen == {"pos:1": "at [-2.0, -2.0]", "pos:2": "at [-1.0, -2.0]", "pos:7": "at [-1.0, -1.0]"}
    status, out, err = run_controller(path, "--world", world, "--start", "pos:26")
    assert status == 2 and err.startswith("error: --start pos:26")
    status, out, err = run_controller(path, "--start", "random")
    assert status == 2
    assert err == "error: --start needs --world (on the course's empty floor the controller chooses its start)\n"


def test_a_supervisor_reset_puts_time_back_at_0_at_the_end_of_the_next_step_and_the_run_counts_its_whole_time(
        controller_file):
    body = ("robot.move_to_start()\n"
            "for _ in range(10):\n    sup.step(robot.timestep)\n"
            "robot.set_velocities(10, 10)\n"
            "for _ in range(10):\n    sup.step(robot.timestep)\n"
            "print('before', round(sup.getTime(), 3), robot.left_encoder.getValue() > 1)\n"
            "sup.simulationReset()\n"
            "print('requested', round(sup.getTime(), 3), sup.getFromDef('Obstacle_4') is not None)\n"
            "sup.step(robot.timestep)\n"
            "print('after', round(sup.getTime(), 3), sup.getFromDef('Obstacle_4'), robot.left_encoder.getValue(),\n"
            "      [round(v, 3) for v in robot.gps.getValues()])\n")
    status, out, err = run_course(course_controller(controller_file, body), "--noise", "0")
    assert status == 0, err
    lines = out.splitlines()
    assert "before 0.704 True" in lines  # 2 calibration steps, 20 of the loops
    assert "requested 0.704 True" in lines
    assert "after 0.0 None 0.0 [0.0, 0.0, 0.0]" in lines
    assert summary_of(out)["sim_time_s"] == "0.736"


def test_the_robot_starts_exactly_at_the_file_s_start_on_a_world_read_on_half_metre_cells(controller_file):
    source = ("from controller import Robot\nrobot = Robot()\ngps = robot.getDevice('gps')\ngps.enable(32)\n"
              "robot.step(32)\nprint('gps', [round(v, 4) for v in gps.getValues()[:2]])\n")
    lattice = os.path.join(COURSE, "WebotsSim", "worlds", "lattice_maze.xml")
    for start, where in (("pos:1", "[-0.5, -0.5]"), ("pos:2", "[0.75, -0.75]")):
        status, out, err = run_controller(controller_file(source), "--world", lattice, "--start", start,
                                          "--noise", "0")
        assert status == 0, err
        assert f"gps {where}" in out.splitlines()
        assert summary_of(out)["size"] == "4x4"  # 0.5 m cells: the start is a lattice node, not a cell centre


def replay_data_of(page):
    """The data block of a replay.html."""
    start = page.index('id="replay-data">') + len('id="replay-data">')
    return json.loads(page[start:page.index("</script>", start)].replace("<\\/", "</"))


def test_out_on_the_empty_floor_draws_the_world_the_supervisor_built_its_landmarks_in_their_colour(tmp_path):
    out = tmp_path / "out"
    status, stdout, err = run_course(os.path.join(CONTROLLERS, "drive", "drive.py"), "--noise", "0", "--out", str(out))
    assert status == 0, err
    assert sorted(os.listdir(out)) == ["controller.log", "controller_lines.csv", "replay.html", "summary.json", "trace.csv", "truth.png"]
    assert f"wrote {out}/: truth.png, summary.json, trace.csv, replay.html, controller.log, controller_lines.csv" in err.splitlines()
    summary = json.loads((out / "summary.json").read_text())
    assert summary["world"] == "the course's empty floor (17 x 17 m)" and summary["end"] == "controller finished"
    assert summary["steps"] == int(summary_of(stdout)["steps"]) > 0
    # The replay in metres over the 17 x 17 m floor, the four landmarks corners.xml's library
    # imported at their places (mm from the floor's corner, radius 0.25 m) in their colours.
    data = replay_data_of((out / "replay.html").read_text())
    assert data["units"] == "metres" and data["boundary_mm"] == []  # the floor's edge is no wall
    corner = data["origin"]  # the shown part's south-west corner (the crop: test below)

    def mm(x, y):
        return [round((x - corner[0]) * 1000), round((y - corner[1]) * 1000)]
    marks = [tuple(data["landmarks"][i:i + 6]) for i in range(0, len(data["landmarks"]), 6)]
    assert sorted(marks) == sorted([(*mm(1.5, 1.5), 250, 255, 0, 0), (*mm(-1.5, 1.5), 250, 0, 255, 0),
                                    (*mm(-1.5, -1.5), 250, 0, 0, 255), (*mm(2.5, -2.5), 250, 255, 255, 0)])
    # The library's random start is a teleport after the first step: the replay starts there,
    # the step before it left out (corners.xml's (-0.75, -1)).
    assert len(data["path"]["steps"]) == summary["steps"] - 1
    assert data["path"]["placed"] == [] and data["path"]["start"] == 0
    assert data["path"]["xy_mm"][0:2] == mm(-0.75, -1.0)
    # truth.png: the imported walls solid, the landmarks in their colours, the robot's path.
    colours = set(map(tuple, png_pixels((out / "truth.png").read_bytes()).reshape(-1, 3).tolist()))
    for colour in [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 0)]:
        assert colour in colours, colour


def colour_centre(pixels, colour):
    """The mean (x, y) of the pixels in colour, or None."""
    import numpy as np
    ys, xs = np.nonzero(np.all(pixels == colour, axis=2))
    return (xs.mean(), ys.mean()) if len(xs) else None


def test_out_on_the_empty_floor_crops_the_pictures_to_the_world_built_and_the_path_with_start_goal_and_robot(tmp_path):
    out = tmp_path / "out"
    status, stdout, err = run_course(os.path.join(CONTROLLERS, "drive", "drive.py"), "--noise", "0", "--out", str(out))
    assert status == 0, err
    # The replay shows the box round corners.xml's walls (-2 to 2 m), its landmarks (the yellow
    # one at (2.5, -2.5), 0.25 m round), its goal and the path, grown by half a metre (a tenth of
    # the 4.8 m box is less): not the 17 x 17 m floor.
    data = replay_data_of((out / "replay.html").read_text())
    x0, y0 = data["origin"]
    x1, y1 = x0 + data["width"] * data["cell_size_m"], y0 + data["height"] * data["cell_size_m"]
    assert x0 <= -2.5 and y0 <= -3.25 and x1 >= 3.25 and y1 >= 2.5
    assert x0 >= -2.6 and y0 >= -3.35 and x1 <= 3.35 and y1 <= 2.6
    # The goal the course's library read with its world, (1.5, 0), in mm from the shown corner.
    assert data["goals"] == [round((1.5 - x0) * 1000), round((0.0 - y0) * 1000)]
    assert data["mark_rule"] == [0.6, 14, 40]
    # truth.png on the same box: the red (1.5, 1.5) and blue (-1.5, -1.5) landmarks 3 m apart
    # span about half the map (600 px over some 6 m), where on the whole floor they spanned a
    # sixth; the start, the goal and the robot's end marked where they are.
    pixels = png_pixels((out / "truth.png").read_bytes())
    red, blue = colour_centre(pixels, (255, 0, 0)), colour_centre(pixels, (0, 0, 255))
    px_per_m = (red[0] - blue[0]) / 3.0
    assert px_per_m > 80
    assert abs((blue[1] - red[1]) / 3.0 - px_per_m) < 1

    def at(x, y):
        return round(red[0] + (x - 1.5) * px_per_m), round(red[1] - (y - 1.5) * px_per_m)
    final = json.loads((out / "summary.json").read_text())["final_pose"]

    def near(where, half):
        x, y = at(*where)
        return pixels[y - half:y + half + 1, x - half:x + half + 1].reshape(-1, 3).tolist()
    assert [20, 170, 40] in near((-0.75, -1.0), 2)  # the start
    assert [30, 90, 220] in near((final["x_m"], final["y_m"]), 5)  # the robot (a white tick its heading)
    assert [240, 170, 0] in near((1.5, 0.0), 20) and [240, 170, 0] not in near((-1.5, 0.0), 20)  # the goal


def test_out_on_the_empty_floor_with_a_kept_map_writes_its_map_png(controller_file, tmp_path):
    out = tmp_path / "out"
    body = ("import numpy as np\nimport maze_mapper\ngrid = np.zeros((34, 34))\n"
            "maze_mapper.keep_map(grid, origin=(-8.5, -8.5), cell_size_m=0.5)\n"
            "for k in range(10):\n    sup.step(robot.timestep)\n    grid[k, 5] = 2.0\n")
    status, stdout, err = run_course(course_controller(controller_file, body), "--out", str(out))
    assert status == 0, err
    assert sorted(os.listdir(out)) == ["controller.log", "controller_lines.csv", "map.png", "replay.html", "summary.json", "trace.csv", "truth.png"]
    assert summary_of(stdout)["map"] == "kept, 34 x 34 cells of 0.5 m from (-8.50, -8.50)"
    data = replay_data_of((out / "replay.html").read_text())
    assert (data["width"], data["height"], data["cell_size_m"]) == (34, 34, 0.5)
    assert any(len(c) > 0 for c in data["frames"]["changes"])



def test_the_runner_help_words_each_shared_option_as_run_room_and_mms_do():
    def words(text):
        return " ".join(text.split())

    pages = {"runner": run_controller("--help")[1]}
    for command in ("run", "room", "mms"):
        pages[command] = program(command, "--help")[1]
    for flag in ("--robot", "--seed", "--noise", "--max-steps", "--time-limit", "--out"):
        line = _native.option_help(flag)
        help_words = words(line.split(": ", 1)[1] if re.match(r"[A-Z][A-Za-z0-9 .]*: ", line) else line)
        for name, page in pages.items():
            assert help_words in words(page), (name, flag, help_words)
