"""Builds the Python module maze_mapper with the project's CMake for `pip install .`
(pyproject.toml): configures a build folder for the running interpreter, builds the module's
target and installs the package (the compiled _native and the Python files) as the wheel's
contents. MAZE_MAPPER_CMAKE_BUILD_DIR reuses a configured build folder (e.g. build/release)
instead of a fresh one under the setuptools build folder."""

import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = os.environ.get("MAZE_MAPPER_CMAKE_BUILD_DIR") or os.path.join(os.path.abspath(self.build_temp), "cmake")
        if not os.path.isfile(os.path.join(build_dir, "CMakeCache.txt")):
            subprocess.run(["cmake", "-S", ROOT, "-B", build_dir, "-G", "Ninja" if shutil.which("ninja") else "Unix Makefiles",
                            "-DCMAKE_BUILD_TYPE=Release", "-DMAZE_MAPPER_PYTHON=ON", "-DMAZE_MAPPER_TESTS=OFF",
                            f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", build_dir, "--target", "maze_mapper_native"], check=True)
        package = os.path.join(build_dir, "python", "maze_mapper")
        target = os.path.join(os.path.abspath(self.build_lib), "maze_mapper")
        shutil.rmtree(target, ignore_errors=True)
        shutil.copytree(package, target, ignore=shutil.ignore_patterns("__pycache__"))


setup(ext_modules=[Extension("maze_mapper._native", sources=[])], cmdclass={"build_ext": CMakeBuild})
