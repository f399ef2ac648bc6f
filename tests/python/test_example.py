# SPDX-License-Identifier: BSD-3-Clause
"""examples/project.py runs and says what it projected; the Python block
of README.md runs as written."""
import os
import re
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


def test_readme_python_block(capsys):
    with open(os.path.join(SOURCE_DIR, "README.md"), encoding="utf-8") as f:
        blocks = re.findall(r"```python\n(.*?)```", f.read(), flags=re.S)
    assert blocks, "README.md has no python block"
    exec(compile(blocks[0], "README.md", "exec"), {})
    assert "CURVE_START CURVE_END" in capsys.readouterr().out
