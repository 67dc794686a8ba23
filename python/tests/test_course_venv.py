"""A course's plain virtual environment (python3 -m venv) linked to this maze_mapper with
python3 -m maze_mapper.venv, offline, and the course-shaped Template run from it."""

import os
import subprocess
import sys

import maze_mapper

COURSE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "course_shape")


def without_pythonpath():
    return {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}


def test_a_plain_venv_is_linked_to_the_module_and_runs_the_course_s_controller(tmp_path):
    venv = tmp_path / "fairis-venv"
    done = subprocess.run([sys.executable, "-m", "maze_mapper.venv", str(venv)], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith(f"linked {venv} to {os.path.dirname(os.path.dirname(maze_mapper.__file__))}")
    python = str(venv / "bin" / "python")
    site = subprocess.run([python, "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"],
                          capture_output=True, text=True, env=without_pythonpath()).stdout.strip()
    assert os.path.isfile(os.path.join(site, "maze_mapper.pth"))
    # The course's root on the venv's path, as its FAIRIS_LIBS.pth puts it.
    with open(os.path.join(site, "FAIRIS_LIBS.pth"), "w") as f:
        f.write(COURSE + "\n")
    drive = os.path.join(COURSE, "WebotsSim", "controllers", "drive", "drive.py")
    run = subprocess.run([python, "-m", "maze_mapper.run", drive], capture_output=True, text=True, timeout=120,
                         cwd=tmp_path, env=without_pythonpath())
    assert run.returncode == 0, run.stderr
    assert "drove 1.5 m by" in run.stdout and "end: controller finished" in run.stdout
    # Linking again (the venv there) rewrites the same file.
    again = subprocess.run([sys.executable, "-m", "maze_mapper.venv", str(venv)], capture_output=True, text=True,
                           timeout=60)
    assert again.returncode == 0 and "creating" not in again.stderr


def test_a_folder_that_is_no_venv_is_refused(tmp_path):
    (tmp_path / "notes").mkdir()
    done = subprocess.run([sys.executable, "-m", "maze_mapper.venv", str(tmp_path / "notes")], capture_output=True,
                          text=True, timeout=60)
    assert done.returncode == 2 and done.stderr == f"error: {tmp_path / 'notes'}: not a virtual environment (no bin/python)\n"
