# SPDX-License-Identifier: MIT
# docs/python.md, the README and examples/python/: every ```python block runs,
# in order, in one namespace (from the source tree, in a scratch directory for
# files), and every example script runs to completion.
import os
import re
import shutil
import subprocess
import sys

from conftest import SOURCE


def test_python_md_blocks_run(tmp_path, monkeypatch):
    # checks the walk-through's code blocks execute without error (their asserts check the thesis's values)
    text = (SOURCE / "docs" / "python.md").read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(blocks) >= 10
    shutil.copytree(SOURCE / "examples", tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for i, block in enumerate(blocks):
        exec(compile(block, f"docs/python.md block {i}", "exec"), namespace)  # noqa: S102 - our own docs


def test_howto_python_blocks_run(tmp_path, monkeypatch):
    # checks the how-to pages' Python blocks (docs/howto/*.md) execute, each page in its own namespace
    shutil.copytree(SOURCE / "examples", tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    ran = 0
    for page in sorted((SOURCE / "docs" / "howto").glob("*.md")):
        namespace = {}
        for i, block in enumerate(re.findall(r"```python\n(.*?)```", page.read_text(encoding="utf-8"), flags=re.S)):
            exec(compile(block, f"docs/howto/{page.name} block {i}", "exec"), namespace)  # noqa: S102 - our own docs
            ran += 1
    assert ran >= 3


def test_readme_python_block_runs():
    # checks the README's Python example executes
    text = (SOURCE / "README.md").read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(blocks) == 1
    exec(compile(blocks[0], "README.md", "exec"), {})  # noqa: S102 - our own docs


def test_example_scripts_run(tmp_path):
    # checks each examples/python script exits 0
    scripts = sorted((SOURCE / "examples" / "python").glob("*.py"))
    assert len(scripts) >= 3
    path = os.pathsep.join(os.path.abspath(p) for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p)
    for script in scripts:
        r = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True, text=True,
                           timeout=600, env={**os.environ, "PYTHONPATH": path, "HULA_EXAMPLE_QUICK": "1"})
        assert r.returncode == 0, f"{script.name}: {r.stderr}"
