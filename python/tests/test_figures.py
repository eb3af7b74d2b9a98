"""Figures drawn in-process are byte for byte what `slider-crank figure`
writes for the same options."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Callable, Dict, List, Tuple

import pytest

import slider_crank as sc
from conftest import Cli

CASES: List[Any] = [
    ("fig-66-kisch", {}, []),
    ("fig-65-klein", {"angle": 130, "rod": 2.0, "offset": 0.2, "style": "handout"},
     ["--angle=130", "--rod=2.0", "--offset=0.2", "--style=handout"]),
    ("ng-fig-1-torque", {"notation": "textbook", "mirror": True, "width": "120mm",
                         "title": "The *OM* line"},
     ["--notation=textbook", "--mirror", "--width=120mm", "--title=The *OM* line"]),
    ("fig-64-velocity-diagrams", {"rpm": 300, "font": "libertinus-serif"},
     ["--rpm=300", "--font=libertinus-serif"]),
    ("fig-63-velocity", {"layers": ["mechanism", "velocity"], "unit": "m", "height": 500},
     ["--layers=mechanism,velocity", "--unit=m", "--height=500"]),
    ("ng-fig-7-calibration", {"fit": "origin"}, ["--fit=origin"]),
    ("inversion-2-rotating-block", {"angle": 40}, ["--angle=40"]),
]


@pytest.mark.parametrize("name,options,flags", CASES)
def test_figure_svg_is_the_command_lines(
    cli: Cli, name: str, options: Dict[str, Any], flags: List[str]
) -> None:
    assert sc.figure(name, **options).svg == cli.stdout(["figure", name, *flags])


def test_engine_figure_draws_that_engine(cli: Cli) -> None:
    engine = sc.SliderCrank(25, 72, 10, unit="mm", force_unit="N")
    want = cli.stdout(["figure", "fig-67-example", "--crank=25.0", "--rod=72.0",
                       "--offset=10.0", "--unit=mm", "--force-unit=N", "--angle=60",
                       "--omega=3"])
    got = engine.figure("fig-67-example", angle=60, omega=3)
    assert got.svg == want
    assert got._repr_svg_() == want


@pytest.mark.parametrize("ext", ["svg", "png", "pdf", "tex"])
def test_saved_files_are_the_command_lines(cli: Cli, tmp_path: Path, ext: str) -> None:
    ours, theirs = tmp_path / f"ours.{ext}", tmp_path / f"theirs.{ext}"
    sc.figure("fig-66-kisch", angle=200).save(ours)
    cli.stdout(["figure", "fig-66-kisch", "--angle=200", f"--out={theirs}"])
    assert ours.read_bytes() == theirs.read_bytes()
    f = sc.figure("fig-66-kisch", angle=200)
    if ext == "png":
        assert f.png() == theirs.read_bytes()
    if ext == "pdf":
        assert f.pdf()[:5] == b"%PDF-"


@pytest.mark.parametrize("standalone", [False, True])
def test_tikz_is_the_command_lines(cli: Cli, tmp_path: Path, standalone: bool) -> None:
    theirs = tmp_path / "theirs.tex"
    flags = ["--tikz-standalone"] if standalone else []
    cli.stdout(["figure", "fig-65-klein", "--angle=130", "--style=handout", f"--out={theirs}", *flags])
    ours = sc.figure("fig-65-klein", angle=130, style="handout").tikz(standalone=standalone)
    assert ours == theirs.read_text()
    assert ("\\documentclass" in ours) == standalone
    assert "\\begin{tikzpicture}" in ours and "{$G$}" in ours


def test_a_figure_not_drawn_by_figure_has_no_tikz() -> None:
    with pytest.raises(ValueError, match="no TikZ"):
        sc.Figure("<svg/>").tikz()


def test_every_named_figure_draws() -> None:
    assert "fig-66-kisch" in sc.FIGURES and len(sc.FIGURES) >= 20
    for name in sc.FIGURES:
        svg = sc.figure(name).svg
        assert svg.startswith("<svg") or svg.startswith("<?xml"), name


def test_gallery_is_the_command_lines(cli: Cli, tmp_path: Path) -> None:
    names = sc.gallery(tmp_path / "py", only=["fig-66-kisch", "ng-fig-1-torque"])
    cli.stdout(["gallery", "--only=fig-66-kisch,ng-fig-1-torque", f"--out={tmp_path / 'cli'}"])
    written = sorted(p.name for p in (tmp_path / "cli").iterdir())
    assert sorted(names) == written and "index.html" in names
    for name in names:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    with pytest.raises(ValueError, match="fig-66-kisch"):
        sc.gallery(tmp_path / "x", only="fig-99")


def test_a_manifest_and_the_check_are_the_command_lines(cli: Cli, tmp_path: Path) -> None:
    manifest = tmp_path / "book.toml"
    manifest.write_text('figures = ["fig-66-kisch"]\nformats = ["svg"]\n', encoding="utf-8")
    names = sc.gallery(tmp_path / "py", manifest=manifest)
    cli.stdout(["gallery", f"--manifest={manifest}", f"--out={tmp_path / 'cli'}"])
    assert names == ["fig-66-kisch.svg"] + names[1:] and "fig-66-kisch.png" not in names
    assert sorted(names) == sorted(p.name for p in (tmp_path / "cli").iterdir())
    for name in names:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    # The gallery just written holds what the manifest asks for; a file
    # changed, one removed and one left staged are found, as --check finds them.
    assert sc.gallery_differences(tmp_path / "py", manifest=manifest) == []
    (tmp_path / "py" / "fig-66-kisch.svg").write_text("<svg/>", encoding="utf-8")
    (tmp_path / "py" / "index.html").unlink()
    (tmp_path / "py" / ".slider-crank-gallery-x").write_text("", encoding="utf-8")
    found = sc.gallery_differences(tmp_path / "py", manifest=manifest)
    said = cli.run(["gallery", f"--manifest={manifest}", f"--out={tmp_path / 'py'}", "--check"])
    assert said.returncode == 1
    assert [f"{p} {w}" for p, w in found] == said.stdout.decode().splitlines()
    assert [(Path(p).name, w.split(" (")[0]) for p, w in found] == [
        ("fig-66-kisch.svg", "differs"),
        ("index.html", "is missing"),
        (".slider-crank-gallery-x", "is left by an interrupted gallery"),
    ]
    with pytest.raises(ValueError, match="only= .*manifest= or only=, not both"):
        sc.gallery(tmp_path / "x", only="fig-66-kisch", manifest=manifest)
    assert not (tmp_path / "x").exists()


@pytest.mark.parametrize("ext", ["svg", "html"])
def test_animation_is_the_command_lines(cli: Cli, tmp_path: Path, ext: str) -> None:
    theirs = tmp_path / f"cli.{ext}"
    cli.stdout(["animate", "fig-63-velocity", "--frames=4", "--period=2", "--angle=10",
                "--style=handout", f"--out={theirs}"])
    ours = tmp_path / f"py.{ext}"
    text = sc.animate("fig-63-velocity", ours, frames=4, period=2, angle=10, style="handout")
    assert ours.read_bytes() == theirs.read_bytes()
    assert text == theirs.read_text(encoding="utf-8")
    assert sc.animate("fig-63-velocity", frames=4, period=2, angle=10, style="handout",
                      html=ext == "html") == text


def test_animation_errors(cli: Cli, tmp_path: Path) -> None:
    cases: List[Tuple[List[str], Callable[[], str]]] = [
        (["fig-61-centrodes", f"--out={tmp_path / 'a.svg'}"],
         lambda: sc.animate("fig-61-centrodes", tmp_path / "a.svg")),
        (["fig-66-kisch", f"--out={tmp_path / 'a.gif'}"],
         lambda: sc.animate("fig-66-kisch", tmp_path / "a.gif")),
        (["fig-66-kisch", "--frames=1", f"--out={tmp_path / 'a.svg'}"],
         lambda: sc.animate("fig-66-kisch", tmp_path / "a.svg", frames=1)),
    ]
    for args, call in cases:
        message = cli.error(["animate", *args])
        with pytest.raises(ValueError) as caught:
            call()
        assert str(caught.value) == message
    assert list(tmp_path.iterdir()) == []


def test_a_count_of_frames_no_machine_integer_holds_is_refused_as_one_out_of_range(
        cli: Cli, tmp_path: Path) -> None:
    # The command line cannot be given -1 frames (its parser refuses the
    # text); the package can, and refuses it with the library's line for a
    # count out of range, as it refuses 1 frame: a ValueError, not Python's
    # OverflowError from the conversion.
    one = cli.error(["animate", "fig-66-kisch", "--frames=1", f"--out={tmp_path / 'a.svg'}"])
    assert one.startswith("frames = 1 is out of range: ")
    for n in (-1, -1000):
        with pytest.raises(ValueError) as caught:
            sc.animate("fig-66-kisch", tmp_path / "a.svg", frames=n)
        assert str(caught.value) == one.replace("frames = 1 ", f"frames = {n} ")
    # From 2⁶⁴ up (and below −2⁶³), the same refusal of the number given.
    reason = one.split(" is out of range: ")[1]
    for n in (2**64, 2**200, -(2**200), 10**400):
        with pytest.raises(ValueError) as caught:
            sc.animate("fig-66-kisch", tmp_path / "a.svg", frames=n)
        assert str(caught.value).startswith("frames = "), n
        assert str(caught.value).endswith(f" is out of range: {reason}"), n
    assert list(tmp_path.iterdir()) == []
