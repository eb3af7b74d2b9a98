"""Every key of the JSON the library writes has its attribute in the
package's classes, holding the value the JSON holds: a key the library
adds that a class forgets (or one it drops), or a value a class reads
from the wrong key, fails here. The classes keep the JSON's names but
where a renaming below says otherwise."""

import dataclasses
from typing import Any, Callable, Dict, Iterator, List, Tuple

import pytest

import slider_crank as sc

Path = Tuple[str, ...]

#: The JSON paths a class holds under another name (its attribute path).
RENAMED: Dict[Path, Path] = {
    ("mechanism", "crank"): ("crank",),
    ("mechanism", "rod"): ("rod",),
    ("mechanism", "offset"): ("offset",),
    ("dynamics", "rod", "equivalent", "torque"): ("dynamics", "rod", "equivalent_torque"),
    ("dynamics", "rod", "dynamical", "mass_at_crosshead"):
        ("dynamics", "rod", "dynamical_mass_at_crosshead"),
    ("dynamics", "rod", "dynamical", "torque"): ("dynamics", "rod", "dynamical_torque"),
}

#: Objects a class flattens into its parent (their keys are the parent's).
FLATTENED: List[Path] = [
    ("dynamics", "rod", "equivalent"),
    ("dynamics", "rod", "dynamical"),
    ("turn",),
]

#: A null object whose flattened keys are each ``None`` in the class.
NULL_FLATTENED: Dict[Path, List[Path]] = {
    ("dynamics", "rod", "dynamical"): [
        ("dynamics", "rod", n)
        for n in ("percussion_distance", "dynamical_mass_at_crosshead",
                  "mass_at_percussion", "dynamical_torque")
    ],
}


def leaves(value: Any, path: Path = ()) -> Iterator[Tuple[Path, Any]]:
    """Every value of a JSON object that is not itself an object, by
    its path of keys (a list is one value)."""
    if isinstance(value, dict) and value:
        for key, v in value.items():
            yield from leaves(v, path + (key,))
    else:
        yield path, value


def attribute_path(path: Path) -> Path:
    """Where a class holds the JSON's value at ``path``."""
    if path in RENAMED:
        return RENAMED[path]
    if path[-1] == "at_infinity":
        return path[:-1] + ("direction",)
    for flat in FLATTENED:
        if path[: len(flat)] == flat and len(path) > len(flat):
            return path[: len(flat) - 1] + path[len(flat):]
    return path


def held(obj: Any, path: Path) -> Any:
    for key in path:
        obj = obj[key] if isinstance(obj, dict) else getattr(obj, key)
    return obj


def plain(value: Any) -> Any:
    """A class's value as JSON writes it: tuples as lists, a class of
    the package as the object of its fields."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {f.name: plain(getattr(value, f.name)) for f in dataclasses.fields(value)}
    if isinstance(value, (tuple, list)):
        return [plain(v) for v in value]
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    return value


def every_key_is_held(obj: Any, json: Dict[str, Any]) -> int:
    """Asserts every value of ``json`` is ``obj``'s at its path; the
    number of values compared."""
    count = 0
    for path, value in leaves(json):
        if path and path[-1] == "indeterminate":
            assert isinstance(held(obj, path[:-1]), sc.Indeterminate), path
        elif value is None and path in NULL_FLATTENED:
            for p in NULL_FLATTENED[path]:
                assert held(obj, p) is None, p
        else:
            where = attribute_path(path)
            try:
                got = held(obj, where)
            except (AttributeError, KeyError) as e:
                raise AssertionError(f"the JSON's {'.'.join(path)} has no attribute {where}") from e
            assert plain(got) == value, (path, got, value)
        count += 1
    return count


ENGINE = sc.SliderCrank(0.5, 3.0, 0.1)
HEAVY: Dict[str, Any] = dict(mass=10.0, rod_mass=4.0, rod_cg=1.2, rod_gyration=1.1, gas_force=250.0)
ANALYSES: List[Callable[[], sc.Analysis]] = [
    lambda: ENGINE.at(30),
    # D at infinity, every centre of an in-line engine at 90°.
    lambda: sc.SliderCrank(0.5, 3.0).at(90),
    lambda: ENGINE.at(200, rpm=300, torque=12.0, friction=0.1),
    lambda: ENGINE.at(75, **HEAVY),
    lambda: ENGINE.at(75, gravity="towards-crank", friction=0.05, **HEAVY),
    # The rod's centre of mass at the cross-head: no true dynamical system.
    lambda: ENGINE.at(10, mass=10.0, rod_mass=4.0, rod_cg=0.0, rod_gyration=1.0),
]


@pytest.mark.parametrize("call", ANALYSES)
def test_every_key_of_analyze_is_an_attribute_holding_its_value(call: Callable[[], sc.Analysis]) -> None:
    a = call()
    assert every_key_is_held(a, a.to_dict()) > 20


def captured(monkeypatch: pytest.MonkeyPatch, cls: Any) -> List[str]:
    """The JSON texts ``cls._from_json`` is given from now on."""
    texts: List[str] = []
    read = cls._from_json.__func__

    def keep(c: Any, text: str) -> Any:
        texts.append(text)
        return read(c, text)

    monkeypatch.setattr(cls, "_from_json", classmethod(keep))
    return texts


READ_FROM_TEXT: List[Tuple[Any, Callable[[], Any]]] = [
    (sc.TurningMoment, lambda: ENGINE.turning_moment(mass=10.0, fluctuation=0.02)),
    (sc.TurningMoment, lambda: ENGINE.turning_moment(phases=[0, 180], **HEAVY)),
    (sc.InlineBalance, lambda: sc.balance([0, 90, 270, 180], [0, 1, 2, 3], n=4)),
    (sc.RadialBalance, lambda: sc.radial([0, 72, 144, 216, 288], n=3.5)),
]


@pytest.mark.parametrize("cls,call", READ_FROM_TEXT)
def test_every_key_of_a_json_text_is_an_attribute_holding_its_value(
        monkeypatch: pytest.MonkeyPatch, cls: Any, call: Callable[[], Any]) -> None:
    import json

    texts = captured(monkeypatch, cls)
    obj = call()
    assert len(texts) == 1
    assert every_key_is_held(obj, json.loads(texts[0])) > 5


def test_a_forgotten_key_is_found() -> None:
    # The check itself: a key the class does not hold, or holds another
    # value for, fails it.
    a = ENGINE.at(30)
    json = a.to_dict()
    json["analytic"]["jerk"] = 1.0
    with pytest.raises(AssertionError, match="analytic.jerk"):
        every_key_is_held(a, json)
    json = a.to_dict()
    json["analytic"]["velocity"] += 1.0
    with pytest.raises(AssertionError):
        every_key_is_held(a, json)
