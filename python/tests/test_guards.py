"""The package is held to the command line's guard on the size of a
request (``--max-cells``, the library's ``MaxCells``): a table or a check
too large is refused before any of it is computed, with the command
line's message in the keyword's spelling (``max_cells=N``)."""

from __future__ import annotations

from typing import Any, Callable, Dict, List

import numpy as np
import pytest

import slider_crank as sc
from conftest import Cli
from conftest import keywords as in_python


# (the call, the command line given the same request): each refused at
# the default bound of 50 000 000 values, without computing a row.
TOO_LARGE: List[Any] = [
    # a billion rows from ten thousand ratios (3.6 GB, then an abort,
    # before the guard)
    (lambda: sc.table("obliquity", angles=np.arange(1e5), n=list(range(2, 10002))),
     ["table", "obliquity", "--angles=0:99999:1", "--n=" + ",".join(map(str, range(2, 10002)))]),
    # ten million angles of kinematics (5.9 GB before the guard)
    (lambda: sc.table("kinematics", angles=np.arange(10**7, dtype=np.float64)),
     ["table", "kinematics", "--angles=0:9999999:1"]),
    (lambda: sc.table("acceleration-factor", angles=np.arange(10_000), n=list(range(2, 10002))),
     ["table", "acceleration-factor", "--angles=0:9999:1",
      "--n=" + ",".join(map(str, range(2, 10002)))]),
    # angles of any shape are counted one by one
    (lambda: sc.table("forces", angles=np.zeros((3000, 5000))),
     ["table", "forces", "--angles=0:14999999:1"]),
    (lambda: sc.SliderCrank(0.5, 3.0).check(samples=100_000_000),
     ["check", "--samples=100000000"]),
]


@pytest.mark.parametrize("call,args", TOO_LARGE)
def test_a_request_beyond_the_guard_is_refused_as_the_command_line_refuses_it(
    cli: Cli, call: Callable[[], Any], args: List[str]
) -> None:
    with pytest.raises(ValueError) as caught:
        call()
    message = str(caught.value)
    assert "more than max_cells=50000000: give max_cells=" in message, message
    assert message == in_python(cli.error(args))


CASES: List[Any] = [
    ("kinematics", {"angles": np.arange(100)}, ["--angles=0:99:1"], 700),
    # over several angles each row names its own θ: a column more
    ("obliquity", {"angles": [10, 20, 30], "n": [4, 5]}, ["--angles=10,20,30", "--n=4,5"], 24),
    ("acceleration-factor", {}, [], 49),
    ("dynamics", {"angles": [0, 90]}, ["--angles=0,90"], 2 * 10),
    ("balance", {"angles": np.arange(10), "cranks": [0, 120, 240]},
     ["--angles=0:9:1", "--cranks=0,120,240"], 10 * 6),
]


@pytest.mark.parametrize("name,options,flags,cells", CASES)
def test_max_cells_allows_exactly_the_request_as_the_flag_does(
    cli: Cli, name: str, options: Dict[str, Any], flags: List[str], cells: int
) -> None:
    # `cells` is the table's size: allowed at that bound, refused one below
    # with the command line's message
    assert sc.table(name, max_cells=cells, **options) == cli.stdout(
        ["table", name, *flags, f"--max-cells={cells}"]
    )
    with pytest.raises(ValueError) as caught:
        sc.table(name, max_cells=cells - 1, **options)
    expected = cli.error(["table", name, *flags, f"--max-cells={cells - 1}"])
    assert str(caught.value) == in_python(expected)
    assert f"more than max_cells={cells - 1}: give max_cells={cells} (or more)" in str(caught.value)


def test_max_cells_bounds_every_check() -> None:
    engine = sc.SliderCrank(0.5, 3.0)
    for check in (engine.check, engine.curved_slot(2.0).check,
                  sc.QuadricChain(1, 3, 2.5, 3).check):
        with pytest.raises(ValueError, match=r"check asks for 1000 poses × 16 quantities = 16000 "
                                             r"values, more than max_cells=15999"):
            check(samples=1000, max_cells=15999)
        assert check(samples=1000, max_cells=16000).rows


def test_max_cells_is_a_count() -> None:
    with pytest.raises(ValueError, match="max_cells"):
        sc.table("kinematics", max_cells=-1)
    with pytest.raises(TypeError, match="max_cells"):
        sc.table("kinematics", max_cells=1e9)  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="max_cells"):
        sc.table("kinematics", max_cells=True)
    with pytest.raises(ValueError, match="more than max_cells=0"):
        sc.table("kinematics", max_cells=0)
