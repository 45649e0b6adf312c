"""Shared set-up of the Python module's tests: the CLI binary ctest passes (NCURVE_CLI), the second
path the module is checked against, and the source tree's examples (NCURVE_SOURCE)."""
import json
import os
import subprocess

import pytest

NOT_BUILT = "the ncurve module is not built (NCURVE_PYTHON=OFF, or pybind11-dev / python3-numpy missing)"


def import_ncurve():
    """The module of the build under test (NCURVE_MODULE_DIR, which ctest sets), for each test file;
    its tests skipped, saying why, where it is not built, not an installed one tested in its place."""
    module = pytest.importorskip("ncurve", reason=NOT_BUILT)
    expected = os.environ.get("NCURVE_MODULE_DIR")
    if expected and os.path.realpath(os.path.dirname(module.__file__)) != os.path.realpath(expected):
        pytest.skip(f"{NOT_BUILT}: ncurve was imported from {module.__file__} instead", allow_module_level=True)
    return module

SOURCE = os.environ.get("NCURVE_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))


def example(name):
    return os.path.join(SOURCE, "examples", name)


@pytest.fixture(scope="session")
def cli():
    """Runs the ncurve binary: cli("run", FILE, ...) -> CompletedProcess (text)."""
    binary = os.environ.get("NCURVE_CLI")
    if not binary:
        pytest.skip("NCURVE_CLI (the ncurve binary) is not set: run these tests through ctest")

    def call(*args):
        return subprocess.run([binary, *map(str, args)], capture_output=True, text=True, timeout=120)

    return call


@pytest.fixture(scope="session")
def cli_json(cli):
    """The summary of `ncurve run ARGS --json` as a dict."""
    def call(*args):
        done = cli("run", *args, "--json")
        assert done.returncode in (0, 1), done.stderr
        return json.loads(done.stdout)

    return call
