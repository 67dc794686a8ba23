"""Solids with heights in course-shaped worlds: the camera recognises a tall landmark over a
0.5 m wall where Webots' occlusion ray clears the wall and not where the wall meets it, a
landmark lower than the wall stays hidden, getImage() draws what stands above the wall, the
lidar passes over a box lower than its plane, and the empty floor has no wall at its edge."""

import os

from conftest import run_controller, summary_of

COURSE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "course_shape")

# A 0.5 m wall across x = 0 (the course's library imports it as an Obstacle 0.5 m high), a
# red landmark 4.5 m tall at (2, 0.5) behind it and a green one 0.4 m tall at (2, 1.2).
WORLD = """<world>
  <wall x1="0" y1="-0.5" x2="0" y2="1.5"/>
  <landmark x="2" y="0.5" height="4.5" red="1" green="0" blue="0"/>
  <landmark x="2" y="1.2" height="0.4" red="0" green="1" blue="0"/>
  <startPositions><pos x="-3" y="0.5" theta="0"/></startPositions>
  <goal id="0" x="2" y="0"/>
</world>
"""


def run_course_body(tmp_path, body):
    """Runs a course-shaped controller that loads WORLD and then runs body; (status, out, err)."""
    world = tmp_path / "wall_and_landmarks.xml"
    world.write_text(WORLD)
    controller = tmp_path / "heights.py"
    controller.write_text("from fairis_tools.my_robot import MyRobot\nimport math\nrobot = MyRobot()\n"
                          f"robot.load_environment({str(world)!r})\nsup = robot.experiment_supervisor\n" + body)
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (env.get("PYTHONPATH", ""), COURSE) if p)
    return run_controller(controller, "--noise", "0", env=env)


def seen_from(camera_x, y=0.5):
    """A body line printing the colours recognised with the camera (0.09 m ahead of the robot)
    at (camera_x, y) facing east."""
    return (f"robot.teleport_robot({camera_x - 0.09}, {y}, 0, 0)\n"
            f"print('at', {camera_x}, {y}, sorted(o.getColors() for o in robot.camera.getRecognitionObjects()))\n")


def test_a_tall_landmark_behind_a_lower_wall_is_recognised_where_the_line_to_its_centre_clears_the_wall(tmp_path):
    # From x the line to the red centre (2, 0.5, 2.25) passes x = 0 at 0.08 + 2.17 |x| / (|x| + 2) m.
    body = seen_from(-1.0) + seen_from(-0.6) + seen_from(-0.4) + seen_from(-0.1) + seen_from(1.0)
    status, out, err = run_course_body(tmp_path, body)
    assert status == 0, err
    lines = out.splitlines()
    red = [1.0, 0.0, 0.0]
    assert f"at -1.0 0.5 {[red]}" in lines   # 0.80 m above the floor at the wall
    assert f"at -0.6 0.5 {[red]}" in lines   # 0.58 m
    assert "at -0.4 0.5 []" in lines         # 0.44 m: the wall hides its centre
    assert "at -0.1 0.5 []" in lines
    assert f"at 1.0 0.5 {[red]}" in lines    # in front of the wall


def test_a_landmark_lower_than_the_wall_stays_hidden_behind_it(tmp_path):
    body = seen_from(-3.0, 1.2) + seen_from(-1.0, 1.2) + seen_from(1.0, 1.2)
    status, out, err = run_course_body(tmp_path, body)
    assert status == 0, err
    lines = out.splitlines()
    red, green = [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]
    assert f"at -3.0 1.2 {[red]}" in lines  # the red one over the wall; the green one behind it
    assert f"at -1.0 1.2 {[red]}" in lines
    assert f"at 1.0 1.2 {[green]}" in lines  # in front of the wall (the red one is out of view)


def test_the_camera_image_shows_the_landmark_in_its_colour_above_the_wall(tmp_path):
    # From (-3, 0.5) facing east: the wall's top 3 m away at row 112 - f 0.42 / 3 = 74; above
    # it, the red landmark 5 m away (up past the image's top); the wall grey below.
    body = ("robot.teleport_robot(-3.09, 0.5, 0, 0)\nimage = robot.camera.getImage()\nw = robot.camera.getWidth()\n"
            "for row in (40, 70, 100):\n"
            "    print('row', row, [f(image, w, 112, row) for f in (robot.camera.imageGetRed, robot.camera.imageGetGreen,"
            " robot.camera.imageGetBlue)])\n")
    status, out, err = run_course_body(tmp_path, body)
    assert status == 0, err
    lines = out.splitlines()
    assert "row 40 [255, 0, 0]" in lines
    assert "row 70 [255, 0, 0]" in lines
    assert "row 100 [200, 200, 200]" in lines


def test_the_lidar_at_its_height_passes_over_a_box_lower_than_it_and_reads_inf_past_the_floor_edge(tmp_path):
    # On the course's empty floor: a 0.1 m box 1 m ahead (below the lidar's 0.13 m plane), then
    # a 0.2 m one 2 m ahead; with the tall one gone the beam reads inf past the Floor's edge.
    source = ("from controller import Supervisor\nr = Supervisor()\nkids = r.getRoot().getField('children')\n"
              "lidar = r.getDevice('lidar')\nlidar.enable(32)\n"
              "kids.importMFNodeFromString(-1, 'Obstacle { translation 0 1 0.05 size 0.5 0.5 0.1 }')\n"
              "r.step(32)\nprint('low box', lidar.getRangeImage()[180])\n"
              "kids.importMFNodeFromString(-1, 'Obstacle { translation 0 2 0.1 size 0.5 0.5 0.2 }')\n"
              "r.step(32)\nprint('tall box', round(lidar.getRangeImage()[180], 2))\n")
    controller = tmp_path / "boxes.py"
    controller.write_text(source)
    status, out, err = run_controller(controller, "--noise", "0")
    assert status == 0, err
    lines = out.splitlines()
    assert "low box inf" in lines
    assert "tall box 1.75" in lines  # the face at y = 1.75, half a beam off straight ahead


def test_a_robot_driving_off_the_empty_floor_is_reported_once(tmp_path):
    source = ("from controller import Supervisor\nr = Supervisor()\n"
              "r.getSelf().getField('translation').setSFVec3f([8.4, 0, 0])\n"
              "r.getSelf().getField('rotation').setSFRotation([0, 0, 1, 0])\n"
              "left, right = r.getDevice('left motor'), r.getDevice('right motor')\n"
              "for m in (left, right):\n    m.setPosition(float('inf'))\n    m.setVelocity(10)\n"
              "for _ in range(40):\n    r.step(32)\n")
    controller = tmp_path / "off.py"
    controller.write_text(source)
    status, out, err = run_controller(controller, "--noise", "0")
    assert status == 0, err
    assert err.count("warning: the robot left the floor at (8.5") == 1
    assert summary_of(out)["end"] == "controller finished"
