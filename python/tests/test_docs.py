"""docs/python.md's code runs: every ```python block, in order, in one namespace, from the
repository's root (the page's examples are its tests)."""

import re

import pytest

from conftest import repo


def blocks() -> list:
    text = open(repo("docs/python.md"), encoding="utf-8").read()
    return re.findall(r"```python\n(.*?)```", text, flags=re.S)


def test_the_guide_has_its_worked_examples():
    code = "\n".join(blocks())
    for needle in ("open-corner.fold", "generate(\"miura\"", ".layers()", "DesignEnv", "matplotlib"):
        assert needle in code, needle


def test_every_code_block_of_the_guide_runs(monkeypatch):
    monkeypatch.chdir(repo("."))
    namespace = {"__name__": "docs_python_md"}
    for k, code in enumerate(blocks()):
        try:
            exec(compile(code, f"docs/python.md block {k + 1}", "exec"), namespace)
        except Exception as e:  # name the block
            pytest.fail(f"docs/python.md, python block {k + 1}: {type(e).__name__}: {e}")
    namespace.clear()
