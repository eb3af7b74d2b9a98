"""`SliderCrank.sweep` against a numpy closed form, against `at`, and on
awkward arrays and many threads."""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor
from typing import Dict, Tuple

import numpy as np
import numpy.typing as npt
import pytest

import slider_crank as sc

Arrays = Dict[str, npt.NDArray[np.float64]]


def closed_form(r: float, l: float, e: float, w: float, deg: npt.NDArray[np.float64]) -> Arrays:
    """x_A = r cos θ + √(l² − s²) with s = r sin θ − e, sin φ = s / l, and
    their θ-derivatives times ω and ω²."""
    t = np.radians(deg)
    s, s1, s2 = r * np.sin(t) - e, r * np.cos(t), -r * np.sin(t)
    c = np.sqrt(l * l - s * s)
    x1 = -r * np.sin(t) - s * s1 / c
    x2 = -r * np.cos(t) - (s1 * s1 + s * s2) / c - (s * s1) ** 2 / c**3
    p1 = s1 / c
    p2 = s2 / c + s * s1 * s1 / c**3
    return {
        "position": r * np.cos(t) + c,
        "velocity": w * x1,
        "acceleration": w * w * x2,
        "rod_angle_deg": np.degrees(np.arcsin(s / l)),
        "rod_angular_velocity": w * p1,
        "rod_angular_acceleration": w * w * p2,
    }


def random_engines(n: int, seed: int) -> "list[Tuple[float, float, float, float]]":
    rng = np.random.default_rng(seed)
    engines = []
    for _ in range(n):
        r = float(10.0 ** rng.uniform(-3, 3))
        e = float(r * rng.uniform(-1, 1))
        l = float((r + abs(e)) * (1 + 10.0 ** rng.uniform(-1, 1)))
        w = float(rng.choice([-1, 1]) * 10.0 ** rng.uniform(-2, 3))
        engines.append((r, l, e, w))
    return engines


@pytest.mark.parametrize("r,l,e,w", random_engines(40, 24))
def test_sweep_agrees_with_the_closed_form(r: float, l: float, e: float, w: float) -> None:
    deg = np.random.default_rng(7).uniform(-720, 720, 2000)
    got = sc.SliderCrank(r, l, e).sweep(deg, omega=w)
    want = closed_form(r, l, e, w, deg)
    for name, expected in want.items():
        # relative to the quantity's size over the turn (a value crossing
        # zero has no relative error of its own)
        scale = np.max(np.abs(expected))
        error = np.max(np.abs(getattr(got, name) - expected)) / scale
        assert error <= 1e-13, (name, error)


def test_sweep_equals_at_value_for_value() -> None:
    engine = sc.SliderCrank(25, 72, 10, unit="mm", force_unit="N")
    deg = np.array([0.0, 30.0, 90.0, 123.456, 270.0, -45.0, 1e6])
    s = engine.sweep(deg, rpm=60, graphical=True)
    assert s.graphical is not None
    for i, d in enumerate(deg):
        a = engine.at(d, rpm=60)
        for name in ("position", "velocity", "acceleration", "rod_angle_deg",
                     "rod_angular_velocity", "rod_angular_acceleration"):
            assert getattr(s, name)[i] == getattr(a.analytic, name), (d, name)
        for name in ("velocity", "acceleration", "rod_angular_velocity",
                     "rod_angular_acceleration"):
            assert getattr(s.graphical, name)[i] == getattr(a.graphical, name), (d, name)


def test_any_array_like_any_shape() -> None:
    engine = sc.SliderCrank(0.5, 3.0)
    want = engine.sweep(np.arange(12.0) * 30, omega=2.0)
    for given in ([0, 30, 60, 90, 120, 150, 180, 210, 240, 270, 300, 330],
                  tuple(range(0, 360, 30)),
                  np.arange(0, 360, 30, dtype=np.int32),
                  np.arange(0, 360, 30, dtype=np.float32),
                  np.arange(0, 360, 15.0)[::2],  # not contiguous
                  np.arange(330, -1, -30.0)[::-1],  # a negative stride
                  np.asfortranarray(np.arange(12.0).reshape(3, 4) * 30)):
        got = engine.sweep(given, omega=2.0)
        assert np.array_equal(got.velocity.reshape(-1), want.velocity)
    grid = engine.sweep(np.arange(12.0).reshape(3, 4) * 30, omega=2.0)
    assert grid.acceleration.shape == (3, 4)
    assert np.array_equal(grid.acceleration.reshape(-1), want.acceleration)
    assert engine.sweep(45.0, omega=2.0).position.shape == ()
    assert engine.sweep([], omega=2.0).position.shape == (0,)


def test_sweep_leaves_its_input_alone() -> None:
    deg = np.arange(0.0, 360.0, 1.0)
    before = deg.copy()
    sc.SliderCrank(0.5, 3.0).sweep(deg, graphical=True)
    assert np.array_equal(deg, before)


def test_threads_sweeping_at_once_get_the_same_results() -> None:
    engines = [sc.SliderCrank(r, l, e) for r, l, e, _ in random_engines(8, 3)]
    deg = np.linspace(-360, 360, 200_001)
    alone = [m.sweep(deg, omega=3.0, graphical=True) for m in engines]
    with ThreadPoolExecutor(max_workers=8) as pool:
        together = list(pool.map(lambda m: m.sweep(deg, omega=3.0, graphical=True),
                                 engines * 3))
    for i, s in enumerate(together):
        a = alone[i % len(engines)]
        assert s.graphical is not None and a.graphical is not None
        assert np.array_equal(s.acceleration, a.acceleration)
        assert np.array_equal(s.graphical.acceleration, a.graphical.acceleration)


def test_a_long_sweep_reports_its_first_bad_angle() -> None:
    engine = sc.SliderCrank(0.5, 3.0)
    deg = np.linspace(0, 360, 100_000)
    deg[20_000], deg[70_000] = np.nan, np.inf
    with pytest.raises(ValueError) as caught:
        engine.sweep(deg)
    with pytest.raises(ValueError) as first:
        engine.at(np.nan)
    assert str(caught.value) == str(first.value)
    deg[20_000] = 1.0
    with pytest.raises(ValueError) as second:
        engine.sweep(deg, graphical=True)
    assert "inf" in str(second.value)
