"""The example notebook runs headless (nbclient) and shows what it says."""

from __future__ import annotations

from pathlib import Path
from typing import Any, List

import pytest

import slider_crank as sc
from conftest import REPO, Cli

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")


def outputs(cell: Any, kind: str) -> List[Any]:
    return [o for o in cell.get("outputs", []) if kind in o.get("data", {})]


def stdout(cell: Any) -> str:
    return "".join(o["text"] for o in cell.get("outputs", []) if o.get("name") == "stdout")


def test_the_notebook_runs_and_shows_its_results(tmp_path: Path, cli: Cli) -> None:
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
    # The dynamics: T = F·OM at 60° as analyze prints it, the turning
    # moment plotted, the turn's mean torque, ΔE and flywheel.
    d = cli.json(["analyze", "--json", "--angle=60", "--rpm=250", "--mass=10", "--gas-force=2000"])
    d = d["dynamics"]
    assert (
        f"at 60°: F = {d['piston_effort']:.2f} lbf, OM = {d['OM']:.4f} ft, "
        f"T = F·OM = {d['crank_effort']:.2f} lbf·ft" in stdout(code[4])
    )
    assert len(outputs(code[4], "image/png")) == 1
    turn = engine.turning_moment(rpm=250, fluctuation=0.02, mass=10, gas_force=2000)
    assert turn.flywheel is not None
    assert f"mean torque {turn.mean:.6g} lbf·ft, ΔE = {turn.fluctuation:.6g} lbf·ft" in stdout(code[4])
    assert f"I = {turn.flywheel.inertia:.6g} lbf·s²·ft" in stdout(code[4])
