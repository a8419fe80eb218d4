"""setup.py: the build step pyproject.toml cannot express.

`pip install .` (or `python3 -m build --wheel`) runs CMake on this checkout
to build the shared library libscaf (target scaf_shared, no tests or
benchmarks), then puts it inside the package next to a generated
_install_paths.py that points at it, so the installed package imports with
no environment variable and no other install of scaf. The package's
version is the C library's (project(scaf VERSION ...) in CMakeLists.txt).
CMake and the libraries libscaf links (scripts/setup.sh installs them) must
be on the machine; the CMake build folder is build/python-cmake.
"""

import os
import re
import shutil
import subprocess

from setuptools import Distribution, setup
from setuptools.command.build_py import build_py

ROOT = os.path.dirname(os.path.abspath(__file__))


def cmake_version():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        m = re.search(r"project\(scaf VERSION ([0-9]+\.[0-9]+\.[0-9]+)", f.read())
    if not m:
        raise RuntimeError("CMakeLists.txt: no `project(scaf VERSION x.y.z)`")
    return m.group(1)


class build_py_with_library(build_py):
    """build_py, then libscaf.so.N built by CMake copied into the package."""

    def run(self):
        super().run()
        work = os.path.join(ROOT, "build", "python-cmake")
        jobs = str(os.cpu_count() or 1)
        subprocess.check_call(["cmake", "-S", ROOT, "-B", work, "-DCMAKE_BUILD_TYPE=Release",
                               "-DSCAF_TESTS=OFF", "-DSCAF_BENCH=OFF", "-DSCAF_FUZZ=OFF"])
        subprocess.check_call(["cmake", "--build", work, "--target", "scaf_shared", "-j", jobs])
        soversion = "0"
        lib = os.path.join(work, "libscaf.so." + soversion)
        if not os.path.exists(lib):
            raise RuntimeError("CMake built no %s" % lib)
        dest = os.path.join(self.build_lib, "scaf")
        # a real file (not the link chain): wheels keep no symbolic links
        shutil.copyfile(os.path.realpath(lib), os.path.join(dest, "libscaf.so." + soversion))
        with open(os.path.join(dest, "_install_paths.py"), "w") as f:
            f.write('"""Written by setup.py: libscaf.so lies in this package."""\n'
                    'LIBDIR = "."\nSOVERSION = "%s"\n' % soversion)


class BinaryDistribution(Distribution):
    """A wheel for this platform: it carries a compiled library."""

    def has_ext_modules(self):
        return True


os.makedirs(os.path.join(ROOT, "build", "python-setuptools"), exist_ok=True)
setup(
    distclass=BinaryDistribution,
    version=cmake_version(),
    package_dir={"": "python"},
    packages=["scaf"],
    cmdclass={"build_py": build_py_with_library},
    zip_safe=False,
)
