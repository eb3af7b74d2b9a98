"""Handouts and exercise sheets are what `slider-crank handout` writes."""

from __future__ import annotations

from pathlib import Path

import pytest

import slider_crank as sc
from conftest import Cli


def test_handout_is_the_command_lines(cli: Cli, tmp_path: Path) -> None:
    theirs = tmp_path / "theirs.html"
    cli.stdout(["handout", "--crank=25", "--rod=72", "--unit=mm", "--force-unit=N",
                "--angle=30", "--rpm=60", "--torque=1000", "--friction=0.1",
                "--paper=letter", f"--out={theirs}"])
    engine = sc.SliderCrank(25, 72, unit="mm", force_unit="N")
    ours = tmp_path / "ours.html"
    html = engine.handout(30, rpm=60, torque=1000, friction=0.1, paper="letter", out=ours)
    assert html == theirs.read_text(encoding="utf-8")
    assert ours.read_bytes() == theirs.read_bytes()


def test_exercise_and_key_are_the_command_lines(cli: Cli, tmp_path: Path) -> None:
    cli.stdout(["handout", "--exercise", "--angle=120", f"--out={tmp_path / 'cli.html'}"])
    sheet, key = sc.SliderCrank(0.5, 3.0).exercise(120, out=tmp_path / "py.html")
    assert sheet == (tmp_path / "cli.html").read_text(encoding="utf-8")
    assert key == (tmp_path / "cli-key.html").read_text(encoding="utf-8")
    assert (tmp_path / "py-key.html").read_text(encoding="utf-8") == key


def test_bad_handout_options(cli: Cli) -> None:
    message = cli.error(["handout", "--paper=a3", "--out=/dev/null"])
    with pytest.raises(ValueError) as caught:
        sc.SliderCrank(0.5, 3.0).handout(paper="a3")
    assert str(caught.value) in message, (message, str(caught.value))


def test_the_dynamics_page_is_the_command_lines(cli: Cli, tmp_path: Path) -> None:
    theirs = tmp_path / "theirs.html"
    cli.stdout(["handout", "--angle=60", "--mass=12", "--fluctuation=0.03", f"--out={theirs}"])
    html = sc.SliderCrank(0.5, 3.0).handout(60, mass=12, fluctuation=0.03)
    assert html == theirs.read_text(encoding="utf-8")
    assert "flywheel" in html.lower()
    plain = sc.SliderCrank(0.5, 3.0).handout(60)
    assert "flywheel" not in plain.lower() or len(plain) < len(html)


def test_dynamics_keywords_that_go_together() -> None:
    engine = sc.SliderCrank(0.5, 3.0)
    with pytest.raises(ValueError, match="give mass=M with it"):
        engine.handout(fluctuation=0.03)
    with pytest.raises(ValueError) as caught:
        engine.handout(mass=-1)
    assert "mass" in str(caught.value)
    metric = sc.SliderCrank(0.15, 0.9, unit="m", force_unit="N")
    with pytest.raises(ValueError) as caught:
        metric.handout(mass=10)
    # The refusal names the keywords to give, not the command line's flags.
    assert "indicator=CSV with bore=D, or gas_force=F" in str(caught.value)
    assert "--" not in str(caught.value)
    with pytest.raises(ValueError, match="give bore=D with indicator="):
        metric.handout(mass=10, indicator="examples/indicator.csv")


def test_an_si_handout_and_exercise_are_the_command_lines(cli: Cli, tmp_path: Path) -> None:
    csv = tmp_path / "p.csv"
    csv.write_text("fraction,expansion (Pa),compression (Pa)\n0,3e6,1e5\n0.5,8e5,2e5\n1,3e5,6e5\n")
    metric = sc.SliderCrank(0.06, 0.24, unit="m", force_unit="N")
    theirs = tmp_path / "theirs.html"
    flags = ["--crank=0.06", "--rod=0.24", "--unit=m", "--force-unit=N", "--angle=40", "--rpm=1500"]
    dyn = ["--mass=2", f"--indicator={csv}", "--bore=0.1"]
    cli.stdout(["handout", *flags, *dyn, f"--out={theirs}"])
    html = metric.handout(40, rpm=1500, mass=2, indicator=csv, bore=0.1)
    assert html == theirs.read_text(encoding="utf-8")
    assert "kg" in html and "lbf" not in html
    cli.stdout(["handout", "--exercise", *flags, "--mass=2", "--gas-force=5000", f"--out={theirs}"])
    sheet, key = metric.exercise(40, rpm=1500, mass=2, gas_force=5000)
    assert sheet == theirs.read_text(encoding="utf-8")
    assert 'data-key="dynamics.crank_effort"' in key
    assert 'data-key="dynamics.' not in sheet
    # A diagram in another unit than the engine's is refused in one line.
    wrong = tmp_path / "psi.csv"
    wrong.write_text("fraction,expansion (psi),compression (psi)\n0,3,1\n1,3,1\n")
    with pytest.raises(ValueError, match="its pressures are in psi, but lengths in m and forces in N need them in N/m²"):
        metric.handout(mass=2, indicator=wrong, bore=0.1)
