"""Shared set-up of the orikin package's tests (CTest `python`; docs/python.md).

Environment (set by CTest; defaults for running pytest by hand from the repository):
  ORIKIN_SOURCE_DIR    the repository (examples/, tests/data/, docs/)
  ORIKIN               the orikin CLI, for the messages the exceptions must share
  ORI_SHARED_PATTERNS  other projects' drawings (tests that need them skip when absent)
"""

import gc
import os
import shlex
import subprocess

import pytest

import orikin
from orikin import _orikin

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.environ.get("ORIKIN_SOURCE_DIR", os.path.normpath(os.path.join(HERE, "..", "..")))
CLI = os.environ.get("ORIKIN", os.path.join(REPO, "build", "orikin"))
SHARED = os.environ.get("ORI_SHARED_PATTERNS", os.path.join(REPO, "..", "shared", "patterns"))
ASAN = os.environ.get("ORIKIN_ASAN") == "1"


def repo(rel: str) -> str:
    """Path of a file of the repository."""
    return os.path.join(REPO, rel)


def shared(rel: str) -> str:
    """Path of a shared drawing; skips the test when it is absent (CI has none)."""
    path = os.path.join(SHARED, rel)
    if not os.path.exists(path):
        pytest.skip(f"{rel}: the shared patterns are not here")
    return path


def cli(args: str) -> subprocess.CompletedProcess:
    """Run `orikin ARGS` from the repository; stdout and stderr as text."""
    if not os.path.exists(CLI):
        pytest.skip(f"{CLI}: the orikin CLI is not built")
    return subprocess.run([CLI] + shlex.split(args), cwd=REPO, capture_output=True, text=True, timeout=600)


def cli_error(args: str) -> str:
    """The one line the CLI prints for a failing command, without its 'orikin CMD: ' prefix."""
    r = cli(args)
    assert r.returncode in (2, 3), (r.returncode, r.stderr)
    line = r.stderr.splitlines()[0]
    prefix = "orikin " + args.split()[0] + ": "
    assert line.startswith(prefix), line
    return line[len(prefix):]


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    report = outcome.get_result()
    if report.when == "call":
        item.call_failed = report.failed


@pytest.fixture(autouse=True)
def library_allocations_return(request):
    """Every test leaves the library's counted allocator no higher than it found it: whatever
    the Python objects held is freed once they are gone. (Lower is fine: a failed test's
    traceback may hold objects until the next test starts.)"""
    gc.collect()
    before = _orikin._alloc_live_count()
    yield
    if getattr(request.node, "call_failed", False):
        return  # the traceback holds the test's objects
    gc.collect()
    after = _orikin._alloc_live_count()
    assert after <= before, f"{after - before} library allocations still live after the test"


def open_corner() -> orikin.Pattern:
    """The thesis' open corner (a function, not a fixture: fixtures outlive the leak check)."""
    return orikin.Pattern.load(repo("examples/patterns/open-corner.fold"))
