"""The options of ``figure``, one table for every front end
(``tests/options/figure.csv``, which the command line's tests read too):
each keyword of :func:`slider_crank.figure` does what the flag of its
name does with the same value: the figure's own bytes at its default, the
command line's figure, or the command line's refusal in the package's
words (its flags spelt as keywords)."""

from __future__ import annotations

import csv
import inspect
import json
import re
from typing import Any, Callable, Dict, List, Set

import pytest

import slider_crank as sc
from conftest import REPO, Cli, keywords

with open(REPO / "tests/options/figure.csv", newline="", encoding="utf-8") as _f:
    CASES: List[Dict[str, str]] = list(csv.DictReader(_f))

#: The keywords whose values are numbers.
NUMBERS = {"crank", "rod", "offset", "angle", "rpm", "omega", "mass", "fluctuation", "bore",
           "gas_force", "rod_mass", "rod_cg", "rod_gyration", "friction"}


def value(case: Dict[str, str]) -> Any:
    """The case's value as the keyword takes it."""
    keyword, text = case["keyword"], case["value"]
    if keyword in NUMBERS:
        return float(text)
    if keyword == "mirror":
        return text == "true"
    if keyword == "data":
        return REPO / text
    if keyword == "coupler":
        t, _, h = text.partition(",")
        return (float(t), float(h)) if h else float(t)
    return text


def flag(case: Dict[str, str]) -> str:
    """The case's value as the command line takes it."""
    if case["flag"] == "--mirror":
        return "--mirror" if case["value"] == "true" else "--no-mirror"
    if case["flag"] == "--projector":
        return "--projector"
    return f"{case['flag']}={case['value']}"


def test_every_keyword_of_figure_is_in_the_table() -> None:
    assert_keywords_are_the_tables(sc.figure, {"name"}, CASES)


@pytest.mark.parametrize("case", CASES, ids=lambda c: f"{c['figure']} {flag(c)}")
def test_a_keyword_does_as_its_flag(cli: Cli, case: Dict[str, str]) -> None:
    name = case["figure"]
    args = ["figure", name, flag(case)]
    if case["outcome"] == "refused":
        message = keywords(cli.error(args))
        with pytest.raises(ValueError) as caught:
            sc.figure(name, **{case["keyword"]: value(case)})
        assert str(caught.value) in message, (str(caught.value), message)
        return
    svg = sc.figure(name, **{case["keyword"]: value(case)}).svg
    assert svg == cli.stdout(args)
    if case["outcome"] == "default":
        assert svg == sc.figure(name).svg


with open(REPO / "tests/options/table.csv", newline="", encoding="utf-8") as _f:
    TABLE_CASES: List[Dict[str, str]] = list(csv.DictReader(_f))

#: The keywords of :func:`slider_crank.table` whose values are lists of
#: numbers, whole numbers, and text (the rest are numbers).
LISTS = {"n", "angles", "cranks", "planes", "fractions", "axes", "phases"}
COUNTS = {"decimals", "order", "inversion", "max_cells"}
TEXTS = {"format", "unit", "force_unit", "indicator", "gravity"}


def table_value(keyword: str, text: str) -> Any:
    """A table option's value as the keyword takes it."""
    if keyword in LISTS:
        return [float(x) for x in text.split(",")]
    if keyword in COUNTS:
        return int(text)
    if keyword in TEXTS:
        return text
    return float(text)


def keywords_of(flags: List[str], value_of: Callable[[str, str], Any]) -> Dict[str, Any]:
    """The keywords of the flags ``--flag=value`` (a switch ``--flag``
    alone is its keyword's True, ``--no-flag`` its False), each value
    ``value_of(keyword, text)``."""
    out = {}
    for f in flags:
        flag, given, text = f.partition("=")
        keyword = flag[2:].replace("-", "_")
        if not given:
            negated = keyword.startswith("no_")
            out[keyword[3:] if negated else keyword] = not negated
            continue
        out[keyword] = value_of(keyword, text)
    return out


def table_keywords(flags: List[str]) -> Dict[str, Any]:
    """The keywords of ``table``'s flags."""
    return keywords_of(flags, table_value)


def assert_keywords_are_the_tables(function: Callable[..., Any], places: Set[str],
                                   cases: List[Dict[str, str]]) -> None:
    """Every keyword of ``function`` but ``places`` is an option of the
    table ``cases``, and every option of the table a keyword of it, named
    after its flag."""
    named = set(inspect.signature(function).parameters) - places
    assert named == {c["keyword"] for c in cases}
    for case in cases:
        assert case["keyword"] == case["flag"][2:].replace("-", "_"), case


def assert_refused_alike(message: str, caught: BaseException, value: str) -> None:
    """The package's refusal is the command line's ``message`` in its
    words; where the command line's parser refused the value (clap's
    ``invalid value '…'``), the package names the value in the library's
    words (or in the parser's own, which name the library's)."""
    said = str(caught)
    if "invalid value '" in message:
        assert value in said or said in message, (said, message)
    else:
        assert said in message, (said, message)


def test_every_keyword_of_table_is_in_the_table() -> None:
    assert_keywords_are_the_tables(sc.table, {"name"}, TABLE_CASES)


@pytest.mark.parametrize(
    "case", TABLE_CASES,
    ids=lambda c: f"{c['table']} {c['with']} {c['flag']}={c['value'][:20]}",
)
def test_a_table_keyword_does_as_its_flag(
    cli: Cli, case: Dict[str, str], monkeypatch: pytest.MonkeyPatch
) -> None:
    # The paths of the table are the repository's, as the command line's.
    monkeypatch.chdir(REPO)
    name, given = case["table"], case["with"].split()
    flags = [*given, f"{case['flag']}={case['value']}"]
    options = table_keywords(flags)
    args = ["table", name, *flags]
    if case["outcome"] == "refused":
        message = keywords(cli.error(args))
        with pytest.raises((ValueError, OSError)) as caught:
            sc.table(name, **options)
        assert_refused_alike(message, caught.value, case["value"])
        return
    text = sc.table(name, **options)
    assert text == cli.stdout(args)
    if case["outcome"] == "default":
        assert text == sc.table(name, **table_keywords(given))


with open(REPO / "tests/options/analyze.csv", newline="", encoding="utf-8") as _f:
    ANALYZE_CASES: List[Dict[str, str]] = list(csv.DictReader(_f))

#: The keywords of the request of ``analyze`` whose values are whole
#: numbers, text, and the four links (the rest are numbers).
ANALYZE_COUNTS = {"inversion", "max_cells"}
ANALYZE_TEXTS = {"unit", "force_unit", "indicator", "assembly", "gravity"}


def analyze_value(keyword: str, text: str) -> Any:
    """An option of ``analyze`` as the keyword takes it."""
    if keyword == "links":
        return tuple(float(x) for x in text.split(","))
    if keyword in ANALYZE_COUNTS:
        return int(text)
    if keyword in ANALYZE_TEXTS:
        return text
    return float(text)


def analyze_keywords(flags: List[str]) -> Dict[str, Any]:
    """The keywords of ``analyze``'s flags."""
    return keywords_of(flags, analyze_value)


def test_every_keyword_of_analyze_is_in_the_table() -> None:
    # The package's classes fill the request of ``analyze`` through the
    # native ``analyze`` (SliderCrank.at, its curved_slot and inversion,
    # QuadricChain.at): every keyword of it is an option of the table.
    assert_keywords_are_the_tables(sc._core.analyze, set(), ANALYZE_CASES)


@pytest.mark.parametrize(
    "case", ANALYZE_CASES, ids=lambda c: f"{c['with']} {c['flag']}={c['value']}"
)
def test_an_analyze_keyword_does_as_its_flag(
    cli: Cli, case: Dict[str, str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(REPO)
    given = case["with"].split()
    flags = [*given, f"{case['flag']}={case['value']}"]
    options = analyze_keywords(flags)
    args = ["analyze", "--json", *flags]
    if case["outcome"] == "refused":
        message = keywords(cli.error(args))
        with pytest.raises((ValueError, OSError)) as caught:
            sc._core.analyze(**options)
        assert_refused_alike(message, caught.value, case["value"])
        return
    got = json.loads(sc._core.analyze(**options))
    assert got == json.loads(cli.stdout(args))
    if case["outcome"] == "default":
        assert got == json.loads(sc._core.analyze(**analyze_keywords(given)))


with open(REPO / "tests/options/animate.csv", newline="", encoding="utf-8") as _f:
    ANIMATE_CASES: List[Dict[str, str]] = list(csv.DictReader(_f))

#: The keywords of :func:`slider_crank.animate` that are not options of
#: the table: the figure, and where and in which format the animation
#: goes (``--out``).
ANIMATE_PLACES = {"name", "out", "html"}


def animate_value(keyword: str, text: str) -> Any:
    """An option of ``animate`` as the keyword takes it: a figure's as
    :func:`figure` takes it (:func:`value`)."""
    if keyword == "frames":
        return int(text)
    if keyword == "period":
        return float(text)
    return value({"keyword": keyword, "value": text})


def animate_keywords(flags: List[str]) -> Dict[str, Any]:
    """The keywords of ``animate``'s flags."""
    return keywords_of(flags, animate_value)


def test_every_keyword_of_animate_is_in_the_table() -> None:
    assert_keywords_are_the_tables(sc.animate, ANIMATE_PLACES, ANIMATE_CASES)


def test_animate_s_defaults_are_the_command_line_s(cli: Cli) -> None:
    # The defaults `animate --help` states are the package's keywords'.
    help = cli.stdout(["animate", "--help"])
    given = inspect.signature(sc.animate).parameters
    for keyword, value_of in (("frames", int), ("period", float)):
        stated = re.search(rf"--{keyword} <\w+>.*?\[default: ([^\]]+)\]", help, re.S)
        assert stated is not None, keyword
        assert given[keyword].default == value_of(stated.group(1)), keyword
    assert given["frames"].default == sc._core.DEFAULT_FRAMES
    assert given["period"].default == sc._core.DEFAULT_PERIOD
    # A switch is off unless given.
    assert given["projector"].default is False and "--no-projector" not in help


@pytest.mark.parametrize(
    "case", ANIMATE_CASES,
    ids=lambda c: f"{c['figure']} {c['with'][:20]} {flag(c)}",
)
def test_an_animate_keyword_does_as_its_flag(cli: Cli, case: Dict[str, str]) -> None:
    name, given = case["figure"], case["with"].split()
    flags = [*given, flag(case)]
    options = animate_keywords(flags)
    args = ["animate", name, "--out=-", *flags]
    if case["outcome"] == "refused":
        message = keywords(cli.error(args))
        with pytest.raises(ValueError) as caught:
            sc.animate(name, **options)
        assert_refused_alike(message, caught.value, case["value"])
        return
    text = sc.animate(name, **options)
    assert text == cli.stdout(args)
    if case["outcome"] == "default":
        assert text == sc.animate(name, **animate_keywords(given))
