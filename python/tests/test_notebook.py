"""The example notebook runs headless (nbclient) and shows what it says."""

from __future__ import annotations

from pathlib import Path
from typing import Any, List

import pytest

import slider_crank as sc
from conftest import REPO

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")


def outputs(cell: Any, kind: str) -> List[Any]:
    return [o for o in cell.get("outputs", []) if kind in o.get("data", {})]


def stdout(cell: Any) -> str:
    return "".join(o["text"] for o in cell.get("outputs", []) if o.get("name") == "stdout")


def test_the_notebook_runs_and_shows_its_results(tmp_path: Path) -> None:
    nb = nbformat.read(REPO / "examples/slider-crank.ipynb", as_version=4)
    nbclient.NotebookClient(
        nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}
    ).execute()
    code = [c for c in nb.cells if c.cell_type == "code"]
    engine = sc.SliderCrank(0.5, 3.0)
    pose = engine.at(45, omega=26.16)
    # The §35 values as the README prints them.
    assert f"velocity      {pose.analytic.velocity:.4f} ft/s" in stdout(code[0])
    assert "-10.3466" in stdout(code[0]) and "-242.3571" in stdout(code[0])
    assert "D at 90°: AtInfinity(direction=(0.0, 1.0))" in stdout(code[0])
    # The sweep is plotted, and the constructions agree with the exact values.
    assert len(outputs(code[1], "image/png")) == 1
    gap = float(stdout(code[1]).split(":")[-1])
    assert 0 <= gap < 1e-9
    # The figure is shown inline as SVG, the library's own.
    svg = outputs(code[2], "image/svg+xml")
    assert len(svg) == 1 and svg[0]["data"]["image/svg+xml"] == sc.figure("fig-66-kisch").svg
    # The handout is written where the notebook runs.
    written = (tmp_path / "slider-crank-handout.html").read_text(encoding="utf-8")
    assert written == engine.handout(45, rpm=250)
