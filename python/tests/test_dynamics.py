"""The engine's dynamics from Python: `at(..., mass=...)` gives the member
`dynamics` of `analyze --mass … --json` digit for digit, `sweep` the same
values at every angle, `table("dynamics")` the command's text byte for
byte, `turning_moment` the numbers of its notes, and every bad value the
command line's message."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from typing import Any, Callable, Dict, List

import numpy as np
import pytest

import slider_crank as sc
from conftest import REPO, Cli, keywords

INDICATOR = REPO / "examples/indicator.csv"

# (engine keywords, analyze flags giving the same engine)
ENGINES: List[Any] = [
    (dict(mass=10), ["--mass=10"]),
    (dict(gas_force=-1500.5), ["--gas-force=-1500.5"]),
    (
        dict(mass=2.5, rod_mass=3, rod_cg=1.1, rod_gyration=0.9, gas_force=800),
        ["--mass=2.5", "--rod-mass=3", "--rod-cg=1.1", "--rod-gyration=0.9", "--gas-force=800"],
    ),
    (
        dict(mass=1.2, indicator=str(INDICATOR), bore=10 / 12),
        ["--mass=1.2", f"--indicator={INDICATOR}", f"--bore={10 / 12!r}"],
    ),
]

# (crank, rod, offset, unit, force unit, angle, omega)
POSES: List[Any] = [
    (0.5, 3.0, 0.0, "ft", "lbf", 45.0, 26.16),
    (0.5, 3.0, 0.0, "ft", "lbf", 90.0, 26.16),  # D at infinity: Kisch's CG
    (0.5, 3.0, 0.0, "ft", "lbf", 0.0, 26.16),  # dead centre
    (0.5, 3.0, 0.2, "ft", "lbf", 197.3, -40.0),
    (0.5, 1.3, 0.0, "m", "N", 271.0, 300.0),
]


def analyze_flags(pose: Any, flags: List[str]) -> List[str]:
    crank, rod, offset, unit, force, angle, omega = pose
    return [
        "analyze", "--json", f"--crank={crank!r}", f"--rod={rod!r}", f"--offset={offset!r}",
        f"--unit={unit}", f"--force-unit={force}", f"--angle={angle!r}", f"--omega={omega!r}",
        *flags,
    ]


def engine_of(pose: Any) -> sc.SliderCrank:
    crank, rod, offset, unit, force, _, _ = pose
    return sc.SliderCrank(crank, rod, offset, unit=unit, force_unit=force)


@pytest.mark.parametrize("keywords,flags", ENGINES)
@pytest.mark.parametrize("pose", POSES)
def test_at_with_masses_equals_analyze(cli: Cli, pose: Any, keywords: Dict[str, Any], flags: List[str]) -> None:
    if "indicator" in keywords and pose[3:5] != ("ft", "lbf"):
        # The example diagram declares lbf/ft²: both refuse it in m and N.
        message = cli.error(analyze_flags(pose, flags))
        with pytest.raises(ValueError) as caught:
            engine_of(pose).at(pose[5], omega=pose[6], **keywords)
        assert str(caught.value) in message, (message, str(caught.value))
        assert "its pressures are in lbf/ft², but lengths in m and forces in N" in message
        return
    text = cli.stdout(analyze_flags(pose, flags))
    got = engine_of(pose).at(pose[5], omega=pose[6], **keywords)
    want = json.loads(text)
    assert "dynamics" in want
    assert got.to_dict() == want
    assert json.dumps(got.to_dict(), indent=2, ensure_ascii=False) == json.dumps(
        want, indent=2, ensure_ascii=False
    )
    d = got.dynamics
    assert d is not None
    assert d.torque == want["dynamics"]["torque"]
    assert d.inertia_force_klein == want["dynamics"]["inertia_force_klein"]
    assert d.unbalanced.secondary == want["dynamics"]["unbalanced"]["secondary"]
    assert (d.rod is None) == (want["dynamics"]["rod"] is None)
    if d.rod is not None:
        assert d.rod.equivalent_torque == want["dynamics"]["rod"]["equivalent"]["torque"]


def test_no_mass_no_dynamics() -> None:
    engine = sc.SliderCrank(0.5, 3.0)
    assert engine.at(45).dynamics is None
    assert "dynamics" not in engine.at(45).to_dict()
    assert engine.sweep([10, 20]).dynamics is None


FIELDS = [
    "gas_force", "inertia_force", "inertia_force_klein", "piston_effort", "rod_force",
    "guide_thrust", "OM", "crank_effort", "crank_effort_exact", "torque",
]


@pytest.mark.parametrize("keywords,flags", ENGINES)
def test_the_sweep_of_the_forces_is_at_at_every_angle(keywords: Dict[str, Any], flags: List[str]) -> None:
    engine = sc.SliderCrank(0.5, 3.0, 0.2)
    deg = np.array([[0.0, 12.5, 90.0], [180.0, 197.3, -400.0]])
    s = engine.sweep(deg, omega=26.16, **keywords)
    assert s.dynamics is not None
    assert s.dynamics.torque.shape == deg.shape
    for index, theta in np.ndenumerate(deg):
        d = engine.at(float(theta), omega=26.16, **keywords).dynamics
        assert d is not None
        for name in FIELDS:
            assert getattr(s.dynamics, name)[index] == getattr(d, name), (name, theta)
        assert s.dynamics.rod_torque[index] == (0.0 if d.rod is None else d.rod.torque)
        assert s.dynamics.primary[index] == d.unbalanced.primary
        assert s.dynamics.secondary[index] == d.unbalanced.secondary


def test_the_torque_sweep_does_virtual_work() -> None:
    """T ω = −F v with F the piston effort (massless rod): the sweep's
    torque against its own kinematics, to 1e-12 of the largest term."""
    w = 31.4
    s = sc.SliderCrank(0.4, 1.7, -0.1).sweep(np.linspace(0, 360, 721), omega=w, mass=3, gas_force=50)
    assert s.dynamics is not None
    power = s.dynamics.torque * w + s.dynamics.piston_effort * s.velocity
    scale = np.max(np.abs(s.dynamics.torque * w))
    assert np.max(np.abs(power)) <= 1e-12 * scale


TABLES: List[Any] = [
    ({}, []),
    (dict(mass=10, phases=[0, 180], fluctuation=0.02, decimals=3, format="csv"),
     ["--mass=10", "--phases=0,180", "--fluctuation=0.02", "--decimals=3", "--format=csv"]),
    (dict(crank=25, rod=72, unit="mm", force_unit="N", mass=0.002, rod_mass=0.001, rod_cg=20,
          rod_gyration=25, gas_force=300, rpm=3000, flywheel=5, angles=[0, 45, 90.5],
          format="markdown"),
     ["--crank=25", "--rod=72", "--unit=mm", "--force-unit=N", "--mass=0.002", "--rod-mass=0.001",
      "--rod-cg=20", "--rod-gyration=25", "--gas-force=300", "--rpm=3000", "--flywheel=5",
      "--angles=0,45,90.5", "--format=markdown"]),
    (dict(indicator=INDICATOR, bore=10 / 12, mass=1, phases=[0, 90, 180, 270]),
     [f"--indicator={INDICATOR}", f"--bore={10 / 12!r}", "--mass=1", "--phases=0,90,180,270"]),
]


@pytest.mark.parametrize("keywords,flags", TABLES)
def test_table_dynamics_is_the_commands(cli: Cli, keywords: Dict[str, Any], flags: List[str]) -> None:
    want = cli.stdout(["table", "dynamics", *flags])
    keywords = dict(keywords)
    fmt = keywords.pop("format", "text")
    assert sc.table("dynamics", fmt, **keywords) == want


def sig(x: float) -> str:
    """The six significant figures of the table's notes."""
    a = abs(x)
    if a != 0.0 and not 1e-4 <= a < 1e9:
        mantissa, exponent = f"{x:.5e}".split("e")
        return f"{mantissa}e{int(exponent)}"
    decimals = 0 if a == 0.0 else max(5 - math.floor(math.log10(a)), 0)
    return f"{x + 0.0:.{decimals}f}"


def settled(x: float, tolerance: float) -> float:
    """``x``, or 0 where it is within ``tolerance`` of zero, as the notes write it."""
    return 0.0 if abs(x) <= tolerance else x


@pytest.mark.parametrize("keywords,flags", TABLES[1:])
def test_turning_moment_gives_the_notes_numbers(cli: Cli, keywords: Dict[str, Any], flags: List[str]) -> None:
    text = cli.stdout(["table", "dynamics", *[f for f in flags if not f.startswith(("--format", "--angles", "--decimals"))]])
    keywords = {k: v for k, v in keywords.items() if k not in ("format", "angles", "decimals")}
    crank, rod, unit, force = (keywords.pop(k, d) for k, d in
                               (("crank", 0.5), ("rod", 3.0), ("unit", "ft"), ("force_unit", "lbf")))
    turn = sc.SliderCrank(crank, rod, unit=unit, force_unit=force).turning_moment(**keywords)
    note = re.search(r"work (\S+) .*, mean torque (\S+) .*ΔE = (\S+) .*most energy at θ = (\S+)°, "
                     r"least at (\S+)°; (\d+) areas", text)
    assert note is not None, text
    # a value within the integrals' tolerance of zero is written 0 (one turn: the
    # mean's tolerance is the work's over 2π)
    assert note.group(1) == sig(settled(turn.work, turn.tolerance))
    assert note.group(2) == sig(settled(turn.mean, turn.tolerance / (2 * math.pi)))
    assert note.group(3) == sig(settled(turn.fluctuation, turn.tolerance))
    assert note.group(4) == f"{turn.max_energy_deg:.2f}"
    assert note.group(5) == f"{turn.min_energy_deg:.2f}"
    assert int(note.group(6)) == len(turn.lobes)
    if "fluctuation" in keywords or "flywheel" in keywords:
        wheel = re.search(r"I = ΔE / \(ω² C_s\) = (\S+) .* for C_s = (\S+)\.", text)
        assert wheel is not None and turn.flywheel is not None
        assert wheel.group(1) == sig(turn.flywheel.inertia)
        assert wheel.group(2) == sig(turn.flywheel.coefficient)
    else:
        assert turn.flywheel is None


def test_the_turn_balances() -> None:
    """The lobes sum to zero over the turn (E(2π) = E(0)), ΔE is the range
    of the stored energy, and the flywheel satisfies ΔE = I ω² C_s."""
    w = 26.16
    turn = sc.SliderCrank(0.5, 3.0).turning_moment(omega=w, mass=10, gas_force=2000, fluctuation=0.03)
    energies = [0.0] + [lobe.energy for lobe in turn.lobes]
    assert abs(sum(lobe.area for lobe in turn.lobes)) <= 4 * turn.tolerance
    assert abs(turn.fluctuation - (max(energies) - min(energies))) <= 1e-9 * turn.fluctuation
    assert turn.flywheel is not None
    f = turn.flywheel
    assert abs(f.inertia * w * w * 0.03 - turn.fluctuation) <= 1e-12 * turn.fluctuation
    # a constant gas force does the work F × 2 strokes... of opposite signs: none
    assert abs(turn.work) <= 4 * turn.tolerance
    inertia_only = sc.SliderCrank(0.5, 3.0).turning_moment(omega=w)
    assert inertia_only.fluctuation > 0 and abs(inertia_only.mean) <= inertia_only.tolerance


# (the call, the command line given the same values)
ENGINE = sc.SliderCrank(0.5, 3.0)
ERRORS: List[Any] = [
    (lambda: ENGINE.at(45, mass=-1), ["analyze", "--mass=-1"]),
    (lambda: ENGINE.at(45, mass=math.nan), ["analyze", "--mass=NaN"]),
    (lambda: ENGINE.at(45, mass=1e300, omega=1e10), ["analyze", "--mass=1e300", "--omega=1e10"]),
    (lambda: ENGINE.at(45, rod_mass=1, rod_cg=4, rod_gyration=1),
     ["analyze", "--rod-mass=1", "--rod-cg=4", "--rod-gyration=1"]),
    (lambda: ENGINE.at(45, rod_mass=1, rod_cg=1, rod_gyration=-1),
     ["analyze", "--rod-mass=1", "--rod-cg=1", "--rod-gyration=-1"]),
    (lambda: ENGINE.at(45, gas_force=math.inf), ["analyze", "--gas-force=inf"]),
    (lambda: ENGINE.at(45, indicator="no-such.csv", bore=1),
     ["analyze", "--indicator=no-such.csv", "--bore=1"]),
    (lambda: ENGINE.at(45, indicator=INDICATOR, bore=0),
     ["analyze", f"--indicator={INDICATOR}", "--bore=0"]),
    (lambda: ENGINE.turning_moment(mass=1, fluctuation=0), ["table", "dynamics", "--fluctuation=0"]),
    (lambda: ENGINE.turning_moment(mass=1, flywheel=-2), ["table", "dynamics", "--flywheel=-2"]),
    (lambda: ENGINE.turning_moment(mass=1, phases=[0.0] * 65),
     ["table", "dynamics", "--phases=" + ",".join(["0"] * 65)]),
    (lambda: sc.table("kinematics", mass=1), ["table", "kinematics", "--mass=1"]),
    (lambda: sc.table("forces", rpm=10), ["table", "forces", "--rpm=10"]),
    (lambda: sc.table("dynamics", torque=10), ["table", "dynamics", "--torque=10"]),
]


def test_an_engine_of_no_cylinder_is_refused() -> None:
    with pytest.raises(ValueError, match="at least one cylinder"):
        ENGINE.turning_moment(mass=1, phases=[])


@pytest.mark.parametrize("call,flags", ERRORS)
def test_bad_dynamics_carry_the_command_lines_message(
    cli: Cli, call: Callable[[], Any], flags: List[str]
) -> None:
    message = cli.error(flags)
    with pytest.raises((ValueError, OSError)) as caught:
        call()
    # the command line names its flags (--mass), Python its keywords (mass)
    assert str(caught.value) in (
        message,
        message.replace("--", "").replace("-", "_"),
        keywords(message),
    ), (str(caught.value), message)


# the pairings the command line's parser enforces, named in Python's words
PAIRS: List[Any] = [
    (dict(rod_mass=1), ["rod_cg", "rod_gyration"]),
    (dict(rod_cg=1), ["rod_mass", "rod_gyration"]),
    (dict(rod_mass=1, rod_cg=1), ["rod_gyration"]),
    (dict(gas_force=1, indicator=INDICATOR, bore=1), ["gas_force", "indicator"]),
    (dict(indicator=INDICATOR), ["bore"]),
    (dict(bore=1), ["indicator", "bore"]),
]


@pytest.mark.parametrize("keywords,named", PAIRS)
def test_keywords_that_go_together(keywords: Dict[str, Any], named: List[str]) -> None:
    with pytest.raises(ValueError) as caught:
        ENGINE.at(45, **keywords)
    for name in named:
        assert name in str(caught.value)


def test_a_bad_angle_in_a_sweep_of_forces() -> None:
    with pytest.raises(ValueError) as kinematic:
        ENGINE.sweep([1.0, math.nan])
    with pytest.raises(ValueError) as dynamic:
        ENGINE.sweep([1.0, math.nan], mass=1)
    assert str(dynamic.value) == str(kinematic.value)


def test_a_phase_that_is_not_finite() -> None:
    with pytest.raises(ValueError, match="phase must be a finite number, got NaN"):
        ENGINE.turning_moment(mass=1, phases=[0, math.nan])


def test_wrong_types_are_type_errors() -> None:
    with pytest.raises(TypeError):
        ENGINE.at(45, mass="10")  # type: ignore[arg-type]
    with pytest.raises(TypeError):
        ENGINE.turning_moment(phases=["a"])  # type: ignore[list-item]


def test_threads_sweeping_the_forces_at_once_agree() -> None:
    from concurrent.futures import ThreadPoolExecutor

    engine = sc.SliderCrank(0.5, 3.0, 0.1)
    deg = np.linspace(0, 720, 20_001)
    one = engine.sweep(deg, omega=30, mass=2, rod_mass=1, rod_cg=1, rod_gyration=1).dynamics
    assert one is not None
    with ThreadPoolExecutor(4) as pool:
        runs = list(pool.map(
            lambda _: engine.sweep(deg, omega=30, mass=2, rod_mass=1, rod_cg=1, rod_gyration=1).dynamics,
            range(8),
        ))
    for run in runs:
        assert run is not None
        assert np.array_equal(run.torque, one.torque) and np.array_equal(run.rod_torque, one.rod_torque)


def test_a_flywheel_is_asked_one_way() -> None:
    """The command line's parser refuses --fluctuation with --flywheel."""
    for call in (
        lambda: ENGINE.turning_moment(mass=1, fluctuation=0.02, flywheel=3),
        lambda: sc.table("dynamics", fluctuation=0.02, flywheel=3),
    ):
        with pytest.raises(ValueError) as caught:
            call()
        assert re.search("fluctuation=? cannot be used with flywheel=?", str(caught.value))


# A four-stroke indicator diagram (the columns of tests/dynamics.rs's CSV4):
# the command reads its exhaust and intake strokes, and so must the package.
FOUR_STROKE = (
    "fraction,expansion,exhaust,intake,compression\n"
    "0,10,0.6,-0.2,1\n0.1,9,0.5,-0.3,1\n0.4,5,0.4,-0.3,1.5\n1,2,0.3,-0.1,3\n"
)


@pytest.mark.parametrize("angle", [30.0, 200.0, 300.0])
def test_a_four_stroke_indicator_diagram_is_read_as_the_command_reads_it(
    cli: Cli, tmp_path: Path, angle: float
) -> None:
    csv = tmp_path / "four-stroke.csv"
    csv.write_text(FOUR_STROKE)
    pose = (0.5, 3.0, 0.0, "ft", "lbf", angle, 26.16)
    flags = ["--mass=1", f"--indicator={csv}", "--bore=0.2"]
    want = json.loads(cli.stdout(analyze_flags(pose, flags)))
    got = engine_of(pose).at(angle, omega=26.16, mass=1, indicator=str(csv), bore=0.2)
    assert got.to_dict() == want
    one_turn = tmp_path / "one-turn.csv"
    one_turn.write_text("\n".join(",".join(row.split(",")[i] for i in (0, 1, 4))
                                  for row in FOUR_STROKE.splitlines()))
    if angle > 180:
        # on the return stroke the exhaust, not the compression, pushes
        other = engine_of(pose).at(angle, omega=26.16, mass=1, indicator=str(one_turn), bore=0.2)
        assert other.dynamics is not None and got.dynamics is not None
        assert other.dynamics.gas_force != got.dynamics.gas_force


def test_gravity_and_friction_enter_the_dynamics() -> None:
    # The §35 engine at 90°, moving towards the crank (ω > 0): the weight
    # of m towards the crank (the cylinder above it) is m g, 32.174 ft/s²,
    # and adds to the piston effort; the guides' friction μ |N| acts
    # against the motion, away from the crank (negative), N of a massless
    # rod the guide thrust's size.
    engine = sc.SliderCrank(0.5, 3.0)
    plain = engine.at(90, rpm=250, mass=10).dynamics
    assert plain is not None
    assert plain.weight is None and plain.friction is None
    up = engine.at(90, rpm=250, mass=10, gravity="towards-crank").dynamics
    assert up is not None and up.weight is not None
    assert up.weight == pytest.approx(10 * 9.80665 / 0.3048, rel=1e-12)
    assert up.piston_effort == pytest.approx(plain.piston_effort + up.weight, rel=1e-12)
    rub = engine.at(90, rpm=250, mass=10, friction=0.1).dynamics
    assert rub is not None
    assert rub.friction is not None and rub.friction < 0
    assert abs(rub.friction) == pytest.approx(0.1 * abs(rub.guide_thrust), rel=1e-12)
    assert rub.whole_engine.friction == pytest.approx(rub.friction, rel=1e-12)
    # Over a turn gravity does no work; the friction takes its work from
    # the mean torque.
    turn = engine.turning_moment(mass=10)
    weighed = engine.turning_moment(mass=10, gravity="towards-crank")
    assert abs(weighed.work - turn.work) <= 2 * (weighed.tolerance + turn.tolerance)
    rubbed = engine.turning_moment(mass=10, friction=0.1)
    assert rubbed.mean < turn.mean - 1e3 * turn.tolerance
    with pytest.raises(ValueError, match="self-locks"):
        engine.at(90, rpm=250, mass=10, friction=6)
    with pytest.raises(ValueError, match="unknown gravity 'up'"):
        engine.at(90, rpm=250, mass=10, gravity="up")
