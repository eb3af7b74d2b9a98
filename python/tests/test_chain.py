"""The chain of Fig. 60 from Python: the quadric chain, the curved slot and
the inversions give what `analyze --links/--slot-radius/--inversion --json`
prints digit for digit, their checks the report of `check`, their figures
the command's SVG, and bad values the command line's messages."""

from __future__ import annotations

import json
import math
from typing import Any, Callable, List

import pytest

import slider_crank as sc
from conftest import Cli, keywords


def same(got: Any, text: str) -> None:
    want = json.loads(text)
    assert got == want
    assert json.dumps(got, indent=2, ensure_ascii=False) == json.dumps(
        want, indent=2, ensure_ascii=False
    )


# (links, assembly, angle, omega, unit)
QUADRICS: List[Any] = [
    ((1.0, 3.0, 2.5, 3.0), "open", 30.0, 1.0, "ft"),
    ((1.0, 3.0, 2.5, 3.0), "crossed", 217.5, -12.0, "mm"),
    ((2.0, 2.0, 2.0, 2.0), "open", 0.0, 5.0, "ft"),  # change point: a toggle
    ((3.0, 2.0, 2.5, 1.0), "open", 123.0, 2.0, "m"),  # double crank
]


@pytest.mark.parametrize("links,mode,angle,omega,unit", QUADRICS)
def test_quadric_chain_is_analyze_links(cli: Cli, links: Any, mode: str, angle: float, omega: float, unit: str) -> None:
    text = cli.stdout([
        "analyze", "--json", "--links=" + ",".join(repr(x) for x in links), f"--assembly={mode}",
        f"--angle={angle!r}", f"--omega={omega!r}", f"--unit={unit}", "--force-unit=N",
    ])
    a, b, c, d = links
    chain = sc.QuadricChain(a, b, c, d, assembly=mode, unit=unit, force_unit="N")
    got = chain.at(angle, omega=omega)
    same(got.to_dict(), text)
    assert got["mechanism"]["grashof"] == json.loads(text)["mechanism"]["grashof"]
    assert got.points["O_cd"] == tuple(json.loads(text)["points"]["O_cd"])


# (crank, rod, offset, slot radius, angle, omega)
SLOTS: List[Any] = [
    (0.5, 1.5, 0.0, 2.0, 50.0, 10.0),
    (0.5, 1.5, 0.1, -3.0, 90.0, 10.0),
    (1.0, 4.0, -0.5, 1e6, 271.0, -3.0),  # nearly straight: the engine
]


@pytest.mark.parametrize("crank,rod,offset,rho,angle,omega", SLOTS)
def test_curved_slot_is_analyze_slot_radius(cli: Cli, crank: float, rod: float, offset: float, rho: float, angle: float, omega: float) -> None:
    text = cli.stdout([
        "analyze", "--json", f"--crank={crank!r}", f"--rod={rod!r}", f"--offset={offset!r}",
        f"--slot-radius={rho!r}", f"--angle={angle!r}", f"--omega={omega!r}",
    ])
    slot = sc.SliderCrank(crank, rod, offset).curved_slot(rho)
    same(slot.at(angle, omega=omega).to_dict(), text)


@pytest.mark.parametrize("n", [1, 2, 3, 4])
@pytest.mark.parametrize("angle", [0.0, 37.5, 90.0])
def test_inversions_are_analyze_inversion(cli: Cli, n: int, angle: float) -> None:
    text = cli.stdout([
        "analyze", "--json", "--crank=0.5", "--rod=1.5", "--offset=0.1", f"--inversion={n}",
        f"--angle={angle!r}", "--rpm=60", "--unit=m", "--force-unit=N",
    ])
    inversion = sc.SliderCrank(0.5, 1.5, 0.1, unit="m", force_unit="N").inversion(n)
    got = inversion.at(angle, rpm=60)
    same(got.to_dict(), text)
    assert got["inversion"] == n


CHECKS: List[Any] = [
    (lambda: sc.QuadricChain(1, 3, 2.5, 3).check(samples=500), ["--links=1,3,2.5,3", "--samples=500"]),
    (lambda: sc.QuadricChain(2, 2, 2, 2).check(samples=100, tolerance=1e-15),
     ["--links=2,2,2,2", "--samples=100", "--tolerance=1e-15"]),
    (lambda: sc.SliderCrank(0.5, 1.5, 0.1).curved_slot(2).check(samples=300),
     ["--crank=0.5", "--rod=1.5", "--offset=0.1", "--slot-radius=2", "--samples=300"]),
    (lambda: sc.SliderCrank(0.5, 3.0, 0.1).check(samples=2000), ["--offset=0.1", "--samples=2000"]),
    (lambda: sc.SliderCrank(1.0, 1.0001).check(samples=1000, tolerance=1e-16),
     ["--crank=1", "--rod=1.0001", "--samples=1000", "--tolerance=1e-16"]),
    (lambda: sc.SliderCrank(0.5, 1.5, 0.1).inversion(2).check(samples=400),
     ["--crank=0.5", "--rod=1.5", "--offset=0.1", "--inversion=2", "--samples=400"]),
    (lambda: sc.SliderCrank(1.0, 1.02, -0.01).inversion(3).check(samples=200, tolerance=1e-15),
     ["--crank=1", "--rod=1.02", "--offset=-0.01", "--inversion=3", "--samples=200",
      "--tolerance=1e-15"]),
]


@pytest.mark.parametrize("n", [1, 4])
def test_an_inversion_without_polygons_of_its_own_is_refused_as_the_command_refuses_it(
        cli: Cli, n: int) -> None:
    message = cli.error(["check", "--crank=0.5", "--rod=1.5", f"--inversion={n}"])
    assert "only inversions 2 and 3" in message
    with pytest.raises(ValueError) as caught:
        sc.SliderCrank(0.5, 1.5).inversion(n).check(samples=10)
    assert str(caught.value) == message.replace("--inversion", "inversion=")


@pytest.mark.parametrize("call,flags", CHECKS)
def test_checks_are_the_commands_report(cli: Cli, call: Callable[[], sc.CheckReport], flags: List[str]) -> None:
    done = cli.run(["check", *flags])
    report = call()
    assert str(report) == done.stdout.decode()
    assert report.passed == (done.returncode == 0)
    assert all(row.passed for row in report.rows) == report.passed
    text = done.stdout.decode()
    # A construction the mechanism lacks (Bennett's with an offset) is a
    # row of the report that says so.
    ends = ("  ok\n", "  FAIL\n", "  not drawn for this mechanism\n")
    assert len(report.rows) == sum(text.count(end) for end in ends)
    assert len(report.rows) > 0


# the chain's figures take the figure options: the command's SVG for the same
FIGURES: List[Any] = [
    ("fig-60-chains", dict(crank=0.4, rod=1.7, offset=0.1, angle=75)),
    ("inversion-2-rotating-block", dict(crank=0.5, rod=1.2, angle=130, style="handout")),
    ("inversion-3-oscillating-cylinder", dict(crank=0.5, rod=2.0, offset=-0.2, angle=10, unit="mm")),
    ("inversion-4-hand-pump", dict(crank=0.6, rod=1.5, angle=200, width="120mm", title="The hand pump")),
    ("inversion-1-engine", dict(rod=1.4, font="libertinus-serif", force_unit="N")),
]


@pytest.mark.parametrize("name,options", FIGURES)
def test_chain_figures_take_their_options(cli: Cli, name: str, options: Any) -> None:
    flags = [f"--{k.replace('_', '-')}={v}" for k, v in options.items()]
    want = cli.stdout(["figure", name, *flags])
    assert sc.figure(name, **options).svg == want


# what the chain's figures do not draw, refused as the command refuses it
REFUSED: List[Any] = [
    ("fig-60-chains", dict(rpm=100), ["--rpm=100"]),
    ("inversion-3-oscillating-cylinder", dict(omega=3), ["--omega=3"]),
    ("inversion-4-hand-pump", dict(mirror=True), ["--mirror"]),
    ("inversion-2-rotating-block", dict(layers="mechanism"), ["--layers=mechanism"]),
    ("inversion-1-engine", dict(notation="ng"), ["--notation=ng"]),
    ("inversion-2-rotating-block", dict(rod=0.4), ["--rod=0.4"]),
]


@pytest.mark.parametrize("name,options,flags", REFUSED)
def test_chain_figures_refuse_what_they_do_not_draw(cli: Cli, name: str, options: Any, flags: List[str]) -> None:
    # the command line names its flags (--rpm), Python its keywords (rpm=)
    message = keywords(cli.error(["figure", name, *flags]))
    with pytest.raises(ValueError) as caught:
        sc.figure(name, **options)
    assert str(caught.value) == message


def test_an_inversions_figure_is_its_engines() -> None:
    engine = sc.SliderCrank(0.5, 1.2)
    inversion = engine.inversion(2)
    assert inversion.figure_name == "inversion-2-rotating-block"
    assert inversion.figure(angle=130).svg == sc.figure(
        "inversion-2-rotating-block", crank=0.5, rod=1.2, offset=0.0, unit="ft", force_unit="lbf", angle=130
    ).svg


ERRORS: List[Any] = [
    (lambda: sc.QuadricChain(1, 1, 5, 1), ["analyze", "--links=1,1,5,1"]),
    (lambda: sc.QuadricChain(-1, 3, 2.5, 3), ["analyze", "--links=-1,3,2.5,3"]),
    (lambda: sc.QuadricChain(3, 1.5, 1.5, 1).at(90), ["analyze", "--links=3,1.5,1.5,1", "--angle=90"]),
    (lambda: sc.QuadricChain(1, 3, 2.5, 3).check(samples=0), ["check", "--links=1,3,2.5,3", "--samples=0"]),
    (lambda: sc.QuadricChain(1, 3, 2.5, 3).check(tolerance=2), ["check", "--links=1,3,2.5,3", "--tolerance=2"]),
    (lambda: sc.QuadricChain(1, 3, 2.5, 3).check(tolerance=-1), ["check", "--links=1,3,2.5,3", "--tolerance=-1"]),
    (lambda: sc.SliderCrank(0.5, 3).check(tolerance=math.nan), ["check", "--tolerance=NaN"]),
    (lambda: sc.SliderCrank(0.5, 3).check(samples=0), ["check", "--samples=0"]),
    (lambda: sc.SliderCrank(0.5, 1.5).curved_slot(1), ["analyze", "--crank=0.5", "--rod=1.5", "--slot-radius=1"]),
    (lambda: sc.SliderCrank(0.5, 1.5).curved_slot(math.nan), ["analyze", "--crank=0.5", "--rod=1.5", "--slot-radius=NaN"]),
    (lambda: sc.SliderCrank(0.5, 1.5).inversion(5), ["analyze", "--crank=0.5", "--rod=1.5", "--inversion=5"]),
    (lambda: sc.SliderCrank(0.5, 1.5).inversion(0), ["analyze", "--crank=0.5", "--rod=1.5", "--inversion=0"]),
    (lambda: sc.SliderCrank(0.5, 1.5).inversion(2).at(10, omega=math.inf),
     ["analyze", "--crank=0.5", "--rod=1.5", "--inversion=2", "--omega=inf"]),
]


@pytest.mark.parametrize("call,flags", ERRORS)
def test_bad_chains_carry_the_command_lines_message(cli: Cli, call: Callable[[], Any], flags: List[str]) -> None:
    message = cli.error(flags)
    with pytest.raises(ValueError) as caught:
        call()
    assert str(caught.value) == message or message.endswith(f": {caught.value} (see --help)"), (
        str(caught.value), message)


def test_numbers_that_are_not_finite() -> None:
    """The library's check names the value; an angle is refused by the
    request of ``analyze`` in the command line's words (``analyze
    --angle inf``)."""
    with pytest.raises(ValueError, match="crank must be a finite number, got NaN"):
        sc.QuadricChain(math.nan, 3, 2.5, 3)
    with pytest.raises(ValueError, match="invalid angle 'inf': the angle must be a finite"):
        sc.QuadricChain(1, 3, 2.5, 3).at(math.inf)
    with pytest.raises(ValueError, match="invalid angle 'NaN': the angle must be a finite"):
        sc.SliderCrank(0.5, 1.5).inversion(3).at(math.nan)


def test_bad_types_and_modes() -> None:
    with pytest.raises(ValueError, match="assembly 'sideways'"):
        sc.QuadricChain(1, 3, 2.5, 3, assembly="sideways")
    with pytest.raises(TypeError):
        sc.SliderCrank(0.5, 1.5).inversion(2.5)  # type: ignore[arg-type]
    with pytest.raises(TypeError):
        sc.QuadricChain(1, 3, 2.5, 3).check(samples=1.5)  # type: ignore[arg-type]


def test_the_coriolis_polygons_read_the_link_motion() -> None:
    for n in (2, 3):
        got = sc.SliderCrank(0.5, 1.5).inversion(n).at(30, rpm=250)
        c = got["coriolis"]
        assert math.isclose(c["omega_d"], got["links"]["d"]["angular_velocity"], rel_tol=1e-12)
        assert math.isclose(c["sliding_velocity"], got["sliding"]["velocity"], rel_tol=1e-12)
    assert sc.SliderCrank(0.5, 1.5).inversion(4).at(30, rpm=250)["coriolis"] is None


def test_the_quick_return_carries_the_time_ratio_and_the_tool() -> None:
    # r/l = 1/3: beta = 2 asin(1/3), the ratio (180 + beta)/(180 - beta).
    beta = 2 * math.degrees(math.asin(0.5 / 1.5))
    for n in (2, 3):
        q = sc.SliderCrank(0.5, 1.5).inversion(n).at(30, rpm=250)["quick_return"]
        assert math.isclose(q["time_ratio"], (180 + beta) / (180 - beta), rel_tol=1e-12)
        assert q["stroke"] == "cutting"
        assert q["tool"]["velocity"] > 0
    assert sc.SliderCrank(0.5, 1.5).inversion(1).at(30, rpm=250)["quick_return"] is None
