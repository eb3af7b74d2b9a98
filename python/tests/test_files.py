"""Files are written as the command line writes them, by the library's
writer: staged under an unpredictable temporary name in the target's
directory and renamed into place, a symbolic link at the target kept (its
target written), and a sheet never left without its key."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Callable, List, Tuple

import pytest

import slider_crank as sc

ENGINE = sc.SliderCrank(0.5, 3.0)

# Each call writes HTML or SVG text to the path it is given (a name of
# that kind), through the package's one writer.
WRITERS: List[Tuple[str, Callable[[Path], object]]] = [
    ("page.html", lambda p: ENGINE.handout(45, rpm=250, out=p)),
    ("sheet.html", lambda p: ENGINE.exercise(45, rpm=250, out=p)),
    ("a.svg", lambda p: sc.animate("fig-63-velocity", p, frames=2)),
]


def left_behind(folder: Path, expected: List[str]) -> List[str]:
    return sorted(set(os.listdir(folder)) - set(expected))


@pytest.mark.parametrize("name,write", WRITERS)
def test_a_link_planted_at_the_old_temporary_name_is_not_followed(
    tmp_path: Path, name: str, write: Callable[[Path], object]
) -> None:
    # The package once wrote `{target}.{pid}.tmp`: a link planted there
    # had the page written into the file it pointed to.
    victim = tmp_path / "victim.txt"
    victim.write_text("keep me")
    target = tmp_path / name
    planted = Path(f"{target}.{os.getpid()}.tmp")
    planted.symlink_to(victim)
    write(target)
    assert victim.read_text() == "keep me"
    assert planted.is_symlink() and os.readlink(planted) == str(victim)
    assert target.is_file() and not target.is_symlink()
    assert target.read_text().lstrip().startswith("<")


def test_a_directory_at_the_old_temporary_name_is_no_obstacle(tmp_path: Path) -> None:
    target = tmp_path / "page.html"
    Path(f"{target}.{os.getpid()}.tmp").mkdir()
    html = ENGINE.handout(45, rpm=250, out=target)
    assert target.read_text() == html


@pytest.mark.parametrize("name,write", WRITERS)
def test_a_link_at_the_target_is_kept_and_its_target_written(
    tmp_path: Path, name: str, write: Callable[[Path], object]
) -> None:
    real = tmp_path / name
    real.write_text("old")
    link = tmp_path / ("link" + real.suffix)
    link.symlink_to(name)
    write(link)
    assert link.is_symlink() and os.readlink(link) == name
    assert real.read_text() != "old" and real.read_text().lstrip().startswith("<")
    # no temporary file is left beside them
    assert left_behind(tmp_path, [name, link.name, "link-key.html"]) == []


def test_a_figure_saved_through_a_link_keeps_it(tmp_path: Path) -> None:
    real = tmp_path / "real.svg"
    real.write_text("old")
    link = tmp_path / "link.svg"
    link.symlink_to("real.svg")
    sc.figure("fig-63-velocity").save(link)
    assert link.is_symlink() and real.read_text().startswith("<svg")


def test_an_exercise_whose_key_cannot_be_written_leaves_no_sheet(tmp_path: Path) -> None:
    sheet = tmp_path / "sheet.html"
    (tmp_path / "sheet-key.html").mkdir()  # the key's name is taken by a folder
    with pytest.raises(OSError, match="sheet-key.html: it is a directory"):
        ENGINE.exercise(45, rpm=250, out=sheet)
    assert not sheet.exists()
    assert left_behind(tmp_path, ["sheet-key.html"]) == []


def test_an_exercise_whose_key_is_write_protected_keeps_the_old_sheet(tmp_path: Path) -> None:
    sheet = tmp_path / "sheet.html"
    sheet.write_text("the old sheet")
    key = tmp_path / "sheet-key.html"
    key.write_text("the old key")
    key.chmod(0o444)
    with pytest.raises(OSError, match="sheet-key.html: it is write-protected"):
        ENGINE.exercise(45, rpm=250, out=sheet)
    assert sheet.read_text() == "the old sheet"
    assert key.read_text() == "the old key"
    assert left_behind(tmp_path, ["sheet.html", "sheet-key.html"]) == []


def test_an_exercise_in_a_missing_folder_writes_nothing(tmp_path: Path) -> None:
    with pytest.raises(OSError, match="does not exist"):
        ENGINE.exercise(45, rpm=250, out=tmp_path / "no" / "sheet.html")
    assert os.listdir(tmp_path) == []


def test_an_exercise_writes_the_sheet_and_its_key(tmp_path: Path) -> None:
    sheet, key = ENGINE.exercise(45, rpm=250, out=tmp_path / "sheet.html")
    assert (tmp_path / "sheet.html").read_text() == sheet
    assert (tmp_path / "sheet-key.html").read_text() == key
    assert sorted(os.listdir(tmp_path)) == ["sheet-key.html", "sheet.html"]


def test_an_exercise_refuses_a_link_planted_at_its_key(tmp_path: Path) -> None:
    # The key's name is derived from `out`: a link planted there would have
    # its target, anywhere, replaced by the key (as `handout --exercise`
    # refuses it).
    victim = tmp_path / "victim.txt"
    victim.write_text("keep me")
    (tmp_path / "sheet-key.html").symlink_to(victim)
    sheet = tmp_path / "sheet.html"
    with pytest.raises(ValueError, match="cannot write .*sheet-key.html: it is a symbolic link"):
        ENGINE.exercise(45, rpm=250, out=sheet)
    assert victim.read_text() == "keep me"
    assert not sheet.exists()
    assert left_behind(tmp_path, ["victim.txt", "sheet-key.html"]) == []


GALLERY = ["fig-63-velocity"]


def gallery_names(tmp_path: Path) -> List[str]:
    return sc.gallery(tmp_path / "first", only=GALLERY)


def test_a_gallery_that_cannot_be_written_whole_leaves_the_old_one(tmp_path: Path) -> None:
    # The last file of the gallery (index.html) cannot be written: the
    # package once wrote every figure and table before failing on it, a
    # gallery half new; now nothing is made and the old files stay.
    names = gallery_names(tmp_path)
    out = tmp_path / "g"
    out.mkdir()
    for name in names[:-1]:
        (out / name).write_text("old")
    (out / names[-1]).mkdir()
    with pytest.raises(OSError, match=f"{names[-1]}: it is a directory"):
        sc.gallery(out, only=GALLERY)
    for name in names[:-1]:
        assert (out / name).read_text() == "old", name
    assert left_behind(out, names) == []


def test_a_gallery_replaces_a_link_at_its_names_and_keeps_its_target(tmp_path: Path) -> None:
    # As `slider-crank gallery` writes: a link of a gallery's name is
    # replaced by the file, never followed to write elsewhere.
    names = gallery_names(tmp_path)
    victim = tmp_path / "victim.svg"
    victim.write_text("keep me")
    out = tmp_path / "g"
    out.mkdir()
    (out / names[0]).symlink_to(victim)
    sc.gallery(out, only=GALLERY)
    assert victim.read_text() == "keep me"
    assert not (out / names[0]).is_symlink()
    assert (out / names[0]).read_bytes() == (tmp_path / "first" / names[0]).read_bytes()
    assert sorted(os.listdir(out)) == sorted(names)


def test_a_gallery_removes_what_a_killed_gallery_left(tmp_path: Path) -> None:
    out = tmp_path / "g"
    out.mkdir()
    (out / ".slider-crank-gallery-x").write_text("staged by a killed gallery")
    names = sc.gallery(out, only=GALLERY)
    assert sorted(os.listdir(out)) == sorted(names)
