"""The orikin package's extension, built by the project's CMake (python/CMakeLists.txt).

setuptools takes the metadata from pyproject.toml; this file only says how orikin._orikin is
made: configure the repository (one directory up) into the build directory with the
interpreter that runs the build, build the target orikin_python (the library's objects linked
in: the wheel needs no liborikin.so) and copy the module where setuptools wants it.
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = Path(__file__).resolve().parent
REPO = HERE.parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if not (REPO / "CMakeLists.txt").exists():
            raise RuntimeError(f"{REPO}: the orikin repository (its CMakeLists.txt) is needed to build the extension")
        build = Path(self.build_temp).resolve() / "cmake"
        build.mkdir(parents=True, exist_ok=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(min(os.cpu_count() or 2, 4)))
        # CMake asks the interpreter for numpy: without pip's isolation (its PYTHONPATH hides the
        # interpreter's site-packages), as the installed package will run.
        env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONNOUSERSITE", "PYTHONHOME")}
        subprocess.check_call(["cmake", "-S", str(REPO), "-B", str(build), "-DCMAKE_BUILD_TYPE=RelWithDebInfo",
                               "-DORI_TESTS=OFF", "-DORI_PYTHON=ON", f"-DPython3_EXECUTABLE={sys.executable}"], env=env)
        subprocess.check_call(["cmake", "--build", str(build), "--target", "orikin_python", "-j", jobs], env=env)
        built = list((build / "python" / "orikin").glob("_orikin*.so"))
        if not built:
            raise RuntimeError(f"{build}: CMake did not build orikin._orikin (python3-dev and python3-numpy installed?)")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(ext_modules=[Extension("orikin._orikin", sources=[])], cmdclass={"build_ext": CMakeBuild})
