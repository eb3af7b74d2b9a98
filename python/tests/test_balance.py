"""The whole engine's forces, the balance of in-line engines and the
piston acceleration's harmonics from Python: ``Dynamics.whole_engine`` is
the member ``whole_engine`` of ``analyze --json`` value for value,
``table("balance")`` and ``table("harmonics")`` the command's text byte
for byte, ``balance`` and ``harmonics`` the numbers of those tables, and
bad input the command line's message."""

from __future__ import annotations

import csv
import io
import json
import math
from typing import Any, Callable, Dict, List

import numpy as np
import pytest

import slider_crank as sc
from conftest import Cli, keywords

# A heavy rod: its mass 0.4 of the reciprocating parts', its inertia large.
HEAVY = ["--unit=m", "--force-unit=N", "--crank=0.3", "--rod=1.2", "--rpm=250",
         "--mass=250", "--rod-mass=100", "--rod-cg=0.4", "--rod-gyration=0.45"]
HEAVY_ENGINE = sc.SliderCrank(0.3, 1.2, unit="m", force_unit="N")
HEAVY_KEYWORDS: Dict[str, Any] = dict(rpm=250, mass=250, rod_mass=100, rod_cg=0.4, rod_gyration=0.45)


@pytest.mark.parametrize("angle", [30.0, 0.0, 90.0, 147.5, 270.0])
def test_the_whole_engine_is_analyzes(cli: Cli, angle: float) -> None:
    want = cli.json(["analyze", "--json", f"--angle={angle!r}", *HEAVY])["dynamics"]["whole_engine"]
    d = HEAVY_ENGINE.at(angle, **HEAVY_KEYWORDS).dynamics
    assert d is not None
    w = d.whole_engine
    assert isinstance(w, sc.EngineLoads)
    assert list(w.crosshead_pin_load) == want["crosshead_pin_load"]
    assert list(w.crank_pin_load) == want["crank_pin_load"]
    assert w.rod_force == want["rod_force"]
    assert w.guide_thrust == want["guide_thrust"]
    assert w.piston_effort_equivalent == want["piston_effort_equivalent"]
    assert list(w.shaking_force) == want["shaking_force"]
    # the names are the JSON's (friction is written only where given)
    assert set(want) == set(sc.EngineLoads.__dataclass_fields__) - {"friction"}


def test_the_heavy_rod_changes_the_forces_and_a_massless_one_does_not() -> None:
    heavy = HEAVY_ENGINE.at(30, **HEAVY_KEYWORDS).dynamics
    assert heavy is not None
    w = heavy.whole_engine
    # the rod's inertia: the whole engine's forces are not the reciprocating parts'
    assert abs(w.rod_force - heavy.rod_force) > 1e-3 * abs(heavy.rod_force)
    assert abs(w.guide_thrust - heavy.guide_thrust) > 1e-3 * abs(heavy.guide_thrust)
    # the rod holds the cross-head against the piston effort (towards the
    # crank, −x): its force on the pin along the stroke is F along +x
    assert w.crosshead_pin_load[0] == pytest.approx(heavy.piston_effort, rel=1e-12)
    assert w.guide_thrust == pytest.approx(w.crosshead_pin_load[1], rel=1e-12)
    # the rod's mass at the cross-head (m_A = m_r BG / l = 100 × 0.4 / 1.2) moves with the piston
    a = HEAVY_ENGINE.at(30, rpm=250).analytic.acceleration
    assert w.piston_effort_equivalent == pytest.approx(heavy.piston_effort + 100 * 0.4 / 1.2 * a,
                                                       rel=1e-12)
    light = HEAVY_ENGINE.at(30, rpm=250, mass=250, gas_force=1e4).dynamics
    assert light is not None
    wl = light.whole_engine
    assert wl.rod_force == pytest.approx(light.rod_force, rel=1e-12)
    assert wl.guide_thrust == pytest.approx(light.guide_thrust, rel=1e-12)
    assert wl.piston_effort_equivalent == light.piston_effort
    assert wl.shaking_force == pytest.approx((-light.inertia_force, 0.0), rel=1e-15)


TABLES: List[Any] = [
    ("balance", {}, []),
    ("balance", {"cranks": [0, 120, 240], "format": "csv", "decimals": 17, "angles": [0, 33, 90.5]},
     ["--cranks=0,120,240", "--format=csv", "--decimals=17", "--angles=0,33,90.5"]),
    ("balance", {"cranks": [0, 180, 180, 0], "planes": [0, 1, 2, 3], "crank": 25, "rod": 100,
                 "unit": "mm", "format": "markdown"},
     ["--cranks=0,180,180,0", "--planes=0,1,2,3", "--crank=25", "--rod=100", "--unit=mm",
      "--format=markdown"]),
    ("balance", {"cranks": [0, 120, 240, 240, 120, 0], "angles": np.arange(0, 181, 15)},
     ["--cranks=0,120,240,240,120,0", "--angles=0:180:15"]),
    ("balance", {"cranks": [0, 180, 90, 270, 270, 90, 180, 0], "rod": 2.2, "decimals": 6},
     ["--cranks=0,180,90,270,270,90,180,0", "--rod=2.2", "--decimals=6"]),
    ("harmonics", {}, []),
    ("harmonics", {"order": 8, "crank": 1, "rod": 3.5, "format": "csv"},
     ["--order=8", "--crank=1", "--rod=3.5", "--format=csv"]),
    ("harmonics", {"order": 2, "decimals": 17, "format": "markdown"},
     ["--order=2", "--decimals=17", "--format=markdown"]),
    ("harmonics", {"order": 40, "crank": 1, "rod": 1.01}, ["--order=40", "--crank=1", "--rod=1.01"]),
]


@pytest.mark.parametrize("name,options,flags", TABLES)
def test_table_is_the_command_lines(
    cli: Cli, name: str, options: Dict[str, Any], flags: List[str]
) -> None:
    assert sc.table(name, **options) == cli.stdout(["table", name, *flags])


def csv_rows(text: str) -> List[List[str]]:
    return [row for row in csv.reader(io.StringIO(text)) if row and not row[0].startswith("#")][1:]


@pytest.mark.parametrize("cranks,planes,rod", [
    ([0, 180, 180, 0], None, 3.0),
    ([0, 120, 240], [-2, 0.5, 3], 2.0),
    ([0, 90, 180, 270, 45], None, 4.25),
    ([10], None, 1.1),
])
def test_balance_gives_the_tables_numbers(cli: Cli, cranks: List[float], planes: Any, rod: float) -> None:
    flags = ["table", "balance", "--format=csv", "--decimals=17", "--angles=0:360:7.5",
             f"--cranks={','.join(map(str, cranks))}", f"--rod={rod!r}"]
    if planes is not None:
        flags.append(f"--planes={','.join(map(str, planes))}")
    rows = csv_rows(cli.stdout(flags))
    b = sc.balance(cranks, planes, n=rod / 0.5)
    assert b.cranks_deg == tuple(cranks) and b.n == rod / 0.5
    s = b.sweep(np.arange(0, 360.1, 7.5))
    assert len(rows) == s.theta_deg.size
    columns = [s.primary_force, s.secondary_force, s.primary_couple, s.secondary_couple, s.exact_force]
    for i, row in enumerate(rows):
        assert float(row[0]) == s.theta_deg[i]
        for cell, column in zip(row[1:], columns):
            assert abs(float(cell) - column[i]) <= 1e-17, (row, i)
    # the notes' verdict is the resultants'
    text = cli.stdout(flags)
    for name, part in (("Primary force", b.primary_force), ("Primary couple", b.primary_couple),
                       ("Secondary force", b.secondary_force),
                       ("Secondary couple", b.secondary_couple)):
        assert (f"{name}: balanced" in text) == part.balanced, name
    assert ("The engine is balanced" in text) == b.balanced


def test_the_textbooks_arrangements() -> None:
    n = 4.5
    four = sc.balance([0, 180, 180, 0], n=n)
    assert four.planes == (-1.5, -0.5, 0.5, 1.5)
    assert four.primary_force.balanced and four.primary_couple.balanced
    assert four.secondary_couple.balanced
    assert not four.secondary_force.balanced and not four.balanced
    assert four.secondary_force.amplitude == pytest.approx(4 / n, rel=1e-15)
    assert four.secondary_force.vector == pytest.approx((4 / n, 0.0), abs=1e-15)
    three = sc.balance([0, 120, 240], n=n)
    assert three.primary_force.balanced and three.secondary_force.balanced
    assert not three.primary_couple.balanced and not three.secondary_couple.balanced
    assert three.primary_couple.amplitude == pytest.approx(math.sqrt(3), rel=1e-15)
    six = sc.balance([0, 120, 240, 240, 120, 0], n=n)
    assert six.balanced
    assert all(p.balanced for p in (six.primary_force, six.primary_couple,
                                     six.secondary_force, six.secondary_couple))
    # the default is the command line's: the flat four, n = 6
    default = sc.balance()
    assert default.cranks_deg == (0, 180, 180, 0) and default.n == 6.0
    assert default.secondary_force.amplitude == pytest.approx(4 / 6, rel=1e-15)
    # what is left unbalanced, at every angle: 4 cos 2θ / n for the flat four
    deg = np.linspace(0, 360, 49).reshape(7, 7)
    s = four.sweep(deg)
    assert s.secondary_force.shape == deg.shape
    assert np.allclose(s.secondary_force, 4 * np.cos(2 * np.radians(deg)) / n, rtol=0, atol=1e-14)
    assert np.max(np.abs(s.primary_force)) <= 1e-14


@pytest.mark.parametrize("crank,rod,order", [(0.5, 3.0, 3), (1.0, 3.5, 8), (1.0, 1.01, 40)])
def test_harmonics_gives_the_tables_numbers(cli: Cli, crank: float, rod: float, order: int) -> None:
    rows = csv_rows(cli.stdout(["table", "harmonics", "--format=csv", "--decimals=17",
                                f"--crank={crank!r}", f"--rod={rod!r}", f"--order={order}"]))
    h = sc.harmonics(rod / crank, order)
    assert h.n == rod / crank
    assert len(h.coefficients) == order and len(h.truncation_error) == order + 1
    assert [r[0] for r in rows] == ["cos θ"] + [f"cos {2 * k}θ" for k in range(1, order + 1)]
    for row, a in zip(rows[1:], h.coefficients):
        assert abs(float(row[1]) - a) <= 1e-17
    for row, e in zip(rows, h.truncation_error):
        assert float(row[2]) == pytest.approx(e, rel=5e-4)
    # each cut is better than the one before; the default is the command line's
    assert all(b < a for a, b in zip(h.truncation_error, h.truncation_error[1:]))
    assert sc.harmonics() == sc.harmonics(6.0, 3)


def test_the_harmonics_are_the_textbooks_leading_terms() -> None:
    n = 5.0
    lam = 1 / n
    h = sc.harmonics(n, 3)
    assert h.coefficients[0] == pytest.approx(lam + lam**3 / 4 + 15 * lam**5 / 128, abs=0.1 * lam**7)
    assert h.coefficients[1] == pytest.approx(-(lam**3 / 4 + 3 * lam**5 / 16), abs=0.2 * lam**7)


# (the call, the command line given the same values)
ERRORS: List[Any] = [
    (lambda: sc.table("balance", cranks=[0, 180], planes=[0]),
     ["table", "balance", "--cranks=0,180", "--planes=0"]),
    (lambda: sc.balance([0, 180], [0], n=6), ["table", "balance", "--cranks=0,180", "--planes=0"]),
    (lambda: sc.table("balance", crank=1, rod=0.9), ["table", "balance", "--crank=1", "--rod=0.9"]),
    (lambda: sc.table("balance", cranks=[0, math.nan]), ["table", "balance", "--cranks=0,NaN"]),
    (lambda: sc.balance([0, math.nan]), ["table", "balance", "--cranks=0,NaN"]),
    (lambda: sc.table("balance", planes=[0, math.inf, 1, 2]),
     ["table", "balance", "--planes=0,inf,1,2"]),
    (lambda: sc.balance(planes=[0, math.inf, 1, 2]), ["table", "balance", "--planes=0,inf,1,2"]),
    (lambda: sc.table("balance", cranks=[0.0] * 65), ["table", "balance", "--cranks=" + ",".join(["0"] * 65)]),
    (lambda: sc.balance([0.0] * 65), ["table", "balance", "--cranks=" + ",".join(["0"] * 65)]),
    (lambda: sc.table("balance", angles=[0, math.nan]), ["table", "balance", "--angles=0,NaN"]),
    (lambda: sc.table("balance", decimals=18), ["table", "balance", "--decimals=18"]),
    (lambda: sc.table("harmonics", order=0), ["table", "harmonics", "--order=0"]),
    (lambda: sc.harmonics(6, 0), ["table", "harmonics", "--order=0"]),
    (lambda: sc.harmonics(6, 1001), ["table", "harmonics", "--order=1001"]),
    (lambda: sc.table("harmonics", crank=1, rod=1.005), ["table", "harmonics", "--crank=1", "--rod=1.005"]),
    (lambda: sc.harmonics(1.005), ["table", "harmonics", "--crank=1", "--rod=1.005"]),
    (lambda: sc.table("balance", offset=1), ["table", "balance", "--offset=1"]),
    (lambda: sc.table("balance", order=2), ["table", "balance", "--order=2"]),
    (lambda: sc.table("balance", rpm=60), ["table", "balance", "--rpm=60"]),
    (lambda: sc.table("harmonics", cranks=[0]), ["table", "harmonics", "--cranks=0"]),
    (lambda: sc.table("harmonics", unit="mm"), ["table", "harmonics", "--unit=mm"]),
    (lambda: sc.table("kinematics", planes=[0]), ["table", "kinematics", "--planes=0"]),
    (lambda: sc.table("dynamics", order=3), ["table", "dynamics", "--order=3"]),
]


@pytest.mark.parametrize("call,flags", ERRORS)
def test_bad_input_carries_the_command_lines_message(
    cli: Cli, call: Callable[[], Any], flags: List[str]
) -> None:
    message = cli.error(flags)
    with pytest.raises(ValueError) as caught:
        call()
    # the command line names its flags (--offset), Python its keywords (offset)
    assert str(caught.value) in (message, message.replace("--", ""), keywords(message)), (
        str(caught.value),
        message,
    )


def test_a_ratio_that_is_not_above_one() -> None:
    """The command line's n comes from --rod / --crank, refused before it
    is 1 or less; given directly it is refused by the library."""
    for n in (1.0, 0.5):
        with pytest.raises(ValueError, match=r"n = l/r > 1"):
            sc.balance(n=n)
    for n in (0.0, -2.0, math.nan, math.inf):
        with pytest.raises(ValueError):
            sc.balance(n=n)
        with pytest.raises(ValueError, match="n = l/r from 1.01"):
            sc.harmonics(n)
    with pytest.raises(ValueError, match="1 to 64 cylinders"):
        sc.balance([])


def test_wrong_types_are_type_errors() -> None:
    with pytest.raises(TypeError):
        sc.harmonics(6, 2.5)  # type: ignore[arg-type]
    with pytest.raises(TypeError):
        sc.balance(["0"])  # type: ignore[list-item]
    with pytest.raises(TypeError):
        sc.table("harmonics", order="3")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="order = -1 is out of range"):
        sc.harmonics(6, -1)


def test_the_values_are_plain_data() -> None:
    b = sc.balance([0, 120, 240])
    assert json.loads(json.dumps(b.primary_couple.vector)) == list(b.primary_couple.vector)
    assert b == sc.balance((0.0, 120.0, 240.0), (-1, 0, 1), 6)
    assert "InlineBalance(" in repr(b) and "Resultant(" in repr(b)
