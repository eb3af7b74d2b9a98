"""Every bad input is a Python exception carrying the command line's
message, never a crash."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any, Callable, Dict, List

import numpy as np
import pytest

import slider_crank as sc
from conftest import Cli, keywords

ENGINE = sc.SliderCrank(0.5, 3.0)

# (the call, the command line given the same values)
ENGINE_CASES: List[Any] = [
    (lambda: sc.SliderCrank(1, 0.5), ["--crank=1", "--rod=0.5"]),
    (lambda: sc.SliderCrank(1, 2, 1.5), ["--crank=1", "--rod=2", "--offset=1.5"]),
    (lambda: sc.SliderCrank(math.nan, 3), ["--crank=NaN", "--rod=3"]),
    (lambda: sc.SliderCrank(0.5, math.inf), ["--crank=0.5", "--rod=inf"]),
    (lambda: sc.SliderCrank(-1, 3), ["--crank=-1", "--rod=3"]),
    (lambda: sc.SliderCrank(0, 3), ["--crank=0", "--rod=3"]),
    (lambda: sc.SliderCrank(1e300, 3e300), ["--crank=1e300", "--rod=3e300"]),
    (lambda: sc.SliderCrank(0.5, 3, -math.inf), ["--offset=-inf"]),
    (lambda: sc.SliderCrank(0.5, 3, unit=""), ["--unit="]),
    (lambda: sc.SliderCrank(0.5, 3, unit="m" * 100), ["--unit=" + "m" * 100]),
    (lambda: sc.SliderCrank(0.5, 3, force_unit="N\nx"), ["--force-unit=N\nx"]),
    (lambda: ENGINE.at(45, omega=1e200), ["--omega=1e200"]),
    (lambda: ENGINE.at(45, omega=1e-200), ["--omega=1e-200"]),
    (lambda: ENGINE.at(45, omega=math.nan), ["--omega=NaN"]),
    (lambda: ENGINE.at(45, rpm=math.inf), ["--rpm=inf"]),
    (lambda: ENGINE.at(45, rpm=1e101), ["--rpm=1e101"]),
    (lambda: ENGINE.at(45, torque=math.inf), ["--torque=inf"]),
    (lambda: ENGINE.at(45, torque=1, friction=-0.5), ["--torque=1", "--friction=-0.5"]),
    (lambda: ENGINE.at(45, torque=1, friction=math.nan), ["--torque=1", "--friction=NaN"]),
    (lambda: sc.SliderCrank(1e100, 1.0000001e100).at(90, omega=1e100),
     ["--crank=1e100", "--rod=1.0000001e100", "--angle=90", "--omega=1e100"]),
]


@pytest.mark.parametrize("call,flags", ENGINE_CASES)
def test_engine_errors_carry_the_command_line_message(
    cli: Cli, call: Callable[[], Any], flags: List[str]
) -> None:
    message = cli.error(["analyze", *flags])
    with pytest.raises(ValueError) as caught:
        call()
    # a value clap parses is quoted in its own words around the library's
    assert str(caught.value) == message or message.endswith(f": {caught.value} (see --help)")


FIGURE_CASES: List[Any] = [
    ({"layers": "mechanism,no-such"}, ["--layers=mechanism,no-such"]),
    ({"layers": ""}, ["--layers="]),
    ({"angle": math.nan}, ["--angle=NaN"]),
    ({"rod": 0.1}, ["--rod=0.1"]),
    ({"omega": math.inf}, ["--omega=inf"]),
    ({"fit": "both"}, ["--fit=both"]),
    ({"width": "12furlongs"}, ["--width=12furlongs"]),
    ({"width": -5}, ["--width=-5"]),
]


@pytest.mark.parametrize("options,flags", FIGURE_CASES)
def test_figure_errors_carry_the_command_line_message(
    cli: Cli, options: Dict[str, Any], flags: List[str]
) -> None:
    message = keywords(cli.error(["figure", "fig-66-kisch", *flags]))
    with pytest.raises(ValueError) as caught:
        sc.figure("fig-66-kisch", **options)
    assert str(caught.value) in message, (message, str(caught.value))


def test_unknown_names_list_the_names() -> None:
    with pytest.raises(ValueError, match="fig-66-kisch"):
        sc.figure("fig-99")
    with pytest.raises(ValueError, match="textbook"):
        sc.figure("fig-66-kisch", style="baroque")


def test_files_that_cannot_be_read_or_written(tmp_path: Path, cli: Cli) -> None:
    missing = tmp_path / "none.csv"
    message = cli.error(["figure", "ng-fig-8-forces", f"--data={missing}"])
    with pytest.raises(OSError) as caught:
        sc.figure("ng-fig-8-forces", data=missing)
    assert str(caught.value) == message
    f = sc.figure("fig-63-velocity")
    out = tmp_path / "x.jpg"
    message = cli.error(["figure", "fig-63-velocity", f"--out={out}"])
    with pytest.raises(ValueError) as refused:
        f.save(out)
    assert str(refused.value) == message
    with pytest.raises(OSError):
        f.save(tmp_path / "no-such-dir" / "x.svg")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_sweep_refuses_angles_that_are_not_finite(bad: float) -> None:
    with pytest.raises(ValueError) as caught:
        ENGINE.sweep([0.0, 10.0, bad, 20.0])
    with pytest.raises(ValueError) as single:
        ENGINE.at(bad)
    assert str(caught.value) == str(single.value)
    assert "angle" in str(caught.value)


@pytest.mark.parametrize(
    "bad", [["a", "b"], np.array([1 + 2j]), [None, 1.0], np.array(["1.0"]), [[1, 2], [3]]]
)
def test_sweep_refuses_values_that_are_not_real_numbers(bad: Any) -> None:
    with pytest.raises((TypeError, ValueError)):
        ENGINE.sweep(bad)


def test_sweep_of_a_huge_array_is_a_memory_error_not_a_crash() -> None:
    huge = np.broadcast_to(np.float64(1.0), (10**12,))
    with pytest.raises(MemoryError):
        ENGINE.sweep(huge)


def test_wrong_types_are_type_errors() -> None:
    with pytest.raises(TypeError):
        sc.SliderCrank("long", 3.0)  # type: ignore[arg-type]
    with pytest.raises(TypeError):
        ENGINE.at(45, rpm="fast")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="not both"):
        ENGINE.at(45, rpm=250, omega=26)
    with pytest.raises(ValueError, match="torque"):
        ENGINE.at(45, friction=0.1)
