"""Shared fixtures: the CLI binary (the reference the package must agree with), the paper's arch."""

import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]


def _cli() -> Path:
    p = Path(os.environ.get("VOUSSOIR_CLI", ROOT / "target" / "release" / "voussoir"))
    if not p.is_file():
        # No skipping: the comparisons with the CLI are the point of these tests.
        raise RuntimeError(
            f"the voussoir CLI is needed at {p} (cargo build --release -p voussoir-cli, "
            "or set VOUSSOIR_CLI); scripts/test-python.sh builds it"
        )
    return p


@pytest.fixture(scope="session")
def cli():
    path = _cli()

    def run(*args, check=True):
        r = subprocess.run([str(path), *map(str, args)], capture_output=True, text=True)
        if check and r.returncode != 0:
            raise AssertionError(f"voussoir {' '.join(map(str, args))} failed: {r.stderr}")
        return r

    return run


@pytest.fixture(scope="session")
def paper_arch(tmp_path_factory, cli):
    """The paper's arch with the live load on the whole span, written by `voussoir gen arch`."""
    path = tmp_path_factory.mktemp("models") / "arch.json"
    cli("gen", "arch", "--live", "full", "-o", path)
    return path


def cli_json(cli, *args):
    return json.loads(cli(*args, "--json").stdout)
