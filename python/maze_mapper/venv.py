"""python3 -m maze_mapper.venv VENV

Puts maze_mapper into a course's virtual environment (python3 -m venv VENV) without building
or downloading anything: it writes VENV's site-packages/maze_mapper.pth, a line naming the
folder this maze_mapper was imported from (the Debian package's /usr/lib/python3/dist-packages,
or a build's build/release/python) and a line naming NumPy's folder when that is another one.
Packages installed in VENV itself come first; the folders named come after them, so the
system's NumPy, pandas and matplotlib (python3-numpy, python3-pandas, python3-matplotlib)
serve the course's library. VENV is created when it does not exist. Run it with the
interpreter that imports maze_mapper (the one the module was built for): VENV's Python must
be the same version. Exit status 0, 1 when VENV's Python cannot import maze_mapper after it,
2 for usage.
"""

import argparse
import os
import subprocess
import sys
import time

PTH_NAME = "maze_mapper.pth"


def _error(message, status=2):
    print(f"error: {message}", file=sys.stderr)
    sys.exit(status)


def _venv_python(venv):
    return os.path.join(venv, "bin", "python")


def _ask(python, code):
    done = subprocess.run([python, "-c", code], capture_output=True, text=True, env=_clean_env())
    if done.returncode != 0:
        _error(f"{python} failed: {done.stderr.strip().splitlines()[-1] if done.stderr.strip() else done.returncode}")
    return done.stdout.strip()


def _clean_env():
    """The environment without PYTHONPATH: what the venv imports is what it holds."""
    return {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}


def folders_to_link():
    """The folders the .pth names: maze_mapper's parent, then NumPy's parent when another."""
    import maze_mapper
    import numpy
    folders = [os.path.dirname(os.path.dirname(os.path.abspath(maze_mapper.__file__)))]
    numpy_folder = os.path.dirname(os.path.dirname(os.path.abspath(numpy.__file__)))
    if numpy_folder not in folders:
        folders.append(numpy_folder)
    return folders


def main(argv=None):
    p = argparse.ArgumentParser(prog="python3 -m maze_mapper.venv",
                                description="Link a course venv to this maze_mapper (a .pth file), offline.")
    p.add_argument("venv", help="the virtual environment's folder (created with python3 -m venv when missing)")
    args = p.parse_args(argv)
    started = time.monotonic()
    python = _venv_python(args.venv)
    if not os.path.exists(args.venv):
        print(f"creating {args.venv} (python3 -m venv)", file=sys.stderr)
        if subprocess.run([sys.executable, "-m", "venv", args.venv], env=_clean_env()).returncode != 0:
            _error(f"cannot create the venv {args.venv}")
    elif not os.access(python, os.X_OK):
        _error(f"{args.venv}: not a virtual environment (no bin/python)")
    version = _ask(python, "import sys; print('%d.%d' % sys.version_info[:2])")
    mine = "%d.%d" % sys.version_info[:2]
    if version != mine:
        _error(f"{args.venv} runs Python {version}; this maze_mapper is built for Python {mine}")
    site = _ask(python, "import sysconfig; print(sysconfig.get_path('purelib'))")
    folders = folders_to_link()
    with open(os.path.join(site, PTH_NAME), "w") as f:
        f.write("".join(folder + "\n" for folder in folders))
    check = subprocess.run([python, "-c", "import maze_mapper, numpy; print(maze_mapper.__file__)"],
                           capture_output=True, text=True, env=_clean_env())
    if check.returncode != 0:
        print(check.stderr, end="", file=sys.stderr)
        _error(f"{args.venv} cannot import maze_mapper through {os.path.join(site, PTH_NAME)}", 1)
    print(f"linked {args.venv} to {', '.join(folders)} ({os.path.join(site, PTH_NAME)}): "
          f"maze_mapper from {check.stdout.strip()} in {time.monotonic() - started:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
