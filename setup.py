"""The module for `pip install .` (pyproject.toml): CMake builds the target ncurve_python for the
interpreter pip runs, and the shipped profiles and macros go to share/ncurve under the prefix,
where the installed module looks for them (docs/python.md). NCURVE_JOBS: the build's parallel jobs
(default 2); NCURVE_CMAKE_ARGS: more -D options."""
import glob
import os
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = os.path.dirname(os.path.abspath(__file__))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        # beside build/, so that ccache with CCACHE_BASEDIR finds the same compile commands
        build = os.path.join(SOURCE, "build-pip")
        # (the module looks for share/ncurve from the interpreter's site-packages under the prefix, where
        # pip puts it: cmake works that folder out from the interpreter)
        subprocess.run(["cmake", "-S", SOURCE, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DNCURVE_PYTHON=ON",
                        f"-DNCURVE_PYTHON_EXECUTABLE={sys.executable}",
                        *shlex.split(os.environ.get("NCURVE_CMAKE_ARGS", ""))], check=True)
        subprocess.run(["cmake", "--build", build, "--target", "ncurve_python", "-j",
                        os.environ.get("NCURVE_JOBS", "2")], check=True)
        built = glob.glob(os.path.join(build, "python", "ncurve*.so"))
        if len(built) != 1:
            sys.exit(f"setup.py: expected one module in {build}/python, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)
        shutil.copyfile(os.path.join(SOURCE, "src", "python", "ncurve.pyi"),
                        os.path.join(os.path.dirname(target), "ncurve.pyi"))


def shipped(folder):
    """(destination, files) pairs of a shipped folder, for share/ncurve under the prefix."""
    out = []
    for here, folders, files in os.walk(os.path.join(SOURCE, folder)):
        folders[:] = [f for f in folders if f != "__pycache__"]
        rel = os.path.relpath(here, SOURCE)
        out.append((os.path.join("share", "ncurve", rel), [os.path.join(rel, f) for f in sorted(files)]))
    return out


# setuptools' own folders in build-pip too, not in build/ (CMake's) or the source tree
os.makedirs(os.path.join(SOURCE, "build-pip"), exist_ok=True)
setup(
    options={"build": {"build_base": "build-pip/setuptools"}, "egg_info": {"egg_base": "build-pip"}},
    ext_modules=[Extension("ncurve", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    data_files=shipped("profiles") + shipped("macros") + shipped("examples"),
)
