"""Tables are what `slider-crank table` prints."""

from __future__ import annotations

import math
from typing import Any, Dict, List

import numpy as np
import pytest

import slider_crank as sc
from conftest import Cli

CASES: List[Any] = [
    ("obliquity", {}, []),
    ("obliquity", {"n": [3, 4.5, math.inf], "angles": [30, 90]}, ["--n=3,4.5,inf", "--angles=30,90"]),
    ("acceleration-factor", {"format": "markdown"}, ["--format=markdown"]),
    ("acceleration-factor", {"angles": np.arange(0, 91, 15)}, ["--angles=0:90:15"]),
    ("kinematics", {}, []),
    ("kinematics", {"crank": 25, "rod": 72, "offset": 5, "rpm": 60, "unit": "mm",
                    "decimals": 6, "format": "csv", "angles": [0, 45, 200]},
     ["--crank=25", "--rod=72", "--offset=5", "--rpm=60", "--unit=mm", "--decimals=6",
      "--format=csv", "--angles=0,45,200"]),
    ("forces", {}, []),
    ("forces", {"torque": 500, "friction": 0.3, "force_unit": "kN"},
     ["--torque=500", "--friction=0.3", "--force-unit=kN"]),
]


@pytest.mark.parametrize("name,options,flags", CASES)
def test_table_is_the_command_lines(
    cli: Cli, name: str, options: Dict[str, Any], flags: List[str]
) -> None:
    assert sc.table(name, **options) == cli.stdout(["table", name, *flags])


ERRORS: List[Any] = [
    ("kinematics", {"rod": 0.2}, ["--rod=0.2"]),
    ("kinematics", {"omega": math.inf}, ["--omega=inf"]),
    ("forces", {"torque": math.nan}, ["--torque=NaN"]),
    ("forces", {"friction": -1}, ["--friction=-1"]),
    ("kinematics", {"decimals": 18}, ["--decimals=18"]),
    ("obliquity", {"n": [0.5]}, ["--n=0.5"]),
    ("obliquity", {"n": [math.nan]}, ["--n=NaN"]),
    ("kinematics", {"angles": [0, math.nan]}, ["--angles=0,NaN"]),
]


@pytest.mark.parametrize("name,options,flags", ERRORS)
def test_table_errors_carry_the_command_line_message(
    cli: Cli, name: str, options: Dict[str, Any], flags: List[str]
) -> None:
    message = cli.error(["table", name, *flags])
    with pytest.raises(ValueError) as caught:
        sc.table(name, **options)
    assert str(caught.value) == message


def test_unknown_tables_and_formats() -> None:
    with pytest.raises(ValueError, match="kinematics"):
        sc.table("velocities")
    with pytest.raises(ValueError, match="csv"):
        sc.table("kinematics", "json")
