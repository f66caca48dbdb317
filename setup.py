"""Builds the Python module multicpg for `pip install .` and `pip wheel .`.

setuptools (Debian's) drives the project's own CMake: build_ext configures the repository with
MULTICPG_PYTHON_ONLY (the libraries and the module, none of the CLI's or tests' packages) for the
interpreter pip runs, builds the one target _multicpg and puts it beside the package
python/multicpg. build_py copies the landscape datasets (data/landscapes/*) into the package as
multicpg/data/landscapes, where the installed module finds them (learning/landscapes.h,
docs/python.md "Datasets"); git holds them once, in data/. The version is the one project() in
CMakeLists.txt sets.

Environment:
  MULTICPG_BUILD_DIR  an existing CMake build directory of this repository (e.g. build/, made by
                      scripts/setup.sh) to build _multicpg in, so an install reuses its objects;
                      otherwise a directory under build/pip is configured and kept, so the next
                      install is incremental.
  CMAKE_BUILD_PARALLEL_LEVEL  compile jobs (default: every core).
ccache, when installed, is the compiler launcher of a directory configured here.
"""

import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py

ROOT = pathlib.Path(__file__).resolve().parent
# setuptools writes its build and metadata folders here (egg_base must exist beforehand).
(ROOT / "build" / "pip").mkdir(parents=True, exist_ok=True)
TARGET = "_multicpg"
# The datasets, and where the package holds them (learning/landscapes.cpp looks beside the module).
DATASETS = ROOT / "data" / "landscapes"
PACKAGE_DATASETS = pathlib.Path("multicpg") / "data" / "landscapes"


def project_version():
    """The version project(multicpg VERSION x.y.z) sets in CMakeLists.txt."""
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(multicpg VERSION ([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    """Builds the extension with CMake instead of compiling its (empty) source list."""

    def build_extension(self, ext):
        given = os.environ.get("MULTICPG_BUILD_DIR")
        build_dir = pathlib.Path(given or pathlib.Path(self.build_temp).resolve() / "cmake")
        if not given or not (build_dir / "CMakeCache.txt").exists():
            configure = ["cmake", "-S", str(ROOT), "-B", str(build_dir),
                         "-DCMAKE_BUILD_TYPE=Release", f"-DPython_EXECUTABLE={sys.executable}"]
            if not given:
                configure.append("-DMULTICPG_PYTHON_ONLY=ON")
            if shutil.which("ccache"):
                configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
            subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build_dir), "--target", TARGET, "--parallel",
                        jobs], check=True)
        built = sorted((build_dir / "python" / "multicpg").glob(TARGET + ".*.so"))
        if not built:
            raise RuntimeError(f"cmake built no {TARGET}*.so in {build_dir}")
        destination = pathlib.Path(self.get_ext_fullpath(ext.name))
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], destination)


class BuildPy(build_py):
    """Builds the package and copies the landscape datasets into it."""

    def run(self):
        super().run()
        destination = pathlib.Path(self.build_lib) / PACKAGE_DATASETS
        shutil.rmtree(destination, ignore_errors=True)  # build_lib is kept: no stale datasets
        destination.mkdir(parents=True)
        for dataset in sorted(DATASETS.iterdir()):
            if dataset.is_file():
                shutil.copyfile(dataset, destination / dataset.name)


setup(
    version=project_version(),
    packages=["multicpg"],
    package_dir={"": "python"},
    package_data={"multicpg": ["py.typed", "*.pyi"]},
    ext_modules=[Extension(f"multicpg.{TARGET}", sources=[])],
    cmdclass={"build_ext": CMakeBuild, "build_py": BuildPy},
    zip_safe=False,
    options={"build": {"build_base": "build/pip"}, "egg_info": {"egg_base": "build/pip"}},
)
