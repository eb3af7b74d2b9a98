"""Shared fixtures: the command-line program the package is compared with.

The program is ``$SLIDER_CRANK_BIN`` or the newest of the repository's
``target/release/slider-crank`` and ``target/debug/slider-crank`` (build it
with ``cargo build --bin slider-crank``); the comparisons fail without it.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
from pathlib import Path
from typing import Any, List, Sequence

import pytest

REPO = Path(__file__).resolve().parents[2]


def _program() -> Path:
    given = os.environ.get("SLIDER_CRANK_BIN")
    if given:
        return Path(given)
    built = [
        p
        for p in (REPO / "target/release/slider-crank", REPO / "target/debug/slider-crank")
        if p.exists()
    ]
    if not built:
        raise RuntimeError(
            "no slider-crank program: run `cargo build --bin slider-crank` "
            "or set SLIDER_CRANK_BIN"
        )
    return max(built, key=lambda p: p.stat().st_mtime)


def keywords(message: str) -> str:
    """The command line's message with each flag it names spelt as the
    package's keyword: ``--gas-force`` as ``gas_force=``, ``--bore D`` as
    ``bore=D`` (a flag's value is a capital or a number after it)."""
    return re.sub(
        r"--([a-z][a-z-]*)(?: (?=[A-Z0-9]))?",
        lambda m: m.group(1).replace("-", "_") + "=",
        message,
    )


class Cli:
    """Runs the command-line program."""

    def __init__(self, path: Path) -> None:
        self.path = path

    def run(self, args: Sequence[str]) -> "subprocess.CompletedProcess[bytes]":
        return subprocess.run(
            [str(self.path), *args], capture_output=True, cwd=REPO, timeout=120
        )

    def stdout(self, args: Sequence[str]) -> str:
        done = self.run(args)
        assert done.returncode == 0, done.stderr.decode()
        return done.stdout.decode()

    def json(self, args: Sequence[str]) -> Any:
        return json.loads(self.stdout(args))

    def error(self, args: Sequence[str]) -> str:
        """The message of a refused command, without its `slider-crank: `
        and `error: ` (a flag clap refused ends in ` (see --help)`)."""
        done = self.run(args)
        assert done.returncode == 2, (args, done.returncode, done.stdout[:200])
        lines: List[str] = done.stderr.decode().splitlines()
        assert len(lines) == 1 and lines[0].startswith("slider-crank: "), lines
        message = lines[0][len("slider-crank: ") :]
        return message[len("error: ") :] if message.startswith("error: ") else message


@pytest.fixture(scope="session")
def cli() -> Cli:
    return Cli(_program())
