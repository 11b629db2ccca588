"""Every Python block of python/README.md runs as written (from the repository root)."""

import os
import re

import pytest

from conftest import REPO

README = REPO / "python" / "README.md"
BLOCKS = re.findall(r"```python\n(.*?)```", README.read_text(), flags=re.S)


def test_there_are_blocks():
    assert len(BLOCKS) >= 4


@pytest.mark.parametrize("code", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_block_runs(code, monkeypatch):
    monkeypatch.chdir(REPO)
    exec(compile(code, str(README), "exec"), {})
