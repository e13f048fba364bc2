"""Builds the compiled half of the Python module (frictionviz._core) with CMake, for `pip install
--no-build-isolation .` (pyproject.toml holds the package's metadata).

The module is the CMake target fvpython_core of this repository (python/CMakeLists.txt), configured with the
interpreter that runs this build (so that a venv's python gets a module of its own version) and without the
tests. FRICTIONVIZ_BUILD_DIR=DIR reuses a configured build tree (e.g. build/, where the module is built
already) instead of a fresh one under build/pip; FRICTIONVIZ_JOBS=N sets the parallel jobs (default: every
core).
"""

import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.environ.get("FRICTIONVIZ_BUILD_DIR") or os.path.join(ROOT, "build", "pip")
        build = os.path.abspath(build)
        jobs = os.environ.get("FRICTIONVIZ_JOBS") or str(os.cpu_count() or 1)
        if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
            subprocess.run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_TESTING=OFF",
                            "-DFV_PYTHON=ON", f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", build, "--target", "fvpython_core", "-j", jobs], check=True)
        pkg = os.path.join(build, "python", "frictionviz")
        built = [f for f in os.listdir(pkg) if f.startswith("_core.") and f.endswith(".so")]
        if len(built) != 1:
            raise RuntimeError(f"expected one _core*.so in {pkg}, found {built}")
        target = self.get_ext_fullpath(ext.name)  # _core.<this interpreter's suffix>.so
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(pkg, built[0]), target)


# setuptools' own scratch (build_base, the .egg-info) under build/setuptools: not in the source folders, and
# not in build/ itself, which is CMake's tree.
SCRATCH = os.path.join(ROOT, "build", "setuptools")
os.makedirs(SCRATCH, exist_ok=True)
setup(ext_modules=[CMakeExtension("frictionviz._core")], cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": SCRATCH}, "egg_info": {"egg_base": SCRATCH}})
