"""The build backend's CMake step (pyproject.toml): builds the C++ core, the `_core` extension and
the `hullinspect` CLI with the project's CMakeLists.txt and puts them into the package.

The version is CMakeLists.txt's `project(... VERSION x.y.z)`, the one place it is written. The CMake
build directory is HULLINSPECT_BUILD_DIR, default build/python-package in the checkout, and is kept
between builds, so a rebuild compiles only what changed (and ccache, when
CMAKE_CXX_COMPILER_LAUNCHER names it, serves the rest).
"""

import os
import re
import shutil
import subprocess
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
BUILD = Path(os.environ.get("HULLINSPECT_BUILD_DIR", ROOT / "build" / "python-package"))


def cmake_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"project\(hullinspect\s+VERSION\s+([0-9][0-9.]*)", text)
    if match is None:
        raise RuntimeError("CMakeLists.txt: project(hullinspect VERSION x.y.z) not found")
    return match.group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    """Configures (once) and builds the module and the CLI, then copies both into the package."""

    def build_extension(self, ext):
        jobs = os.environ.get("HULLINSPECT_JOBS", str(os.cpu_count() or 1))
        if not (BUILD / "CMakeCache.txt").exists():
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(BUILD), "-G", "Ninja",
                            "-DCMAKE_BUILD_TYPE=Release", "-DHULLINSPECT_BUILD_TESTS=OFF",
                            "-DHULLINSPECT_BUILD_BENCH=OFF"], check=True)
        subprocess.run(["cmake", "--build", str(BUILD), "-j", jobs, "--target",
                        "hullinspect_python", "hullinspect"], check=True)
        module = Path(self.get_ext_fullpath(ext.name))
        module.parent.mkdir(parents=True, exist_ok=True)
        built = list((BUILD / "python" / "hullinspect").glob("_core*.so"))
        if len(built) != 1:
            raise RuntimeError(f"{BUILD}/python/hullinspect: expected one _core*.so, found {built}")
        shutil.copyfile(built[0], module)
        cli = module.parent / "bin" / "hullinspect"
        cli.parent.mkdir(exist_ok=True)
        shutil.copyfile(BUILD / "hullinspect", cli)
        cli.chmod(0o755)


BUILD.mkdir(parents=True, exist_ok=True)
setup(version=cmake_version(),
      ext_modules=[CMakeExtension("hullinspect._core")],
      cmdclass={"build_ext": CMakeBuild},
      options={"build": {"build_base": str(BUILD / "setuptools")},
               "egg_info": {"egg_base": str(BUILD)}})
