"""Every ```python block of docs/python.md runs (in order, each in a fresh namespace with REPO defined)."""

import os
import re

import pytest

from conftest import REPO

DOC = os.path.join(REPO, "docs", "python.md")
BLOCKS = re.findall(r"```python\n(.*?)```", open(DOC, encoding="utf-8").read(), re.S)


def test_docs_have_examples():
    assert len(BLOCKS) >= 3


@pytest.mark.parametrize("k", range(len(BLOCKS)))
def test_docs_example_runs(k):
    exec(compile(BLOCKS[k], f"{DOC} block {k + 1}", "exec"), {"REPO": REPO, "__name__": "__doc_example__"})
