"""`SliderCrank.at` gives what `slider-crank analyze --json` prints, digit
for digit (the same binary64 numbers, so the same shortest decimals)."""

from __future__ import annotations

import json
from typing import Any, List, Optional

import pytest

import slider_crank as sc
from conftest import Cli

# (crank, rod, offset, unit, force unit, angle, rpm, omega, torque, friction)
CASES = [
    (0.5, 3.0, 0.0, "ft", "lbf", 45.0, 250.0, None, None, None),
    (0.5, 3.0, 0.0, "ft", "lbf", 90.0, None, 26.16, None, None),  # D at infinity
    (0.5, 3.0, 0.0, "ft", "lbf", 0.0, None, None, 100.0, None),  # dead centre
    (25.0, 72.0, 0.0, "mm", "N", 30.0, 60.0, None, 1000.0, 0.1),  # Ng's rig
    (25.0, 72.0, 10.0, "mm", "N", 123.456, None, -7.5, -250.0, 0.0),
    (1.0, 1.5, 0.4, "m", "kN", 300.0, 3000.0, None, 5.0, 3.0),  # self-locking
    (1e-3, 2e-3, -5e-4, "m", "N", 271.0, None, 1e3, None, None),
    (2.0, 2.000001, 0.0, "in", "lbf", 179.9, 10.0, None, 1.0, None),
]


def flags(case: Any) -> List[str]:
    crank, rod, offset, unit, force, angle, rpm, omega, torque, friction = case
    args = ["analyze", "--json", f"--crank={crank!r}", f"--rod={rod!r}"]
    args += [f"--offset={offset!r}", f"--unit={unit}", f"--force-unit={force}"]
    args += [f"--angle={angle!r}"]
    for name, value in (("rpm", rpm), ("omega", omega), ("torque", torque)):
        if value is not None:
            args.append(f"--{name}={value!r}")
    if friction is not None:
        args.append(f"--friction={friction!r}")
    return args


def analysis(case: Any) -> sc.Analysis:
    crank, rod, offset, unit, force, angle, rpm, omega, torque, friction = case
    engine = sc.SliderCrank(crank, rod, offset, unit=unit, force_unit=force)
    return engine.at(angle, rpm=rpm, omega=omega, torque=torque, friction=friction)


@pytest.mark.parametrize("case", CASES)
def test_at_equals_the_json_of_analyze(cli: Cli, case: Any) -> None:
    text = cli.stdout(flags(case))
    got = analysis(case).to_dict()
    assert got == json.loads(text)
    # Digit for digit: the same numbers print the same.
    assert json.dumps(got, indent=2, ensure_ascii=False) == json.dumps(
        json.loads(text), indent=2, ensure_ascii=False
    )


def test_the_attributes_are_the_json_values(cli: Cli) -> None:
    case = CASES[3]
    v = cli.json(flags(case))
    a = analysis(case)
    assert a.analytic.velocity == v["analytic"]["velocity"]
    assert a.graphical.acceleration == v["graphical"]["acceleration"]
    assert a.points["B"] == tuple(v["points"]["B"])
    assert a.statics is not None
    assert a.statics.slider_force == v["statics"]["slider_force"]
    assert a.statics.slider_force_with_friction == v["statics"]["slider_force_with_friction"]
    assert a.units["torque"] == "N·mm"
    assert set(a.virtual_centres) == set(v["virtual_centres"])


def test_points_at_infinity_have_a_documented_form() -> None:
    a = sc.SliderCrank(0.5, 3.0).at(90, omega=10)
    d = a.points["D"]
    assert isinstance(d, sc.AtInfinity)
    assert a.to_dict()["points"]["D"] == {"at_infinity": list(d.direction)}
    assert abs(d.direction[0] ** 2 + d.direction[1] ** 2 - 1) < 1e-15
    # D is the centre O_bd of the rod (b) and the frame (d).
    assert a.virtual_centres["O_bd"] == d
    assert a.graphical.rod_angular_velocity == 0.0


def test_statics_at_a_dead_centre_and_when_locking() -> None:
    dead = analysis(CASES[2]).statics
    assert dead is not None
    assert dead.slider_force is None and dead.side_thrust is None
    assert not dead.self_locking
    locked = analysis(CASES[5]).statics
    assert locked is not None and locked.self_locking
    assert locked.slider_force_with_friction is None
    assert analysis(CASES[0]).statics is None


def test_default_speed_is_250_rpm(cli: Cli) -> None:
    v = cli.json(["analyze", "--json", "--angle=10"])
    assert sc.SliderCrank(0.5, 3.0).at(10).to_dict() == v


