# SPDX-License-Identifier: BSD-3-Clause
"""examples/project.py runs and says what it projected."""
import os
import subprocess
import sys

from conftest import SOURCE_DIR, data

EXAMPLE = os.path.join(SOURCE_DIR, "examples", "project.py")


def run(*args):
    out = subprocess.run([sys.executable, EXAMPLE, *args], capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 0, out.stderr
    return out.stdout


def test_built_in():
    out = run()
    assert "1 branch(es), 0 failure(s)" in out and "curve_start -> curve_end" in out


def test_model_and_output(pc, tmp_path):
    path = tmp_path / "fold.igs"
    out = run(data("cases", "fold_c_sheet_jump.igs"), "-o", str(path))
    assert "2 branch(es)" in out and "wrote" in out
    back = pc.Model.read(path)
    assert len(back.surfaces) == 1 and len(back.curves) >= 2
