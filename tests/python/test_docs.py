"""The Python examples of docs/python.md run as written, in the source tree (as the commands of the
documentation do in docs_commands)."""
import os
import re

import pytest

from conftest import SOURCE, import_ncurve

import_ncurve()

with open(os.path.join(SOURCE, "docs", "python.md"), encoding="utf-8") as f:
    BLOCKS = re.findall(r"^```python\n(.*?)^```", f.read(), re.S | re.M)


def test_the_page_has_examples():
    assert len(BLOCKS) >= 5


@pytest.mark.parametrize("number", range(len(BLOCKS)))
def test_example_runs(number, monkeypatch):
    monkeypatch.chdir(SOURCE)
    exec(compile(BLOCKS[number], f"docs/python.md, example {number + 1}", "exec"), {})
