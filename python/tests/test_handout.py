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
    with pytest.raises(ValueError, match="give mass= with it"):
        engine.handout(fluctuation=0.03)
    with pytest.raises(ValueError) as caught:
        engine.handout(mass=-1)
    assert "mass" in str(caught.value)
    metric = sc.SliderCrank(0.15, 0.9, unit="m", force_unit="N")
    with pytest.raises(ValueError, match="ft and forces in lbf"):
        metric.handout(mass=10)
