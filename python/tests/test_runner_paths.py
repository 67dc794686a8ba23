"""The paths a user gives python3 -m maze_mapper.run are the user's: taken from the folder the
runner was started in, though the controller runs in its own folder (as Webots runs it)."""

import os
import shutil

from conftest import EXAMPLES, run_controller, summary_of, temporaries_under, world

DRIVE = ("from controller import Robot\nimport math\nrobot = Robot()\n"
         "left, right = robot.getDevice('left motor'), robot.getDevice('right motor')\n"
         "for m in (left, right):\n    m.setPosition(math.inf)\n    m.setVelocity(5.0)\n"
         "for _ in range(40):\n    robot.step(32)\n")


def controller_elsewhere(tmp_path, source=DRIVE):
    """(the folder the runner starts in, the controller's path in a folder of its own)."""
    (tmp_path / "controllers" / "drive").mkdir(parents=True)
    (tmp_path / "work").mkdir()
    path = tmp_path / "controllers" / "drive" / "drive.py"
    path.write_text(source)
    return tmp_path / "work", path


def test_a_relative_out_is_written_where_the_runner_was_started_not_in_the_controllers_folder(tmp_path):
    work, controller = controller_elsewhere(tmp_path)
    (controller.parent / "out").mkdir()  # a folder of that name beside the controller is not the user's
    status, stdout, err = run_controller(controller, "--world", world("lab4x4.txt"), "--out", "out", cwd=work)
    assert status == 0, err
    assert summary_of(stdout)["end"] == "controller finished"
    assert sorted(os.listdir(work / "out")) == ["controller.log", "controller_lines.csv", "replay.html", "summary.json", "trace.csv", "truth.png"]
    assert len((work / "out" / "trace.csv").read_text().splitlines()) == 41
    assert os.listdir(controller.parent / "out") == []
    assert temporaries_under(tmp_path) == []


def test_a_relative_world_and_robot_file_are_read_where_the_runner_was_started(tmp_path):
    work, controller = controller_elsewhere(tmp_path)
    shutil.copy(world("lab4x4.txt"), work / "lab.txt")
    status, stdout, err = run_controller(controller, "--world", "lab.txt", "--out", "runs/one", cwd=work)
    assert status == 0, err
    assert summary_of(stdout)["world"] == "lab.txt"
    assert (work / "runs" / "one" / "summary.json").exists()


def test_the_readme_hand_in_command_writes_the_grid_in_the_folder_it_names_from_where_it_was_typed(tmp_path):
    (tmp_path / "examples").mkdir()
    shutil.copy(os.path.join(EXAMPLES, "lab_mapper.py"), tmp_path / "examples" / "lab_mapper.py")
    (tmp_path / "submissions").mkdir()
    status, stdout, err = run_controller("examples/lab_mapper.py", "--world", world("lab4x4.txt"), "--",
                                         "--size", "4x4", "--save-grid", "submissions/me.npz", cwd=tmp_path)
    assert status == 0, err
    assert (tmp_path / "submissions" / "me.npz").exists()
    assert not (tmp_path / "examples" / "submissions").exists()


def test_a_hand_in_path_whose_folder_is_missing_is_refused_before_the_run(tmp_path):
    (tmp_path / "examples").mkdir()
    shutil.copy(os.path.join(EXAMPLES, "lab_mapper.py"), tmp_path / "examples" / "lab_mapper.py")
    status, stdout, err = run_controller("examples/lab_mapper.py", "--world", world("lab4x4.txt"), "--",
                                         "--size", "4x4", "--save-grid", "nowhere/me.npz", cwd=tmp_path)
    assert status == 2
    assert f"--save-grid {tmp_path}/nowhere/me.npz: no folder {tmp_path}/nowhere to write it in" in err
    assert summary_of(stdout)["steps"] == "0"
