"""The slider-crank mechanism in-process: exact kinematics and statics, the
values read off the classical graphical constructions, numpy sweeps, and
textbook figures as SVG, PNG or PDF (shown inline in Jupyter).

Frame and signs (those of the command line and ``analyze --json``): the
crank centre C at the origin, the line of stroke ``y = offset``, the slider
on the +x side; the crank angle θ in degrees counter-clockwise from +x
(0: outer dead centre); a positive crank speed turns the crank
counter-clockwise. Velocities and accelerations are signed: dx_A/dt,
d²x_A/dt², dφ/dt, d²φ/dt² with sin φ = (r sin θ − e)/l. Lengths and forces
are in the units the engine names (names only: no number is converted).

Bad input raises ``ValueError`` with the message the command line prints
after ``slider-crank:`` (``OSError`` for a file that cannot be read or
written, ``TypeError`` for a value of the wrong type).

>>> import slider_crank as sc
>>> engine = sc.SliderCrank(0.5, 3.0)          # textbook §35, in ft
>>> round(engine.at(45, rpm=250).analytic.velocity, 4)
-10.3545
"""

from __future__ import annotations

import json
import numbers
import os
from dataclasses import dataclass, field
from typing import Any, Dict, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import _core

__all__ = [
    "SliderCrank",
    "Analysis",
    "Values",
    "GraphicalValues",
    "Statics",
    "AtInfinity",
    "Indeterminate",
    "Sweep",
    "GraphicalSweep",
    "Figure",
    "figure",
    "table",
    "gallery",
    "animate",
    "FIGURES",
]

__version__: str = _core.VERSION

Point = Tuple[float, float]

#: The names of the figures, as ``slider-crank figure --help`` lists them.
FIGURES: Tuple[str, ...] = tuple(_core.figure_names())


@dataclass(frozen=True)
class AtInfinity:
    """A point at infinity: where parallel lines meet (the rod's
    instantaneous centre D at θ = 90° and 270° of an in-line engine).

    ``direction`` is the unit vector (dx, dy) of those lines; the JSON of
    ``analyze`` writes it ``{"at_infinity": [dx, dy]}``.
    """

    direction: Point


@dataclass(frozen=True)
class Indeterminate:
    """A centre left anywhere on a line, where the two lines that fix it
    coincide; the JSON writes it ``{"indeterminate": true}``."""


#: A point (x, y), a point at infinity, or an indeterminate centre.
Centre = Union[Point, AtInfinity, Indeterminate]


def _centre(value: Any) -> Centre:
    if isinstance(value, list):
        return (value[0], value[1])
    if "at_infinity" in value:
        d = value["at_infinity"]
        return AtInfinity((d[0], d[1]))
    return Indeterminate()


@dataclass(frozen=True)
class Values:
    """The exact values of the analytic core at one pose: the slider's
    position x_A (length unit), velocity and acceleration (per second,
    per second squared), the rod's angle φ in degrees and its angular
    velocity and acceleration (rad/s, rad/s²)."""

    position: float
    velocity: float
    acceleration: float
    rod_angle_deg: float
    rod_angular_velocity: float
    rod_angular_acceleration: float


@dataclass(frozen=True)
class GraphicalValues:
    """The values read off the constructions (textbook §36–37), scaled by
    the crank speed: the velocity ω·CE, the acceleration ω²·CG, the rod's
    angular velocity ω·CB/BD (0 while D is at infinity) and angular
    acceleration ω²·FG/l."""

    velocity: float
    acceleration: float
    rod_angular_velocity: float
    rod_angular_acceleration: float


@dataclass(frozen=True)
class Statics:
    """Ng's statics for a crank torque T (``at(..., torque=T)``).

    ``OM`` is the signed moment arm (= CE); ``slider_force`` F_p = T/OM and
    ``side_thrust`` F_s are ``None`` at a dead centre (OM = 0);
    ``slider_force_with_friction`` F_p' is ``None`` there and when the
    slider locks (``self_locking``: μ|tan φ| ≥ 1); ``friction`` is μ;
    ``transmission_angle_deg`` the interior angle β at the crank pin.
    """

    OM: float
    slider_force: Optional[float]
    side_thrust: Optional[float]
    slider_force_with_friction: Optional[float]
    self_locking: bool
    friction: float
    transmission_angle_deg: float


@dataclass(frozen=True)
class Analysis:
    """Everything ``slider-crank analyze --json`` prints at one angle.

    ``points`` maps the letters C (crank centre), B (crank pin), A
    (cross-head), D (instantaneous centre of the rod: an :class:`AtInfinity`
    at θ = 90°, 270° of an in-line engine), E (the rod produced meets the
    perpendicular to the stroke through C), F and G (Klein's and Kisch's
    constructions) and H (Kisch's; ``None`` only at the very limit of
    assembly) to their positions. ``virtual_centres`` maps ``O_ab`` …
    ``O_cd`` (links a frame, b crank, c rod, d slider) to a :data:`Centre`.
    ``statics`` is ``None`` unless a torque was given. :meth:`to_dict`
    gives the JSON object itself.
    """

    crank: float
    rod: float
    offset: float
    units: Dict[str, str]
    angle_deg: float
    omega: float
    points: Dict[str, Optional[Centre]]
    analytic: Values
    graphical: GraphicalValues
    virtual_centres: Dict[str, Centre]
    statics: Optional[Statics]
    _json: Dict[str, Any] = field(repr=False, compare=False)

    @classmethod
    def _from_json(cls, text: str) -> "Analysis":
        v = json.loads(text)
        m = v["mechanism"]
        s = v.get("statics")
        return cls(
            crank=m["crank"],
            rod=m["rod"],
            offset=m["offset"],
            units=dict(v["units"]),
            angle_deg=v["angle_deg"],
            omega=v["omega"],
            points={
                k: None if p is None else _centre(p) for k, p in v["points"].items()
            },
            analytic=Values(**v["analytic"]),
            graphical=GraphicalValues(**v["graphical"]),
            virtual_centres={k: _centre(c) for k, c in v["virtual_centres"].items()},
            statics=None if s is None else Statics(**s),
            _json=v,
        )

    def to_dict(self) -> Dict[str, Any]:
        """The object ``analyze --json`` prints, as a new dict (the schema
        of docs/design.md §4)."""
        copy: Dict[str, Any] = json.loads(json.dumps(self._json))
        return copy


@dataclass(frozen=True)
class GraphicalSweep:
    """The values read off the constructions over a sweep (numpy arrays
    shaped as the angles): see :class:`GraphicalValues`."""

    velocity: npt.NDArray[np.float64]
    acceleration: npt.NDArray[np.float64]
    rod_angular_velocity: npt.NDArray[np.float64]
    rod_angular_acceleration: npt.NDArray[np.float64]


@dataclass(frozen=True)
class Sweep:
    """The exact values over an array of crank angles, each a float64
    numpy array shaped as ``theta_deg`` (see :class:`Values`);
    ``graphical`` holds the values read off the constructions when asked
    for (``sweep(..., graphical=True)``), else ``None``."""

    theta_deg: npt.NDArray[np.float64]
    position: npt.NDArray[np.float64]
    velocity: npt.NDArray[np.float64]
    acceleration: npt.NDArray[np.float64]
    rod_angle_deg: npt.NDArray[np.float64]
    rod_angular_velocity: npt.NDArray[np.float64]
    rod_angular_acceleration: npt.NDArray[np.float64]
    graphical: Optional[GraphicalSweep]


def _real(x: float) -> float:
    """``x`` as a float; a TypeError for what is not a real number (a
    string, None)."""
    if isinstance(x, numbers.Real):
        return float(x)
    raise TypeError(f"expected a real number, got {type(x).__name__} {x!r}")


def _option(x: Optional[float]) -> Optional[float]:
    return None if x is None else _real(x)


def _angles(thetas: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """The angles as a C-contiguous float64 array (a copy only where
    needed); a TypeError for values that are not real numbers."""
    a = np.asarray(thetas)
    if a.dtype.kind not in "biuf":
        raise TypeError(
            f"thetas must be real numbers of degrees, got an array of dtype {a.dtype}"
        )
    return np.asarray(a, dtype=np.float64, order="C")


class SliderCrank:
    """A slider-crank engine: crank radius ``crank`` (r), connecting rod
    ``rod`` (l) and the offset ``offset`` (e) of the line of stroke from
    the crank centre (0: in line), all in the length unit ``unit``;
    forces in ``force_unit``. Units are names only (written in tables,
    figures and JSON); no number is converted.

    The rod must exceed r + |e| so that the crank turns fully; lengths are
    positive and finite. Bad values raise ``ValueError`` with the command
    line's message, e.g. ``SliderCrank(1, 0.5)``:
    ``rod length l = 0.5 must exceed r + |e| = 1 ...``.

    >>> engine = SliderCrank(25, 72, unit="mm", force_unit="N")   # Ng's rig
    >>> round(engine.at(30, rpm=60, torque=1000).statics.slider_force, 3)   # N
    61.287
    """

    __slots__ = ("_crank", "_rod", "_offset", "_unit", "_force_unit")

    def __init__(
        self,
        crank: float,
        rod: float,
        offset: float = 0.0,
        unit: str = "ft",
        force_unit: str = "lbf",
    ) -> None:
        crank, rod, offset = _real(crank), _real(rod), _real(offset)
        _core.check_engine(crank, rod, offset, unit, force_unit)
        self._crank, self._rod, self._offset = crank, rod, offset
        self._unit, self._force_unit = unit, force_unit

    @property
    def crank(self) -> float:
        """The crank radius r."""
        return self._crank

    @property
    def rod(self) -> float:
        """The connecting-rod length l."""
        return self._rod

    @property
    def offset(self) -> float:
        """The offset e of the line of stroke (y = e)."""
        return self._offset

    @property
    def unit(self) -> str:
        """The name of the length unit."""
        return self._unit

    @property
    def force_unit(self) -> str:
        """The name of the force unit."""
        return self._force_unit

    def __repr__(self) -> str:
        return (
            f"SliderCrank(crank={self._crank!r}, rod={self._rod!r}, "
            f"offset={self._offset!r}, unit={self._unit!r}, "
            f"force_unit={self._force_unit!r})"
        )

    def at(
        self,
        theta_deg: float,
        rpm: Optional[float] = None,
        omega: Optional[float] = None,
        torque: Optional[float] = None,
        friction: Optional[float] = None,
    ) -> Analysis:
        """Analyses the engine at crank angle ``theta_deg`` (degrees), as
        ``slider-crank analyze --angle θ --json`` does.

        The crank speed is ``rpm`` (revolutions per minute) or ``omega``
        (rad/s), not both; 250 rpm when neither is given. With a crank
        ``torque`` T (counter-clockwise positive, force × length) the
        result carries Ng's statics, with the slider's coefficient of
        friction ``friction`` μ ≥ 0 (0 by default; only with a torque).
        """
        w = _core.crank_speed(rpm, omega)
        if friction is not None and torque is None:
            raise ValueError("friction applies with a torque: give torque= too")
        text = _core.analyze(
            self._crank,
            self._rod,
            self._offset,
            self._unit,
            self._force_unit,
            _real(theta_deg),
            w,
            _option(torque),
            0.0 if friction is None else _real(friction),
        )
        return Analysis._from_json(text)

    def sweep(
        self,
        thetas: npt.ArrayLike,
        rpm: Optional[float] = None,
        omega: Optional[float] = None,
        graphical: bool = False,
    ) -> Sweep:
        """The exact values at every crank angle of ``thetas`` (degrees;
        any array-like of real numbers, any shape), as numpy float64
        arrays of that shape; with ``graphical=True`` also the values read
        off the constructions.

        The speed is given as in :meth:`at`. The computation runs in the
        library with the GIL released, one pass over the angles; each
        value equals the one :meth:`at` gives at that angle. A NaN or
        infinite angle raises ``ValueError`` (the first one met).
        """
        w = _core.crank_speed(rpm, omega)
        a = _angles(thetas)
        flat = a.reshape(-1)
        rows = 10 if graphical else 6
        out = np.empty((rows, flat.size), dtype=np.float64)
        _core.sweep(self._crank, self._rod, self._offset, w, flat, out)
        r = [row.reshape(a.shape) for row in out]
        return Sweep(
            theta_deg=a,
            position=r[0],
            velocity=r[1],
            acceleration=r[2],
            rod_angle_deg=r[3],
            rod_angular_velocity=r[4],
            rod_angular_acceleration=r[5],
            graphical=GraphicalSweep(*r[6:10]) if graphical else None,
        )

    def _handout(
        self,
        which: str,
        theta_deg: float,
        rpm: Optional[float],
        omega: Optional[float],
        torque: Optional[float],
        friction: Optional[float],
        paper: str,
    ) -> str:
        w = _core.crank_speed(rpm, omega)
        if friction is not None and torque is None:
            raise ValueError("friction applies with a torque: give torque= too")
        return _core.handout(
            self._crank,
            self._rod,
            self._offset,
            self._unit,
            self._force_unit,
            _real(theta_deg),
            w,
            which,
            paper,
            _option(torque),
            0.0 if friction is None else _real(friction),
        )

    def handout(
        self,
        theta_deg: float = 45.0,
        rpm: Optional[float] = None,
        omega: Optional[float] = None,
        torque: Optional[float] = None,
        friction: Optional[float] = None,
        paper: str = "a4",
        out: Union[None, str, "os.PathLike[str]"] = None,
    ) -> str:
        """The printable teaching page (HTML) that works this engine
        through textbook §35–37 and Ng step by step at ``theta_deg``, as
        ``slider-crank handout`` writes it; ``paper`` is ``a4`` or
        ``letter``; speed and load as in :meth:`at`. Written to ``out``
        too when given; the HTML is returned."""
        html = self._handout("page", theta_deg, rpm, omega, torque, friction, paper)
        if out is not None:
            _write(out, html)
        return html

    def exercise(
        self,
        theta_deg: float = 45.0,
        rpm: Optional[float] = None,
        omega: Optional[float] = None,
        torque: Optional[float] = None,
        friction: Optional[float] = None,
        paper: str = "a4",
        out: Union[None, str, "os.PathLike[str]"] = None,
    ) -> Tuple[str, str]:
        """The exercise sheet and its answer key (HTML), as ``slider-crank
        handout --exercise`` writes them; with ``out`` (``sheet.html``)
        also written there and beside it (``sheet-key.html``)."""
        args = (theta_deg, rpm, omega, torque, friction, paper)
        sheet = self._handout("exercise", *args)
        key = self._handout("key", *args)
        if out is not None:
            path = os.fspath(out)
            stem = path[: -len(".html")] if path.endswith(".html") else path
            _write(path, sheet)
            _write(stem + "-key.html", key)
        return sheet, key

    def figure(
        self,
        name: str = "fig-66-kisch",
        *,
        angle: Optional[float] = None,
        rpm: Optional[float] = None,
        omega: Optional[float] = None,
        **options: Any,
    ) -> "Figure":
        """A named figure (see :func:`figure`) drawn for this engine in
        its units: ``figure(name, crank=r, rod=l, offset=e, unit=...,
        force_unit=..., ...)``."""
        return figure(
            name,
            crank=self._crank,
            rod=self._rod,
            offset=self._offset,
            unit=self._unit,
            force_unit=self._force_unit,
            angle=angle,
            rpm=rpm,
            omega=omega,
            **options,
        )


def _write(path: Union[str, "os.PathLike[str]"], text: str) -> None:
    """Writes ``text`` to ``path`` whole or not at all (a temporary file
    beside it, renamed into place)."""
    target = os.fspath(path)
    temporary = f"{target}.{os.getpid()}.tmp"
    try:
        with open(temporary, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(temporary, target)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


class Figure:
    """A figure drawn by the library: its SVG text (``svg``), shown inline
    by Jupyter (``_repr_svg_``), and written as SVG, PNG (2 pixels per page
    unit) or PDF (vector, the bundled faces embedded) by :meth:`save`."""

    __slots__ = ("_svg",)

    def __init__(self, svg: str) -> None:
        self._svg = svg

    @property
    def svg(self) -> str:
        """The SVG text, byte for byte what ``slider-crank figure`` prints."""
        return self._svg

    def _repr_svg_(self) -> str:
        return self._svg

    def png(self) -> bytes:
        """The figure as PNG bytes (2 pixels per page unit)."""
        return _core.encode(self._svg, "png")

    def pdf(self) -> bytes:
        """The figure as a one-page vector PDF."""
        return _core.encode(self._svg, "pdf")

    def save(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Writes the figure to ``path`` in the format its extension names
        (.svg, .png, .pdf; SVG without one), whole or not at all, as
        ``figure --out`` does; any other extension raises ``ValueError``."""
        _core.save(self._svg, os.fspath(path))

    def __repr__(self) -> str:
        return f"<Figure: {len(self._svg)} characters of SVG>"


def _length(value: Union[None, float, str]) -> Optional[str]:
    return None if value is None else str(value)


def figure(
    name: str,
    *,
    crank: Optional[float] = None,
    rod: Optional[float] = None,
    offset: Optional[float] = None,
    angle: Optional[float] = None,
    rpm: Optional[float] = None,
    omega: Optional[float] = None,
    layers: Union[None, str, "list[str]", Tuple[str, ...]] = None,
    style: Optional[str] = None,
    font: Optional[str] = None,
    data: Union[None, str, "os.PathLike[str]"] = None,
    fit: Optional[str] = None,
    unit: Optional[str] = None,
    force_unit: Optional[str] = None,
    notation: Optional[str] = None,
    mirror: Optional[bool] = None,
    width: Union[None, float, str] = None,
    height: Union[None, float, str] = None,
    title: Optional[str] = None,
) -> Figure:
    """The named figure (one of :data:`FIGURES`), as ``slider-crank figure
    NAME`` draws it; each option is the flag of that name (``None``: the
    figure's own).

    ``crank``, ``rod``, ``offset``: the mechanism; ``angle``: the crank
    angle drawn (degrees; the plane's tilt for ``ng-fig-2-incline``);
    ``rpm`` or ``omega``: the crank speed; ``layers``: a list or a
    comma-separated string (mechanism, angles, dimensions, centrodes,
    coupler, polar, virtual-centres, velocity, klein, kisch, torque,
    motion, scales); ``style``: ``textbook`` or ``handout``; ``font``:
    ``new-computer-modern`` or ``libertinus-serif``; ``data``: a CSV file
    of measured data; ``fit``: ``origin``, ``intercept`` or ``both``;
    ``unit``, ``force_unit``: unit names; ``notation``: ``textbook`` or
    ``ng``; ``mirror``: the cylinder on the left (True) or right (False);
    ``width``, ``height``: page units (800) or a size (``"120mm"``,
    ``"4.5in"``); ``title``: set below the figure.
    """
    return Figure(_core.figure(name, **_figure_options(locals())))


def _figure_options(given: Dict[str, Any]) -> Dict[str, Any]:
    """The keywords of :func:`figure` as the native call takes them."""
    layers = given["layers"]
    if layers is not None and not isinstance(layers, str):
        layers = ",".join(layers)
    crank, rod, offset, angle = (given[k] for k in ("crank", "rod", "offset", "angle"))
    rpm, omega, data, width = (given[k] for k in ("rpm", "omega", "data", "width"))
    style, font, fit, unit = (given[k] for k in ("style", "font", "fit", "unit"))
    force_unit, notation, mirror = (given[k] for k in ("force_unit", "notation", "mirror"))
    height, title = given["height"], given["title"]
    return dict(
        crank=_option(crank),
        rod=_option(rod),
        offset=_option(offset),
        angle=_option(angle),
        rpm=_option(rpm),
        omega=_option(omega),
        layers=layers,
        style=style,
        font=font,
        data=None if data is None else os.fspath(data),
        fit=fit,
        unit=unit,
        force_unit=force_unit,
        notation=notation,
        mirror=mirror,
        width=_length(width),
        height=_length(height),
        title=title,
    )



def table(
    name: str,
    format: str = "text",
    *,
    n: Optional["list[float]"] = None,
    angles: Optional[npt.ArrayLike] = None,
    crank: Optional[float] = None,
    rod: Optional[float] = None,
    offset: float = 0.0,
    rpm: Optional[float] = None,
    omega: Optional[float] = None,
    torque: Optional[float] = None,
    friction: Optional[float] = None,
    decimals: Optional[int] = None,
    unit: Optional[str] = None,
    force_unit: Optional[str] = None,
) -> str:
    """A table as ``slider-crank table NAME`` prints it: ``obliquity``,
    ``acceleration-factor`` (the textbook's), ``kinematics`` (a θ sweep)
    or ``forces`` (Ng's Table 2); ``format`` is ``text``, ``markdown`` or
    ``csv``. Each keyword is the flag of that name (``None``: the table's
    default): ``n`` the ratios l/r (``math.inf`` for the infinitely long
    rod), ``angles`` the crank angles in degrees (any array-like),
    ``crank``, ``rod``, ``offset`` the mechanism of ``kinematics`` and
    ``forces``, ``rpm`` or ``omega`` the speed, ``torque`` and
    ``friction`` the load of ``forces``, ``decimals`` the digits printed.
    """
    return _core.table(
        name,
        format,
        n=None if n is None else [_real(x) for x in n],
        angles=None if angles is None else _angles(angles).reshape(-1).tolist(),
        crank=_option(crank),
        rod=_option(rod),
        offset=_real(offset),
        rpm=_option(rpm),
        omega=_option(omega),
        torque=_option(torque),
        friction=_option(friction),
        decimals=decimals,
        unit=unit,
        force_unit=force_unit,
    )


def gallery(
    out: Union[str, "os.PathLike[str]"] = "gallery",
    only: Union[None, str, "list[str]", Tuple[str, ...]] = None,
) -> "list[str]":
    """Writes the gallery into the directory ``out`` (made if missing), as
    ``slider-crank gallery --out DIR`` does: every named figure as SVG,
    PNG and PDF, the textbook's tables and an ``index.html`` captioning
    each figure with the section it reproduces; ``only`` limits it to
    some figures (a list or a comma-separated string). Each file is
    written whole or not at all. Returns the names of the files."""
    path = os.fspath(out)
    os.makedirs(path, exist_ok=True)
    if isinstance(only, str):
        only = only.split(",")
    return _core.gallery(path, None if only is None else list(only))


def animate(
    name: str = "fig-66-kisch",
    out: Union[None, str, "os.PathLike[str]"] = None,
    *,
    frames: int = 72,
    period: float = 4.0,
    html: bool = False,
    crank: Optional[float] = None,
    rod: Optional[float] = None,
    offset: Optional[float] = None,
    angle: Optional[float] = None,
    rpm: Optional[float] = None,
    omega: Optional[float] = None,
    layers: Union[None, str, "list[str]", Tuple[str, ...]] = None,
    style: Optional[str] = None,
    font: Optional[str] = None,
    unit: Optional[str] = None,
    force_unit: Optional[str] = None,
    notation: Optional[str] = None,
    mirror: Optional[bool] = None,
    width: Union[None, float, str] = None,
    height: Union[None, float, str] = None,
    title: Optional[str] = None,
) -> str:
    """One revolution of a mechanism figure in ``frames`` poses played in
    ``period`` seconds, as ``slider-crank animate NAME --out FILE`` makes
    it: a self-playing SVG, or an HTML page with a slider when ``out``
    ends in ``.html`` (or, without ``out``, ``html=True``). The options
    are :func:`figure`'s (``angle``: the first frame's). Returns the text;
    writes it to ``out`` too when given."""
    options = _figure_options({**locals(), "data": None, "fit": None})
    path = os.fspath(out) if out is not None else ("animation.html" if html else "animation.svg")
    text = _core.figure(name, animate=(int(frames), _real(period), path), **options)
    if out is not None:
        _write(out, text)
    return text
