"""The package's namespace is its API: ``dir(slider_crank)``'s public
names are ``__all__``, none of them a module or a name imported for the
implementation; and a result computed at a speed nobody gave says so."""

from __future__ import annotations

import inspect
import math
import pickle
import types

import numpy as np

import slider_crank as sc


def public_names() -> set[str]:
    return {n for n in dir(sc) if not n.startswith("_")}


def test_the_public_names_are_all_and_nothing_else() -> None:
    assert public_names() == set(sc.__all__)
    assert len(sc.__all__) == len(set(sc.__all__))
    for leaked in ("np", "npt", "json", "os", "numbers", "Any", "Dict", "Optional",
                   "dataclass", "field", "annotations"):
        assert not hasattr(sc, leaked), leaked


def test_no_public_name_is_a_module_or_an_import() -> None:
    for name in sc.__all__:
        item = getattr(sc, name)
        assert not isinstance(item, types.ModuleType), name
        if inspect.isclass(item) or inspect.isfunction(item):
            # defined by the package, and said to be the package's
            assert item.__module__ == "slider_crank", (name, item.__module__)
            assert item.__name__ == name


def test_the_classes_are_named_and_pickled_as_the_packages() -> None:
    assert repr(sc.SliderCrank) == "<class 'slider_crank.SliderCrank'>"
    assert sc.SliderCrank.at.__module__ == "slider_crank"
    pose = sc.SliderCrank(0.5, 3.0).at(30, rpm=250)
    assert pickle.loads(pickle.dumps(pose.analytic)) == pose.analytic


ENGINE = sc.SliderCrank(0.5, 3.0)


def test_a_speed_assumed_is_said_in_the_result() -> None:
    assumed = ENGINE.at(30)
    assert assumed.assumed_rpm == 250.0
    assert math.isclose(assumed.omega, 250 * 2 * math.pi / 60)
    assert "assumed_rpm=250.0" in repr(assumed)
    assert ENGINE.sweep([10, 20]).assumed_rpm == 250.0
    assert ENGINE.inversion(2).at(30).assumed_rpm == 250.0
    assert sc.QuadricChain(1, 3, 2.5, 3).at(30).assumed_rpm == 250.0
    assert ENGINE.curved_slot(2.0).at(30).assumed_rpm == 250.0


def test_a_speed_given_is_not_said_to_be_assumed() -> None:
    for pose in (ENGINE.at(30, rpm=250), ENGINE.at(30, omega=1.0),
                 ENGINE.at(30, rpm=250, mass=10)):
        assert pose.assumed_rpm is None
        assert "assumed_rpm=None" in repr(pose)
    assert ENGINE.sweep(np.arange(3.0), omega=2.0).assumed_rpm is None
    assert sc.QuadricChain(1, 3, 2.5, 3).at(30, rpm=60).assumed_rpm is None
    # the same values either way: the JSON is the command line's
    assert ENGINE.at(30) == ENGINE.at(30, rpm=250)
    assert ENGINE.at(30).to_dict() == ENGINE.at(30, rpm=250).to_dict()
    assert "assumed_rpm" not in ENGINE.at(30).to_dict()


def test_the_polygons_read_the_exact_values() -> None:
    pose = ENGINE.at(45, rpm=250)
    p = pose.polygons
    assert math.isclose(p["slider_velocity"], pose.analytic.velocity, rel_tol=1e-12)
    assert math.isclose(p["slider_acceleration"], pose.analytic.acceleration, rel_tol=1e-12)
    assert math.isclose(
        p["rod_angular_velocity"], pose.analytic.rod_angular_velocity, rel_tol=1e-12
    )
    assert p["coupler"] == 0.5
    assert pose.to_dict()["polygons"] == p
    for construction in (pose.ritterhaus, pose.bennett):
        assert construction is not None
        assert math.isclose(
            construction["acceleration"], pose.analytic.acceleration, rel_tol=1e-12
        )
    assert sc.SliderCrank(1.0, 4.0, 0.5).at(30, rpm=250).bennett is None


def test_the_polygons_carry_the_images_of_a_point_off_the_rod() -> None:
    # Q = A + t (B - A) + h J(B - A), J a quarter turn counter-clockwise:
    # its velocity is omega dQ/dtheta, here by central differences.
    r, l, e, w = 1.0, 4.0, 0.5, 10.0

    def point(th: float, t: float, h: float) -> tuple[float, float]:
        wx = math.sqrt(l * l - (r * math.sin(th) - e) ** 2)
        ax, ay = r * math.cos(th) + wx, e
        bx, by = r * math.cos(th), r * math.sin(th)
        dx, dy = bx - ax, by - ay
        return ax + t * dx - h * dy, ay + t * dy + h * dx

    for deg in (0.0, 45.0, 90.0, 200.0):
        off = sc.SliderCrank(r, l, e).at(deg, omega=w).polygons["off_rod"]
        t, h = off["along"], off["across"]
        assert (t, h) == (0.5, 0.25)
        th, d = math.radians(deg), 1e-5
        ahead, behind = point(th + d, t, h), point(th - d, t, h)
        for k in (0, 1):
            rate = w * (ahead[k] - behind[k]) / (2 * d)
            assert abs(off["velocity"][k] - rate) <= 1e-6 * w
