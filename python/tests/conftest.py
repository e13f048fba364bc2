"""Shared helpers: the frictionviz executable of the same build (FV_EXE, set by CTest) and its JSON output."""

import json
import os
import subprocess

import pytest

REPO = os.environ.get("FV_REPO", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))


def exe():
    path = os.environ.get("FV_EXE")
    if not path:
        pytest.skip("FV_EXE (the frictionviz executable) not set; run through ctest -R python")
    return path


def cli(*args, expect=(0,)):
    """Runs the CLI; returns (exit status, stdout, stderr)."""
    p = subprocess.run([exe(), *map(str, args)], capture_output=True, text=True)
    assert p.returncode in expect, (args, p.returncode, p.stderr)
    return p.returncode, p.stdout, p.stderr


def cli_json(*args, expect=(0,)):
    """The CLI's --format json output, parsed: nlohmann's dump writes the shortest decimal that reads back
    as the same double, so the parsed floats are the CLI's values bit for bit."""
    _, out, _ = cli(*args, "--format", "json", expect=expect)
    return json.loads(out)
