"""Builds the somicage extension with the project's CMake (target somicage_python) for the running interpreter;
the package metadata is in pyproject.toml. Environment: CMAKE_BUILD_PARALLEL_LEVEL (default: all cores),
SOMICAGE_CMAKE_ARGS (extra -D options). The module runs on any CPU of its architecture, with the AVX2/FMA kernels
where the CPU has them; -DSOMICAGE_NATIVE=ON builds for this machine's CPU only (docs/performance.md)."""
import os
import pathlib
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     f"-DPython3_EXECUTABLE={sys.executable}", "-DSOMICAGE_PYTHON=ON",
                     "-DSOMICAGE_BUILD_EDITOR=OFF", "-DSOMICAGE_BUILD_TESTS=OFF", "-DSOMICAGE_CUDA=OFF",
                     *shlex.split(os.environ.get("SOMICAGE_CMAKE_ARGS", ""))]
        subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "--target", "somicage_python", "-j", jobs], check=True)
        built = next((build / "python" / "somicage").glob("_somicage*.so"))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


# build-pip/, not build/: the CMake build folder of the README stays as it is.
setup(ext_modules=[Extension("somicage._somicage", sources=[])], cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": "build-pip"}})
