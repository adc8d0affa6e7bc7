"""Packages the Python module fgsg for pip (pyproject.toml) from a CMake build.

The engine is a pybind11 module linked with fgsg's C++ libraries, which only CMake knows
how to build; so the wheel is made of what CMake built: build/python/fgsg/_fgsg*.so and
the JIT plugin build/lib/libfgsg_llvm.so (as fgsg/lib/, where fgsg/__init__.py looks),
with the package's Python files from python/fgsg/. When they are missing, the two
targets are built first (configuring build/ if needed). FGSG_BUILD_DIR names another
build directory. Offline with Debian's tools:

    pip install --no-build-isolation .      (or: pip wheel --no-build-isolation --no-deps .)
"""
import atexit
import glob
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tempfile

from setuptools import Distribution, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
BUILD_DIR = os.path.abspath(os.environ.get("FGSG_BUILD_DIR", os.path.join(ROOT, "build")))
PY_FILES = ("__init__.py", "__init__.pyi", "batch.py", "py.typed")


def project_version():
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        match = re.search(r"project\(fgsg\s+VERSION\s+([0-9.]+)", f.read())
    if not match:
        sys.exit("setup.py: no 'project(fgsg VERSION x.y.z' in CMakeLists.txt")
    return match.group(1)


def engine_module():
    """The built module for this python (its ABI suffix), or None."""
    path = os.path.join(BUILD_DIR, "python", "fgsg", "_fgsg" + sysconfig.get_config_var("EXT_SUFFIX"))
    return path if os.path.isfile(path) else None


def cmake_build():
    """Builds only what the package needs (not fgsg's tests), configuring for this python."""
    if not os.path.isfile(os.path.join(BUILD_DIR, "CMakeCache.txt")):
        subprocess.check_call(["cmake", "-S", ROOT, "-B", BUILD_DIR, "-DCMAKE_BUILD_TYPE=Release",
                               "-DPython3_EXECUTABLE=" + sys.executable])
    subprocess.check_call(["cmake", "--build", BUILD_DIR, "--target", "fgsg_python", "fgsg_llvm_plugin"])


class CopyCMakeBuild(build_ext):
    """The "extension" is the module CMake built: copied, with the JIT plugin, not compiled."""

    def run(self):
        plugin = os.path.join(BUILD_DIR, "lib", "libfgsg_llvm.so")
        if engine_module() is None or not os.path.isfile(plugin):
            cmake_build()
        module = engine_module()
        if module is None:
            built = glob.glob(os.path.join(BUILD_DIR, "python", "fgsg", "_fgsg*.so"))
            sys.exit(f"setup.py: {BUILD_DIR} holds {', '.join(map(os.path.basename, built)) or 'no module'}, "
                     f"not one for this python ({sys.executable}, _fgsg{sysconfig.get_config_var('EXT_SUFFIX')}); "
                     f"configure that build with -DPython3_EXECUTABLE={sys.executable} or set FGSG_BUILD_DIR")
        package = os.path.join(self.build_lib, "fgsg")
        os.makedirs(os.path.join(package, "lib"), exist_ok=True)
        for name in PY_FILES:
            shutil.copyfile(os.path.join(ROOT, "python", "fgsg", name), os.path.join(package, name))
        shutil.copy2(module, package)
        shutil.copy2(plugin, os.path.join(package, "lib"))

    def get_outputs(self):
        package = os.path.join(self.build_lib, "fgsg")
        return [os.path.join(package, n) for n in PY_FILES] + [
            os.path.join(package, "_fgsg" + sysconfig.get_config_var("EXT_SUFFIX")),
            os.path.join(package, "lib", "libfgsg_llvm.so")]


class BinaryDistribution(Distribution):
    """A wheel for this python and platform (cp311-cp311-linux_x86_64), not a pure one."""

    def has_ext_modules(self):
        return True


# setuptools' scratch folders (build/ by default: CMake's build directory here) and its
# egg-info go to a temporary folder, not into the source tree.
_scratch = tempfile.mkdtemp(prefix="fgsg-setup-")
atexit.register(shutil.rmtree, _scratch, ignore_errors=True)

setup(
    version=project_version(),
    packages=[],  # the package is laid out by CopyCMakeBuild
    distclass=BinaryDistribution,
    cmdclass={"build_ext": CopyCMakeBuild},
    options={"build": {"build_base": os.path.join(_scratch, "build")},
             "egg_info": {"egg_base": _scratch}},
)
