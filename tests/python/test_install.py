# SPDX-License-Identifier: BSD-3-Clause
"""The package as users install it: `cmake --install --component python`
into a prefix (the package then loads that prefix's library, without
PROJCURVE_LIBRARY), and `pip install --no-build-isolation` offline (with the
library given by PROJCURVE_LIBRARY, or copied next to the package before
building so that it is installed with it)."""
import glob
import os
import shutil
import subprocess
import sys

import pytest

SOURCE = os.environ.get("PROJCURVE_SOURCE_DIR")
BUILD = os.environ.get("PROJCURVE_BUILD_DIR")
CMAKE = os.environ.get("PROJCURVE_CMAKE")
PYDIR = os.environ.get("PROJCURVE_PYTHON_INSTALL_DIR")

PROBE = ("import projcurve as pc, sys; "
         "s = pc.Surface.from_nurbs((1, 1), (2, 2), [[0,0,0],[1,0,0],[0,1,0],[1,1,1]], "
         "([0,0,1,1],[0,0,1,1])); "
         "c = pc.Curve.from_nurbs(1, [[0.1,0.2,2],[0.9,0.7,2]], [0,0,1,1]); "
         "assert len(pc.project_directional(s, c, (0,0,-1)).branches) == 1; "
         "print(pc.library_path()); print(pc.__file__)")


def clean_env(**extra):
    env = {k: v for k, v in os.environ.items()
           if k not in ("PROJCURVE_LIBRARY", "PYTHONPATH", "LD_LIBRARY_PATH")}
    env.update(extra)
    return env


def run_probe(cwd, **env):
    out = subprocess.run([sys.executable, "-c", PROBE], cwd=cwd, env=clean_env(**env),
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    return out.stdout.split()


@pytest.fixture
def need_build():
    if not (SOURCE and BUILD and CMAKE and PYDIR):
        pytest.skip("run through CTest (python_package) for the build and install paths")


def test_cmake_install_component(need_build, tmp_path):
    prefix = tmp_path / "prefix"
    for component in ([], ["--component", "python"]):
        subprocess.run([CMAKE, "--install", BUILD, "--prefix", str(prefix)] + component,
                       check=True, capture_output=True, timeout=300)
    site = prefix / PYDIR
    assert (site / "projcurve" / "__init__.py").exists()
    assert (site / "projcurve" / "_install_location.py").exists()
    lib_path, module = run_probe(tmp_path, PYTHONPATH=str(site))
    assert os.path.realpath(lib_path).startswith(os.path.realpath(prefix))
    assert module.startswith(str(site))


def copy_sources(tmp_path):
    src = tmp_path / "src"
    shutil.copytree(os.path.join(SOURCE, "python"), src,
                    ignore=shutil.ignore_patterns("__pycache__", "build", "*.egg-info"))
    return src


def pip_install(src, target):
    pip = subprocess.run([sys.executable, "-m", "pip", "--version"], capture_output=True)
    if pip.returncode != 0:
        pytest.skip("pip not installed for %s" % sys.executable)
    out = subprocess.run([sys.executable, "-m", "pip", "install", "--no-build-isolation",
                          "--no-deps", "--no-index", "--disable-pip-version-check", "--no-compile",
                          "--target", str(target), str(src)],
                         capture_output=True, text=True, timeout=300, env=clean_env())
    if out.returncode != 0 and "setuptools" in out.stderr and "No module" in out.stderr:
        pytest.skip("setuptools not installed for %s" % sys.executable)
    assert out.returncode == 0, out.stdout + out.stderr


def test_pip_install(need_build, pc, tmp_path):
    """One pip run (each takes seconds): a library copied next to the
    package is installed with it and loaded without PROJCURVE_LIBRARY,
    which, when set, still decides."""
    src = copy_sources(tmp_path)
    shutil.copy(pc.library_path(), src / "projcurve" / pc._lib.SONAME)
    target = tmp_path / "site"
    pip_install(src, target)
    assert glob.glob(str(target / ("projcurve-%s.dist-info" % pc.__version__)))
    lib_path, module = run_probe(tmp_path, PYTHONPATH=str(target))
    assert lib_path == str(target / "projcurve" / pc._lib.SONAME)
    assert module.startswith(str(target))
    lib_path, _ = run_probe(tmp_path, PYTHONPATH=str(target), PROJCURVE_LIBRARY=pc.library_path())
    assert lib_path == pc.library_path()


def test_loader_paths(need_build, pc, tmp_path):
    """PROJCURVE_LIBRARY decides alone (a wrong path is an error naming it);
    without it, from the source tree, the dynamic loader's search is used."""
    src = os.path.join(SOURCE, "python")
    missing = str(tmp_path / "nowhere" / pc._lib.SONAME)
    out = subprocess.run([sys.executable, "-c", "import projcurve"], cwd=tmp_path,
                         env=clean_env(PYTHONPATH=src, PROJCURVE_LIBRARY=missing),
                         capture_output=True, text=True, timeout=60)
    assert out.returncode != 0 and missing in out.stderr and "PROJCURVE_LIBRARY" in out.stderr
    lib_path, _ = run_probe(tmp_path, PYTHONPATH=src,
                            LD_LIBRARY_PATH=os.path.dirname(pc.library_path()))
    assert os.path.basename(lib_path) == pc._lib.SONAME
