"""Two-plane balance from Python (``two_plane_balance``): the balance
masses, with the masses they balance, leave neither a force nor a couple
about any plane, worked here from the returned values (not the library's
formulas); bad input is refused."""

from __future__ import annotations

import math
import random

import pytest

import slider_crank as sc


def residual(masses: list[tuple[float, float, float]], about: float) -> tuple[float, float]:
    """The size of the sum of the m r vectors and of their moments about
    the plane ``about``."""
    fx = fy = cx = cy = 0.0
    for m, a, x in masses:
        c, s = math.cos(math.radians(a)), math.sin(math.radians(a))
        fx, fy = fx + m * c, fy + m * s
        cx, cy = cx + m * (x - about) * c, cy + m * (x - about) * s
    return math.hypot(fx, fy), math.hypot(cx, cy)


def test_the_balances_leave_no_force_and_no_couple() -> None:
    rng = random.Random(39)
    for _ in range(200):
        masses = [
            (rng.uniform(0.1, 5), rng.uniform(0, 360), rng.uniform(-3, 3))
            for _ in range(rng.randint(1, 6))
        ]
        planes = (rng.uniform(-4, -0.5), rng.uniform(0.5, 4))
        balances = sc.two_plane_balance(masses, planes)
        assert [b[2] for b in balances] == list(planes)
        assert all(0 <= b[1] < 360 and b[0] >= 0 for b in balances)
        scale = sum(m for m, _, _ in masses) * 8
        for about in (0.0, 2.5):
            force, couple = residual(masses + balances, about)
            assert force < 1e-12 * scale and couple < 1e-12 * scale, (masses, balances)


def test_one_mass_between_the_planes_is_balanced_opposite_in_both() -> None:
    # A mass m r at 0° midway: half of it at 180° in each plane.
    balances = sc.two_plane_balance([(2.0, 0.0, 0.0)], (-1.0, 1.0))
    for m, a, _ in balances:
        assert m == pytest.approx(1.0) and a == pytest.approx(180.0)


def test_bad_input_is_refused() -> None:
    with pytest.raises(ValueError):
        sc.two_plane_balance([], (-1.0, 1.0))
    with pytest.raises(ValueError):
        sc.two_plane_balance([(1.0, 0.0, 0.0)], (1.0, 1.0))
    with pytest.raises(ValueError):
        sc.two_plane_balance([(math.nan, 0.0, 0.0)], (-1.0, 1.0))
