# SPDX-License-Identifier: LGPL-3.0-or-later
"""Build of the Python package relpos (pyproject.toml): CMake compiles the library, the extension
relpos._relpos and the CLI `relpos` (Release, only those targets, all cores); the extension and the
installed _build.py go into the package, the CLI into the environment's bin/ (beside the `python`
that installs it, where relpos._cli.find_cli looks first).
"""
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


def project_version():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        m = re.search(r"project\(relpos VERSION ([0-9.]+)", f.read())
    return m.group(1)


class CMakeBuild(build_ext):
    """Configures and builds with CMake instead of compiling the (empty) extension sources."""

    def build_extension(self, ext):
        build = os.path.abspath(os.path.join(self.build_temp, "cmake"))
        cmake = shutil.which("cmake") or sys.exit("relpos needs cmake (Debian: cmake)")
        subprocess.run(
            [cmake, "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
             "-DRELPOS_BUILD_TESTS=OFF", "-DBUILD_TESTING=OFF", "-DRELPOS_BUILD_PYTHON=ON",
             "-DRELPOS_BUILD_SHARED=OFF", "-DPython3_EXECUTABLE=" + sys.executable],
            check=True)
        subprocess.run(
            [cmake, "--build", build, "--target", "_relpos", "relpos_cli",
             "-j", str(os.cpu_count() or 1)],
            check=True)
        target = self.get_ext_fullpath(ext.name)
        package_dir = os.path.dirname(target)
        os.makedirs(package_dir, exist_ok=True)
        built = [f for f in os.listdir(os.path.join(build, "python", "relpos")) if f.startswith("_relpos.")]
        self.copy_file(os.path.join(build, "python", "relpos", built[0]), target)
        self.copy_file(os.path.join(build, "python", "installed", "_build.py"),
                       os.path.join(package_dir, "_build.py"))
        # The CLI is installed as data into <prefix>/bin (a binary cannot go through build_scripts).
        self.distribution.data_files = [("bin", [os.path.join(build, "cli", "relpos")])]


setup(
    version=project_version(),
    ext_modules=[Extension("relpos._relpos", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # Not build/: that is where scripts/setup.sh puts the CMake build tree.
    options={"build": {"build_base": "build-python"}},
)
