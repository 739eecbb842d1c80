"""Builds the dtlab extension (dtlab._core) with the project's own CMake.

pyproject.toml holds the metadata; this file only teaches setuptools' build_ext to
configure the project and build one target, `dtlab_python`, instead of compiling
sources itself. Environment:
  DTLAB_BUILD_DIR    the CMake build folder (default build/wheel, next to build/release,
                     so that ccache, with CCACHE_BASEDIR at the source root, reuses the
                     objects of `make build`)
  DTLAB_BUILD_JOBS   parallel compile jobs (default: all cores)
  DTLAB_CMAKE_ARGS   extra configure arguments, split on spaces
"""
import glob
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = os.path.dirname(os.path.abspath(__file__))


def _configure_args(build_dir):
    # The release preset's flags, so that the objects are those `make build` compiles.
    args = ["cmake", "-S", SOURCE, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
            "-DCMAKE_CXX_FLAGS_RELEASE=-O3 -DNDEBUG", f"-DPython_EXECUTABLE={sys.executable}",
            "-DDTLAB_BUILD_BENCH=OFF"]
    if shutil.which("ninja"):
        args += ["-G", "Ninja"]
    return args + os.environ.get("DTLAB_CMAKE_ARGS", "").split()


class CMakeBuild(build_ext):
    """build_ext for one prebuilt-by-CMake extension: configure, build, copy."""

    def build_extension(self, ext):
        build_dir = os.environ.get("DTLAB_BUILD_DIR") or os.path.join(SOURCE, "build", "wheel")
        env = dict(os.environ)
        env.setdefault("CCACHE_BASEDIR", SOURCE)
        if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
            subprocess.run(_configure_args(build_dir), check=True, env=env)
        jobs = os.environ.get("DTLAB_BUILD_JOBS") or str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", build_dir, "--target", "dtlab_python", "-j", jobs], check=True, env=env)
        built = glob.glob(os.path.join(build_dir, "python", "dtlab", "_core*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one _core module in {build_dir}/python/dtlab, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)


setup(ext_modules=[Extension("dtlab._core", sources=[])], cmdclass={"build_ext": CMakeBuild})
