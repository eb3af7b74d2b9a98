"""Partial balance, the hammer blow, V and radial engines and the rod's
true dynamical system from Python: ``table("partial-balance")`` and
``table("radial")`` the command's text byte for byte, ``radial`` and
``hammer_blow`` the numbers of those tables' notes against closed forms,
``Dynamics.rod`` the member ``dynamics.rod.dynamical`` of ``analyze
--json``, and bad input the command line's message."""

from __future__ import annotations

import math
from typing import Any, Callable, Dict, List

import numpy as np
import pytest

import slider_crank as sc
from conftest import Cli, keywords

TABLES: List[Any] = [
    ("partial-balance", {}, []),
    ("partial-balance", {"fractions": [0.25, 0.75], "format": "csv", "decimals": 17,
                         "angles": [0, 33, 90.5]},
     ["--fractions=0.25,0.75", "--format=csv", "--decimals=17", "--angles=0,33,90.5"]),
    ("partial-balance", {"fractions": [2 / 3], "unit": "m", "force_unit": "N", "mass": 180,
                         "crank": 0.3, "wheel": 1.8, "speed": 25, "load": 60000},
     [f"--fractions={2 / 3!r}", "--unit=m", "--force-unit=N", "--mass=180", "--crank=0.3",
      "--wheel=1.8", "--speed=25", "--load=60000"]),
    ("radial", {}, []),
    ("radial", {"axes": [0, 72, 144, 216, 288], "crank": 1, "rod": 4, "format": "markdown"},
     ["--axes=0,72,144,216,288", "--crank=1", "--rod=4", "--format=markdown"]),
    ("radial", {"axes": [-30, 30], "angles": np.arange(0, 91, 15), "decimals": 6},
     ["--axes=-30,30", "--angles=0:90:15", "--decimals=6"]),
]


@pytest.mark.parametrize("name,options,flags", TABLES)
def test_table_is_the_command_lines(
    cli: Cli, name: str, options: Dict[str, Any], flags: List[str]
) -> None:
    assert sc.table(name, **options) == cli.stdout(["table", name, *flags])


def test_the_v_twin_and_the_radial_engines() -> None:
    v = sc.radial()
    assert v.axes_deg == (-45.0, 45.0) and v.n == 6.0
    # the 90° V-twin: all primary direct crank, m r ω² along the crank
    assert v.primary_direct.vector == (1.0, 0.0) and v.primary_reverse.balanced
    for k in (3, 5, 7):
        r = sc.radial([360 * i / k for i in range(k)], n=4)
        assert r.primary_direct.amplitude == k / 2
        assert r.primary_reverse.balanced and r.secondary_direct.balanced
        # three cylinders keep a secondary reverse crank of 3/(2n)
        assert r.secondary_reverse.balanced == (k != 3)
        if k == 3:
            assert r.secondary_reverse.amplitude == pytest.approx(3 / 8, rel=1e-15)


def test_the_hammer_blow_is_c_m_r_omega_squared() -> None:
    blow, lift = sc.hammer_blow(2 / 3, 180, 0.3, 1.8, 25, load=60000)
    w = 2 * 25 / 1.8
    assert blow == pytest.approx(2 / 3 * 180 * 0.3 * w * w, rel=1e-14)
    assert lift is not None
    assert lift == pytest.approx(0.9 * math.sqrt(60000 / (2 / 3 * 180 * 0.3)), rel=1e-14)
    assert sc.hammer_blow(0, 180, 0.3, 1.8, 25, load=60000) == (0.0, None)
    assert sc.hammer_blow(0.5, 180, 0.3, 1.8, 25)[1] is None


def test_the_rods_dynamical_system_is_analyzes(cli: Cli) -> None:
    flags = ["--unit=m", "--force-unit=N", "--crank=0.3", "--rod=1.2", "--rpm=250",
             "--mass=250", "--rod-mass=100", "--rod-cg=0.4", "--rod-gyration=0.45"]
    want = cli.json(["analyze", "--json", "--angle=30", *flags])["dynamics"]["rod"]
    d = sc.SliderCrank(0.3, 1.2, unit="m", force_unit="N").at(
        30, rpm=250, mass=250, rod_mass=100, rod_cg=0.4, rod_gyration=0.45).dynamics
    assert d is not None and d.rod is not None
    got = want["dynamical"]
    assert d.rod.percussion_distance == got["percussion_distance"]
    assert d.rod.dynamical_mass_at_crosshead == got["mass_at_crosshead"]
    assert d.rod.mass_at_percussion == got["mass_at_percussion"]
    assert d.rod.dynamical_torque == got["torque"]
    # L = l1 + k²/l1 with l1 = AG = 1.2 − 0.4
    assert d.rod.percussion_distance == pytest.approx(0.8 + 0.45**2 / 0.8, rel=1e-15)
    assert d.rod.dynamical_torque == pytest.approx(d.rod.torque, rel=1e-12)


ERRORS: List[Any] = [
    (lambda: sc.table("partial-balance", fractions=[0.5, 1.5]),
     ["table", "partial-balance", "--fractions=0.5,1.5"]),
    (lambda: sc.table("partial-balance", mass=180), ["table", "partial-balance", "--mass=180"]),
    (lambda: sc.table("partial-balance", mass=180, crank=0.3, wheel=0, speed=25),
     ["table", "partial-balance", "--mass=180", "--crank=0.3", "--wheel=0", "--speed=25"]),
    (lambda: sc.hammer_blow(0.5, 180, 0.3, 1.8, 25, load=-1),
     ["table", "partial-balance", "--fractions=0.5", "--mass=180", "--crank=0.3", "--wheel=1.8",
      "--speed=25", "--load=-1"]),
    (lambda: sc.table("radial", axes=[0, math.nan]), ["table", "radial", "--axes=0,NaN"]),
    (lambda: sc.radial([0, math.nan]), ["table", "radial", "--axes=0,NaN"]),
    (lambda: sc.table("radial", mass=1), ["table", "radial", "--mass=1"]),
    (lambda: sc.table("partial-balance", rod=3), ["table", "partial-balance", "--rod=3"]),
]


@pytest.mark.parametrize("call,flags", ERRORS)
def test_bad_input_carries_the_command_lines_message(
    cli: Cli, call: Callable[[], Any], flags: List[str]
) -> None:
    message = cli.error(flags)
    with pytest.raises(ValueError) as caught:
        call()
    assert str(caught.value) in (message, message.replace("--", ""), keywords(message)), (
        str(caught.value),
        message,
    )
