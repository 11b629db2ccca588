"""Shared fixtures: the repository's test data and the `gmap` binary to compare with."""

import os
import shutil
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
DATA = REPO / "tests" / "data"

#: the extensions gmap reads
INPUT_EXTENSIONS = {".gmap", ".moka", ".facets", ".lex", ".off", ".json", ".cub", ".pbm"}


def data_files():
    """Every input file under tests/data, sorted."""
    return sorted(p for p in DATA.rglob("*") if p.is_file() and p.suffix.lower() in INPUT_EXTENSIONS)


def cargo_target_dir():
    """The workspace's target folder as cargo reports it (`cargo metadata`: CARGO_TARGET_DIR
    and a config's build.target-dir followed); the repository's target/ without cargo."""
    import json
    import subprocess

    try:
        out = subprocess.run(
            ["cargo", "metadata", "--format-version", "1", "--no-deps"],
            cwd=REPO,
            capture_output=True,
            text=True,
            timeout=120,
        )
        return Path(json.loads(out.stdout)["target_directory"])
    except (OSError, ValueError, KeyError, subprocess.SubprocessError):
        return REPO / "target"


def gmap_binary():
    """The `gmap` command: $GMAP_BIN, else a build in the repository's target folder, else
    one on the PATH; None when there is none."""
    env = os.environ.get("GMAP_BIN")
    if env:
        return env
    for profile in ("release", "test-release", "debug"):
        p = cargo_target_dir() / profile / "gmap"
        if p.exists():
            return str(p)
    return shutil.which("gmap")


@pytest.fixture(scope="session")
def gmap_bin():
    b = gmap_binary()
    if b is None:
        if os.environ.get("GMAP_REQUIRE_CLI"):
            pytest.fail("GMAP_REQUIRE_CLI is set but no gmap binary was found (set GMAP_BIN)")
        pytest.skip("no gmap binary: build it with `cargo build --release` or set GMAP_BIN")
    return b
