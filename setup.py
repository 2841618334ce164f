"""`pip install .`: the Python package urdfsnap (python/urdfsnap) with its extension module built
by this repository's CMake (target urdfsnap_python, src/python), offline: nothing is downloaded.

    pip install --no-build-isolation --break-system-packages .      # Debian 12, system Python
    python3 -m venv --system-site-packages env && env/bin/pip install --no-build-isolation .

--no-build-isolation makes pip use the installed setuptools and wheel (python3-setuptools,
python3-wheel) instead of fetching them. The C++ build needs what scripts/deps.sh installs, plus
python3-dev, python3-numpy and pybind11-dev. CMAKE_ARGS (environment) adds CMake options; ccache is
used when installed. Compiled in build-pip/.
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    """Builds urdfsnap._urdfsnap with CMake and copies it where setuptools packs it."""

    def build_extension(self, ext):
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        configure = ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     "-DURDFSNAP_BUILD_TESTS=OFF", "-DURDFSNAP_BUILD_BENCH=OFF", "-DURDFSNAP_BUILD_PYTHON=ON",
                     f"-DPython3_EXECUTABLE={sys.executable}"]
        if shutil.which("ccache"):
            configure += ["-DCMAKE_C_COMPILER_LAUNCHER=ccache", "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"]
        configure += os.environ.get("CMAKE_ARGS", "").split()
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "urdfsnap_python", "-j", str(os.cpu_count() or 1)],
                       check=True)
        built = next((build / "python" / "urdfsnap").glob("_urdfsnap*.so"))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


def version():
    """The project's version, from CMakeLists.txt's project()."""
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(urdfsnap VERSION ([0-9.]+)", text).group(1)


setup(
    version=version(),
    package_dir={"": "python"},
    packages=["urdfsnap"],
    package_data={"urdfsnap": ["__init__.pyi", "py.typed"]},
    ext_modules=[Extension("urdfsnap._urdfsnap", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build-pip"}, "egg_info": {"egg_base": "build-pip"}},
    zip_safe=False,
)
