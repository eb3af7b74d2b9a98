"""The package's implementation: the classes and functions that
``slider_crank`` exports (see its ``__all__``), with the imports they
need kept here, out of the package's namespace. Import them from
``slider_crank``."""

from __future__ import annotations

import json
import numbers
import os
from dataclasses import dataclass, field
from typing import Any, Dict, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import _core

#: A point (x, y), in the engine's length unit.
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
class RodDynamics:
    """The connecting rod's inertia at one pose (an engine with
    ``rod_mass``): its inertia force (x, y) at the centre of mass G and
    couple, the torque they deliver to the crank (exact, rigid body), and
    the same rod as the equivalent dynamical system (two masses, at the
    cross-head and the crank pin, and the correction couple) with the
    torque that system gives: equal to ``torque``. The true dynamical
    system, two masses with the rod's moment of inertia and no couple:
    ``dynamical_mass_at_crosshead`` at the cross-head and
    ``mass_at_percussion`` at the centre of percussion, L = l₁ + k²/l₁
    (``percussion_distance``, l₁ = AG) from the cross-head, and their
    torque ``dynamical_torque`` (equal to ``torque``); all four ``None``
    when the centre of mass is at the cross-head (l₁ = 0)."""

    inertia_force: Point
    inertia_couple: float
    torque: float
    mass_at_crosshead: float
    mass_at_crank_pin: float
    correction_couple: float
    correction_torque: float
    equivalent_torque: float
    percussion_distance: Optional[float] = None
    dynamical_mass_at_crosshead: Optional[float] = None
    mass_at_percussion: Optional[float] = None
    dynamical_torque: Optional[float] = None


@dataclass(frozen=True)
class Unbalanced:
    """The unbalanced force of the reciprocating parts along the stroke:
    the primary m r ω² cos θ and secondary m r ω² cos 2θ / n parts, the
    exact −m a, and the remainder (the higher harmonics)."""

    primary: float
    secondary: float
    exact: float
    remainder: float


@dataclass(frozen=True)
class EngineLoads:
    """The forces of the whole engine at one pose, the rod's inertia
    included (Newton–Euler on the slider and on the rod as a rigid body):
    the member ``whole_engine`` of ``analyze --mass … --json``. Vectors
    are (x, y) in the frame of the engine (x along the line of stroke
    away from the crank centre); the crank is massless (or balanced about
    C). With ``gravity`` the rod's weight at G is in the pin loads; with
    ``friction`` the guides' friction, from their reaction with the rod's
    inertia, is ``friction`` (towards the crank; ``None`` without).

    Where :class:`Dynamics` gives the forces of the reciprocating parts
    alone (its ``rod_force`` F / cos φ and ``guide_thrust`` −F tan φ, the
    rod a massless link), these carry the rod's mass and moment of inertia
    too; for an engine without ``rod_mass`` they are the same forces.

    ``crosshead_pin_load``: the force of the rod on the cross-head pin A.
    ``crank_pin_load``: the force of the rod on the crank pin B, which is
    also the load on the main bearing. ``rod_force``: the force along the
    rod at the cross-head, compression positive (the cross-head pin's
    force along B → A; a heavy rod's pin force also has a part across
    it). ``guide_thrust``: the slider's thrust on its guides along +y.
    ``piston_effort_equivalent``: the piston effort of the equivalent
    dynamical system, the gas force and the inertia force of the
    reciprocating parts with the rod's mass at the cross-head
    (m_A = m_r BG / l) moving with the piston, positive towards the crank.
    ``shaking_force``: the force on the frame, −m a_A − m_r a_G, the
    inertia forces of the reciprocating parts and the rod (the gas force
    acts on the piston and the cylinder head alike and cancels).
    """

    crosshead_pin_load: Point
    crank_pin_load: Point
    rod_force: float
    guide_thrust: float
    piston_effort_equivalent: float
    shaking_force: Point
    friction: Optional[float] = None

    @classmethod
    def _from_json(cls, v: Dict[str, Any]) -> "EngineLoads":
        def pair(key: str) -> Point:
            return (v[key][0], v[key][1])

        return cls(
            crosshead_pin_load=pair("crosshead_pin_load"),
            crank_pin_load=pair("crank_pin_load"),
            rod_force=v["rod_force"],
            guide_thrust=v["guide_thrust"],
            piston_effort_equivalent=v["piston_effort_equivalent"],
            shaking_force=pair("shaking_force"),
            friction=v.get("friction"),
        )


@dataclass(frozen=True)
class Dynamics:
    """The engine's forces and torques at one pose, the member
    ``dynamics`` of ``analyze --mass … --json`` (``at(..., mass=...)``).

    Forces along the stroke are positive towards the crank centre, torques
    on the crank counter-clockwise positive; ``units`` names the force,
    torque and mass units. ``inertia_force`` is the reciprocating parts'
    m a exact, ``inertia_force_klein`` the same from Klein's construction
    (−m ω² CG); ``piston_effort`` F = gas + inertia force; ``rod_force``
    F / cos φ (compression positive); ``guide_thrust`` −F tan φ, the
    slider's thrust on its guides along +y; ``OM`` Ng's torque arm read off
    the construction; ``crank_effort`` F · OM and ``crank_effort_exact``
    F r sin(θ + φ) / cos φ; ``torque`` the whole torque on the crank (the
    crank effort and the rod's inertia torque); ``rod`` ``None`` for a
    massless rod. These forces are the reciprocating parts' (the rod a
    massless link); ``whole_engine`` (:class:`EngineLoads`) gives those of
    the whole engine with the rod's inertia: the pin and main-bearing
    loads, the force along the rod and the thrust on the guides with a
    heavy rod, and the shaking force on the frame. With ``gravity``
    (a vertical engine) ``weight`` is the reciprocating parts' weight
    along the stroke towards the crank, in ``piston_effort``; with
    ``friction`` the guides' friction on them, μ |N| against the motion
    (0 at a dead centre), is ``friction``, in ``piston_effort`` too; each
    ``None`` where not given (``gravity`` is the acceleration of gravity
    (x, y) in the engine's frame, ``friction_coefficient`` that μ). ``sign``
    states the signs in words, as the JSON does.
    """

    units: Dict[str, str]
    reciprocating_mass: float
    gas_force: float
    inertia_force: float
    inertia_force_klein: float
    piston_effort: float
    rod_force: float
    guide_thrust: float
    OM: float
    crank_effort: float
    crank_effort_exact: float
    torque: float
    unbalanced: Unbalanced
    rod: Optional[RodDynamics]
    whole_engine: EngineLoads
    weight: Optional[float] = None
    friction: Optional[float] = None
    friction_coefficient: Optional[float] = None
    gravity: Optional[Point] = None
    sign: str = ""

    @classmethod
    def _from_json(cls, v: Dict[str, Any]) -> "Dynamics":
        rod = v["rod"]
        return cls(
            units=dict(v["units"]),
            unbalanced=Unbalanced(**v["unbalanced"]),
            whole_engine=EngineLoads._from_json(v["whole_engine"]),
            rod=None
            if rod is None
            else RodDynamics(
                inertia_force=(rod["inertia_force"][0], rod["inertia_force"][1]),
                inertia_couple=rod["inertia_couple"],
                torque=rod["torque"],
                equivalent_torque=rod["equivalent"]["torque"],
                mass_at_crosshead=rod["equivalent"]["mass_at_crosshead"],
                mass_at_crank_pin=rod["equivalent"]["mass_at_crank_pin"],
                correction_couple=rod["equivalent"]["correction_couple"],
                correction_torque=rod["equivalent"]["correction_torque"],
                percussion_distance=_dynamical(rod, "percussion_distance"),
                dynamical_mass_at_crosshead=_dynamical(rod, "mass_at_crosshead"),
                mass_at_percussion=_dynamical(rod, "mass_at_percussion"),
                dynamical_torque=_dynamical(rod, "torque"),
            ),
            weight=v.get("weight"),
            friction=v.get("friction"),
            friction_coefficient=v.get("friction_coefficient"),
            gravity=None if "gravity" not in v else (v["gravity"][0], v["gravity"][1]),
            sign=v["sign"],
            **{k: v[k] for k in _DYNAMICS_VALUES},
        )


def _dynamical(rod: Dict[str, Any], key: str) -> Optional[float]:
    """A value of the true dynamical system from ``analyze --json``'s
    ``dynamics.rod.dynamical`` (``null``: none, so ``None``)."""
    d = rod["dynamical"]
    return None if d is None else float(d[key])


_DYNAMICS_VALUES = (
    "reciprocating_mass",
    "gas_force",
    "inertia_force",
    "inertia_force_klein",
    "piston_effort",
    "rod_force",
    "guide_thrust",
    "OM",
    "crank_effort",
    "crank_effort_exact",
    "torque",
)


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
    ``polygons`` is the velocity and acceleration polygons of the
    relative-velocity method (docs/polygons.md): the vectors from the pole
    (``velocity``: ``a``, ``b``, ``q``; ``acceleration``: ``a``, ``b``,
    ``q``, ``x``; q the image of the rod's middle) and the values read off
    them (``slider_velocity``, ``rod_angular_velocity``,
    ``slider_acceleration``, ``rod_angular_acceleration``,
    ``normal_component``, ``tangential_component``), in the user's units,
    and ``off_rod``, the images of a point of the rod's plane off its line
    (``along`` 0.5 and ``across`` 0.25 rod lengths, left of A to B; its
    ``velocity`` and ``acceleration``, by similar triangles).
    ``ritterhaus`` and ``bennett`` are Ritterhaus's and Bennett's
    constructions (docs/polygons.md): their points (K, F, G; L, K, F, G)
    and the piston's ``acceleration`` read off them; ``bennett`` is
    ``None`` for an offset engine (the construction is the in-line
    engine's).
    ``statics`` is ``None`` unless a torque was given; ``dynamics`` is
    ``None`` unless a mass or gas force was given (see :class:`Dynamics`).
    ``assumed_rpm`` is the crank speed in rpm that was assumed because none
    was given (250, the command line's default; ``omega`` is that speed in
    rad/s), ``None`` when the call gave ``rpm`` or ``omega`` (see
    :meth:`SliderCrank.at`); it is not part of the JSON, nor compared.
    :meth:`to_dict` gives the JSON object itself.
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
    polygons: Dict[str, Any]
    ritterhaus: Dict[str, Any]
    bennett: Optional[Dict[str, Any]]
    statics: Optional[Statics]
    dynamics: Optional[Dynamics]
    assumed_rpm: Optional[float] = field(compare=False)
    _json: Dict[str, Any] = field(repr=False, compare=False)

    @classmethod
    def _from_json(
        cls, text: str, dynamics: Optional[str] = None, assumed_rpm: Optional[float] = None
    ) -> "Analysis":
        v = json.loads(text)
        if dynamics is not None:
            # the command line's object has its keys in sorted order
            v = dict(sorted({**v, "dynamics": json.loads(dynamics)}.items()))
        d = v.get("dynamics")
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
            polygons=json.loads(json.dumps(v["polygons"])),
            ritterhaus=json.loads(json.dumps(v["ritterhaus"])),
            bennett=None if v["bennett"] is None else json.loads(json.dumps(v["bennett"])),
            statics=None if s is None else Statics(**s),
            dynamics=None if d is None else Dynamics._from_json(d),
            assumed_rpm=assumed_rpm,
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
class DynamicsSweep:
    """The engine's forces and torques over a sweep (numpy arrays shaped
    as the angles), each the value of :class:`Dynamics` of that name at
    that angle; ``rod_torque`` is the rod's inertia torque (``rod.torque``,
    0 for a massless rod), ``primary`` and ``secondary`` the unbalanced
    forces."""

    gas_force: npt.NDArray[np.float64]
    inertia_force: npt.NDArray[np.float64]
    inertia_force_klein: npt.NDArray[np.float64]
    piston_effort: npt.NDArray[np.float64]
    rod_force: npt.NDArray[np.float64]
    guide_thrust: npt.NDArray[np.float64]
    OM: npt.NDArray[np.float64]
    crank_effort: npt.NDArray[np.float64]
    crank_effort_exact: npt.NDArray[np.float64]
    rod_torque: npt.NDArray[np.float64]
    torque: npt.NDArray[np.float64]
    primary: npt.NDArray[np.float64]
    secondary: npt.NDArray[np.float64]


@dataclass(frozen=True)
class Lobe:
    """One area between the turning-moment curve and its mean line, from
    ``from_deg`` to ``to_deg``: ``area`` = ∫ (T − T_mean) dθ over it
    (positive above the mean: energy stored in the flywheel) and
    ``energy`` the energy stored since θ = 0 at its end."""

    from_deg: float
    to_deg: float
    area: float
    energy: float


@dataclass(frozen=True)
class Flywheel:
    """A flywheel for the fluctuation of energy ``fluctuation`` ΔE at the
    mean crank speed ``omega``: its moment of inertia ``inertia`` I and
    the coefficient of fluctuation of speed ``coefficient`` C_s, with
    ΔE = I ω² C_s (one of the two was given)."""

    fluctuation: float
    omega: float
    inertia: float
    coefficient: float


@dataclass(frozen=True)
class TurningMoment:
    """The turning-moment diagram over one turn (the notes of ``table
    dynamics``, in full precision): the cylinders' phase angles, the work
    of a turn ∫ T dθ, the ``mean`` torque, the largest |T| (``peak``), the
    absolute ``tolerance`` of the integrals, the areas between the curve
    and its mean line (``lobes``), the fluctuation of energy ΔE
    (``fluctuation``) with the crank angles of the most and least energy
    stored, the angles where T has a kink, and the ``flywheel`` asked for
    (``None`` unless ``fluctuation=`` or ``flywheel=`` was given).
    ``cycle_deg`` is the cycle's length in crank degrees the integrals
    and angles are over: 360, or 720 for a four-stroke indicator diagram.

    The integrals are adaptive Simpson quadrature split at every kink and
    at the exact crossings of the mean line, each within ``tolerance``."""

    phases_deg: Tuple[float, ...]
    work: float
    mean: float
    peak: float
    tolerance: float
    lobes: Tuple[Lobe, ...]
    fluctuation: float
    max_energy_deg: float
    min_energy_deg: float
    kinks_deg: Tuple[float, ...]
    flywheel: Optional[Flywheel]
    cycle_deg: float = 360.0

    @classmethod
    def _from_json(cls, text: str) -> "TurningMoment":
        v = json.loads(text)
        t, f = v["turn"], v["flywheel"]
        return cls(
            phases_deg=tuple(t["phases_deg"]),
            work=t["work"],
            mean=t["mean"],
            peak=t["peak"],
            tolerance=t["tolerance"],
            lobes=tuple(Lobe(**x) for x in t["lobes"]),
            fluctuation=t["fluctuation"],
            max_energy_deg=t["max_energy_deg"],
            min_energy_deg=t["min_energy_deg"],
            kinks_deg=tuple(t["kinks_deg"]),
            flywheel=None if f is None else Flywheel(**f),
            cycle_deg=t["cycle_deg"],
        )


@dataclass(frozen=True)
class Resultant:
    """A part of the unbalance an in-line engine's cylinders leave
    together: the closing side of its polygon (``table balance``'s notes).

    Each cylinder's primary force is the projection on the line of stroke
    of a vector m r ω² turning with its crank (the secondary: m r ω²/n at
    twice the crank's angle); a couple multiplies each by the cylinder's
    distance from the reference plane. ``vector`` is the resultant's
    components (x along the line of stroke) at θ = 0 of the first crank,
    per unit m r ω² (a couple's also in the unit of the planes);
    ``amplitude`` its length, the largest unbalanced force (or couple)
    over a turn; ``balanced`` whether the polygon closes (its closing
    side at most 1e-12 times the sum of the lengths of its sides)."""

    vector: Point
    amplitude: float
    balanced: bool


@dataclass(frozen=True)
class InlineBalance:
    """The balance of the reciprocating masses of an in-line engine, as
    ``table balance`` works it out (made by :func:`balance`): the
    cylinders' crank angles ``cranks_deg`` (degrees ahead of the first),
    their lines of stroke's distances ``planes`` from the reference plane
    along the shaft, the ratio ``n`` = l/r of every cylinder, the four
    resultants :class:`Resultant` of the primary and secondary forces and
    couples (per unit m r ω², m the reciprocating mass of one cylinder, the
    same for all; the secondary ones carry 1/n), and ``balanced``: all
    four balanced. :meth:`sweep` gives the table's columns against θ."""

    cranks_deg: Tuple[float, ...]
    planes: Tuple[float, ...]
    n: float
    primary_force: Resultant
    primary_couple: Resultant
    secondary_force: Resultant
    secondary_couple: Resultant
    balanced: bool

    @classmethod
    def _from_json(cls, text: str) -> "InlineBalance":
        v = json.loads(text)

        def part(key: str) -> Resultant:
            r = v[key]
            return Resultant((r["vector"][0], r["vector"][1]), r["amplitude"], r["balanced"])

        return cls(
            cranks_deg=tuple(v["cranks_deg"]),
            planes=tuple(v["planes"]),
            n=v["n"],
            primary_force=part("primary_force"),
            primary_couple=part("primary_couple"),
            secondary_force=part("secondary_force"),
            secondary_couple=part("secondary_couple"),
            balanced=v["balanced"],
        )

    def sweep(self, thetas: npt.ArrayLike) -> "BalanceSweep":
        """The unbalanced forces and couples at every crank angle of
        ``thetas`` (the first cylinder's, degrees; any array-like, any
        shape), the columns of ``table balance``, computed by the library
        with the GIL released; a NaN or infinite angle raises
        ``ValueError``."""
        a = _angles(thetas)
        flat = a.reshape(-1)
        out = np.empty((_core.BALANCE_ROWS, flat.size), dtype=np.float64)
        _core.inline_sweep(list(self.cranks_deg), list(self.planes), self.n, flat, out)
        return BalanceSweep(a, *(row.reshape(a.shape) for row in out))


@dataclass(frozen=True)
class BalanceSweep:
    """An in-line engine's unbalanced forces and couples over an array of
    the first crank's angles ``theta_deg`` (numpy arrays of its shape),
    per unit m r ω² (couples also in the unit of the planes): the columns
    of ``table balance``. ``primary_force`` and ``secondary_force`` are the
    resultants' projections on the line of stroke (m r ω² cos θ and
    m r ω² cos 2θ / n summed over the cylinders), ``primary_couple`` and
    ``secondary_couple`` their moments about the reference plane, and
    ``exact_force`` the inertia force −m a of every cylinder summed (its
    harmonics beyond the second are O(1/n³))."""

    theta_deg: npt.NDArray[np.float64]
    primary_force: npt.NDArray[np.float64]
    secondary_force: npt.NDArray[np.float64]
    primary_couple: npt.NDArray[np.float64]
    secondary_couple: npt.NDArray[np.float64]
    exact_force: npt.NDArray[np.float64]


@dataclass(frozen=True)
class RadialBalance:
    """Cylinders on one crank (a V engine, a radial engine), balanced by
    the direct and reverse crank method as ``table radial`` notes it (made
    by :func:`radial`): the axes ``axes_deg`` (degrees from the reference
    line; the crank angle θ is taken from it), the ratio ``n``, and four
    :class:`Resultant`: the primary direct crank (k/2 along the crank,
    turning with it: balanced by a counterweight of k m/2 at r), the
    primary reverse crank (at −θ), the secondary direct (at 2θ) and
    reverse (at −2θ) cranks, their ``vector`` at θ = 0, per unit m r ω²
    (the secondary ones carry 1/n)."""

    axes_deg: Tuple[float, ...]
    n: float
    primary_direct: Resultant
    primary_reverse: Resultant
    secondary_direct: Resultant
    secondary_reverse: Resultant

    @classmethod
    def _from_json(cls, text: str) -> "RadialBalance":
        v = json.loads(text)

        def part(key: str) -> Resultant:
            r = v[key]
            return Resultant((r["vector"][0], r["vector"][1]), r["amplitude"], r["balanced"])

        return cls(
            axes_deg=tuple(v["axes_deg"]),
            n=v["n"],
            primary_direct=part("primary_direct"),
            primary_reverse=part("primary_reverse"),
            secondary_direct=part("secondary_direct"),
            secondary_reverse=part("secondary_reverse"),
        )


@dataclass(frozen=True)
class Harmonics:
    """The piston's acceleration of an in-line engine as a series of
    harmonics, as ``table harmonics`` gives it (made by :func:`harmonics`):
    −d²x/dt² = r ω² (cos θ + A₂ cos 2θ + A₄ cos 4θ + …) for the ratio
    ``n`` = l/r. ``coefficients`` are the exact A₂, A₄, …, A₂ₖ (A₂ₖ at
    index k − 1; from the exact acceleration sampled 4096 times a turn,
    not the textbooks' leading terms in 1/n); ``truncation_error[k]`` is
    the largest error over a turn, ÷ r ω², of the series cut after
    cos 2kθ (index 0: after cos θ; index 1: the textbook's eq. (3))."""

    n: float
    coefficients: Tuple[float, ...]
    truncation_error: Tuple[float, ...]


@dataclass(frozen=True)
class Sweep:
    """The exact values over an array of crank angles, each a float64
    numpy array shaped as ``theta_deg`` (see :class:`Values`);
    ``graphical`` holds the values read off the constructions when asked
    for (``sweep(..., graphical=True)``), else ``None``; ``dynamics`` the
    engine's forces and torques when a mass or gas force is given, else
    ``None``; ``assumed_rpm`` the crank speed assumed because none was
    given (250 rpm), ``None`` when ``rpm`` or ``omega`` was (see
    :meth:`SliderCrank.at`)."""

    theta_deg: npt.NDArray[np.float64]
    position: npt.NDArray[np.float64]
    velocity: npt.NDArray[np.float64]
    acceleration: npt.NDArray[np.float64]
    rod_angle_deg: npt.NDArray[np.float64]
    rod_angular_velocity: npt.NDArray[np.float64]
    rod_angular_acceleration: npt.NDArray[np.float64]
    graphical: Optional[GraphicalSweep]
    dynamics: Optional[DynamicsSweep] = None
    assumed_rpm: Optional[float] = field(default=None, compare=False)


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
        *,
        mass: Optional[float] = None,
        rod_mass: Optional[float] = None,
        rod_cg: Optional[float] = None,
        rod_gyration: Optional[float] = None,
        gas_force: Optional[float] = None,
        indicator: Union[None, str, "os.PathLike[str]"] = None,
        bore: Optional[float] = None,
        gravity: Optional[str] = None,
    ) -> Analysis:
        """Analyses the engine at crank angle ``theta_deg`` (degrees), as
        ``slider-crank analyze --angle θ --json`` does.

        The crank speed is ``rpm`` (revolutions per minute) or ``omega``
        (rad/s), not both. When neither is given the speed is the command
        line's default, 250 rpm (the §35 engine's), and the result says so:
        its ``assumed_rpm`` is 250.0 (``None`` when a speed was given), and
        shows in its repr. A speed is not required because most of what
        ``at`` gives does not depend on it (the points and virtual centres,
        the position, the rod's angle, Ng's statics) and because
        ``at(θ).to_dict()`` is what ``analyze --angle θ --json`` prints
        with its own default; the velocities, accelerations and inertia
        forces do depend on it, so a program that uses them can tell an
        assumed speed from a given one (``assert pose.assumed_rpm is
        None``). :meth:`sweep` and the chains' ``at`` do the same. With a crank
        ``torque`` T (counter-clockwise positive, force × length) the
        result carries Ng's statics, with the slider's coefficient of
        friction ``friction`` μ ≥ 0 (0 by default; with a torque or the
        engine's masses, whose dynamics then take the guides' friction
        μ |N| against the slider's motion).

        The engine's masses and gas force, the flags of ``analyze --mass
        …``, add its dynamics (:class:`Dynamics`, the JSON's member
        ``dynamics``): ``mass`` the reciprocating mass m (piston and
        cross-head; 0 when only another is given) in the unit that makes
        mass × length/s² the force unit (kg with m and N, slug with ft and
        lbf); ``rod_mass`` with ``rod_cg`` (BG, the rod's centre of mass
        from the crank pin, 0 ≤ BG ≤ l) and ``rod_gyration`` (its radius of
        gyration k) the rod's mass; ``gas_force`` a constant force on the
        piston, positive towards the crank centre, or ``indicator`` a CSV
        file (columns fraction of the stroke from the outer dead centre,
        expansion and compression pressures) with the cylinder's ``bore``;
        ``gravity`` a vertical engine, ``"towards-crank"`` (the cylinder
        above the crank) or ``"away-from-crank"``, standard gravity in the
        length unit weighing m and the rod.

        >>> engine = SliderCrank(0.5, 3.0)
        >>> round(engine.at(90, rpm=250, mass=10).dynamics.torque, 2)   # lbf·ft
        289.63
        """
        text = _core.analyze(
            crank=self._crank,
            rod=self._rod,
            offset=self._offset,
            angle=_real(theta_deg),
            rpm=_option(rpm),
            omega=_option(omega),
            torque=_option(torque),
            friction=_option(friction),
            unit=self._unit,
            force_unit=self._force_unit,
            mass=_option(mass),
            rod_mass=_option(rod_mass),
            rod_cg=_option(rod_cg),
            rod_gyration=_option(rod_gyration),
            gas_force=_option(gas_force),
            indicator=None if indicator is None else os.fspath(indicator),
            bore=_option(bore),
            gravity=gravity,
        )
        return Analysis._from_json(text, None, _assumed_rpm(rpm, omega))

    def _chain_at(
        self,
        theta_deg: float,
        rpm: Optional[float],
        omega: Optional[float],
        *,
        slot_radius: Optional[float] = None,
        inversion: Optional[int] = None,
    ) -> "ChainAnalysis":
        """This engine's chain with its block in a curved slot or another
        link fixed, analysed at ``theta_deg`` as ``analyze --json`` does."""
        text = _core.analyze(
            crank=self._crank,
            rod=self._rod,
            offset=self._offset,
            angle=_real(theta_deg),
            rpm=_option(rpm),
            omega=_option(omega),
            unit=self._unit,
            force_unit=self._force_unit,
            slot_radius=slot_radius,
            inversion=inversion,
        )
        return ChainAnalysis(text, _assumed_rpm(rpm, omega))

    def _engine(
        self,
        w: float,
        mass: Optional[float],
        rod_mass: Optional[float],
        rod_cg: Optional[float],
        rod_gyration: Optional[float],
        gas_force: Optional[float],
        indicator: Union[None, str, "os.PathLike[str]"],
        bore: Optional[float],
        default_mass: Optional[float] = None,
        gravity: Optional[str] = None,
        friction: Optional[float] = None,
    ) -> Optional[_core.Engine]:
        """The native engine of these keywords; ``None`` when none is
        given (or, with ``default_mass``, an engine of that mass), with
        ``gravity`` and ``friction`` where given."""
        given = (mass, rod_mass, rod_cg, rod_gyration, gas_force, indicator, bore)
        if all(x is None for x in given):
            if default_mass is None:
                if gravity is not None or friction is not None:
                    raise ValueError(
                        "gravity and friction apply to the engine's dynamics: give mass or rod_mass too"
                    )
                return None
            mass = default_mass
        return _core.Engine(
            self._crank,
            self._rod,
            self._offset,
            w,
            mass=_option(mass),
            rod_mass=_option(rod_mass),
            rod_cg=_option(rod_cg),
            rod_gyration=_option(rod_gyration),
            gas_force=_option(gas_force),
            indicator=None if indicator is None else os.fspath(indicator),
            bore=_option(bore),
            unit=self._unit,
            force_unit=self._force_unit,
            gravity=gravity,
            friction=_option(friction),
        )

    def turning_moment(
        self,
        rpm: Optional[float] = None,
        omega: Optional[float] = None,
        *,
        mass: Optional[float] = None,
        rod_mass: Optional[float] = None,
        rod_cg: Optional[float] = None,
        rod_gyration: Optional[float] = None,
        gas_force: Optional[float] = None,
        indicator: Union[None, str, "os.PathLike[str]"] = None,
        bore: Optional[float] = None,
        phases: Sequence[float] = (0.0,),
        fluctuation: Optional[float] = None,
        flywheel: Optional[float] = None,
        gravity: Optional[str] = None,
        friction: Optional[float] = None,
    ) -> TurningMoment:
        """The turning-moment diagram over one turn, as ``table dynamics``
        works it out in its notes: the mean torque, the fluctuation of
        energy ΔE and, with ``fluctuation`` (the coefficient of fluctuation
        of speed C_s) or ``flywheel`` (a moment of inertia I), the
        flywheel. ``phases`` are the cylinders' crank angles ahead of the
        first, in degrees (``(0, 180)``: two opposite cranks). Speed as in
        :meth:`at`, masses and gas force as there; with none of them, the
        example engine's reciprocating mass m = 10 as ``table dynamics``
        takes it; ``gravity`` and ``friction`` as ``table dynamics`` takes
        them (gravity does no work over a turn; the guides' friction
        lowers the mean torque by its work per turn over 2π).

        >>> turn = SliderCrank(0.5, 3.0).turning_moment(mass=10, fluctuation=0.02)
        >>> abs(turn.mean) < 1e-9 * turn.peak    # inertia forces do no net work
        True
        """
        w = _core.crank_speed(rpm, omega)
        engine = self._engine(
            w, mass, rod_mass, rod_cg, rod_gyration, gas_force, indicator, bore,
            default_mass=_core.EXAMPLE_MASS, gravity=gravity, friction=friction,
        )
        assert engine is not None
        text = engine.turning_moment(
            [_real(p) for p in phases], _option(fluctuation), _option(flywheel)
        )
        return TurningMoment._from_json(text)

    def check(
        self,
        samples: int = 100_000,
        tolerance: Optional[float] = None,
        *,
        max_cells: int = _core.DEFAULT_MAX_CELLS,
    ) -> "CheckReport":
        """``slider-crank check``: every construction against the analytic
        core at ``samples`` equally spaced crank angles (and the dead
        centres, 0°, 90°, 180° and 270°); a difference passes when at most
        ``tolerance`` (4 × 2⁻⁵², 4 ulps, by default) times the condition
        number κ of the quantity at that pose. The report is the command's,
        byte for byte; ``passed`` is its exit status 0. ``max_cells`` bounds
        the poses × quantities compared as ``--max-cells`` does (see
        :func:`table`)."""
        result = _core.engine_check(
            self._crank,
            self._rod,
            self._offset,
            _samples(samples),
            _option(tolerance),
            _max_cells(max_cells),
        )
        return CheckReport._from(result)

    def curved_slot(self, slot_radius: float) -> "CurvedSlot":
        """This engine with its block in a circular slot of radius
        ``slot_radius`` ρ (Fig. 60 b, ``analyze --slot-radius``)."""
        return CurvedSlot(self, slot_radius)

    def inversion(self, number: int) -> "Inversion":
        """The inversion ``number`` of this engine's chain (``analyze
        --inversion N``): 1 the frame fixed (the engine), 2 the crank fixed
        (the rotating block), 3 the rod fixed (the oscillating cylinder),
        4 the slider fixed (the hand pump)."""
        return Inversion(self, number)

    def sweep(
        self,
        thetas: npt.ArrayLike,
        rpm: Optional[float] = None,
        omega: Optional[float] = None,
        graphical: bool = False,
        *,
        mass: Optional[float] = None,
        rod_mass: Optional[float] = None,
        rod_cg: Optional[float] = None,
        rod_gyration: Optional[float] = None,
        gas_force: Optional[float] = None,
        indicator: Union[None, str, "os.PathLike[str]"] = None,
        bore: Optional[float] = None,
        gravity: Optional[str] = None,
        friction: Optional[float] = None,
    ) -> Sweep:
        """The exact values at every crank angle of ``thetas`` (degrees;
        any array-like of real numbers, any shape), as numpy float64
        arrays of that shape; with ``graphical=True`` also the values read
        off the constructions.

        The speed is given as in :meth:`at`. The computation runs in the
        library with the GIL released, one pass over the angles; each
        value equals the one :meth:`at` gives at that angle. A NaN or
        infinite angle raises ``ValueError`` (the first one met).

        The masses and gas force of :meth:`at` (with its ``gravity`` and
        ``friction``) add the engine's forces and torques at every angle (:class:`DynamicsSweep`), each equal to the
        value of :attr:`Analysis.dynamics` there.
        """
        w = _core.crank_speed(rpm, omega)
        engine = self._engine(
            w, mass, rod_mass, rod_cg, rod_gyration, gas_force, indicator, bore,
            gravity=gravity, friction=friction,
        )
        a = _angles(thetas)
        flat = a.reshape(-1)
        rows = 10 if graphical else 6
        out = np.empty((rows, flat.size), dtype=np.float64)
        _core.sweep(self._crank, self._rod, self._offset, w, flat, out)
        r = [row.reshape(a.shape) for row in out]
        dynamics = None
        if engine is not None:
            forces = np.empty((_core.DYNAMICS_ROWS, flat.size), dtype=np.float64)
            engine.sweep(flat, forces)
            dynamics = DynamicsSweep(*(row.reshape(a.shape) for row in forces))
        return Sweep(
            theta_deg=a,
            position=r[0],
            velocity=r[1],
            acceleration=r[2],
            rod_angle_deg=r[3],
            rod_angular_velocity=r[4],
            rod_angular_acceleration=r[5],
            graphical=GraphicalSweep(*r[6:10]) if graphical else None,
            dynamics=dynamics,
            assumed_rpm=_assumed_rpm(rpm, omega),
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
        dynamics: Optional["_Dynamics"] = None,
    ) -> str:
        d = dynamics or _Dynamics()
        return _core.handout(
            which,
            crank=self._crank,
            rod=self._rod,
            offset=self._offset,
            angle=_real(theta_deg),
            rpm=_option(rpm),
            omega=_option(omega),
            unit=self._unit,
            force_unit=self._force_unit,
            torque=_option(torque),
            friction=_option(friction),
            mass=_option(d.mass),
            fluctuation=_option(d.fluctuation),
            gas_force=_option(d.gas_force),
            indicator=None if d.indicator is None else os.fspath(d.indicator),
            bore=_option(d.bore),
            paper=paper,
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
        *,
        mass: Optional[float] = None,
        fluctuation: Optional[float] = None,
        gas_force: Optional[float] = None,
        indicator: Union[None, str, "os.PathLike[str]"] = None,
        bore: Optional[float] = None,
    ) -> str:
        """The printable teaching page (HTML) that works this engine
        through textbook §35–37 and Ng step by step at ``theta_deg``, as
        ``slider-crank handout`` writes it; ``paper`` is ``a4`` or
        ``letter``; speed and load as in :meth:`at`. With ``mass`` (the
        reciprocating mass in the unit that makes mass × length/s² the
        force unit: kg with m and N, slug with ft and lbf) it also works
        the dynamics (``--mass``): the inertia force, the crank effort, the
        turning-moment diagram and the flywheel for the coefficient of
        fluctuation of speed ``fluctuation`` (0.02 when not given). The
        gas force is ``gas_force`` (a constant, in the force unit), or the
        indicator diagram read from the CSV file ``indicator`` (pressures
        in force per length², a unit declared in its header checked
        against the engine's) on the cylinder's ``bore``, else the
        example's steam diagram (lbf/ft² on a 10 in bore: in ft and lbf
        only). Written to ``out`` too when given; the HTML is returned."""
        dynamics = _Dynamics(mass, fluctuation, gas_force, indicator, bore)
        html = self._handout("page", theta_deg, rpm, omega, torque, friction, paper, dynamics)
        if out is not None:
            _write((out, html))
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
        *,
        mass: Optional[float] = None,
        fluctuation: Optional[float] = None,
        gas_force: Optional[float] = None,
        indicator: Union[None, str, "os.PathLike[str]"] = None,
        bore: Optional[float] = None,
    ) -> Tuple[str, str]:
        """The exercise sheet and its answer key (HTML), as ``slider-crank
        handout --exercise`` writes them; with ``mass`` and the gas force
        as in :meth:`handout`, the sheet also asks the inertia force, the
        piston effort and the crank effort at its pose. With ``out``
        (``sheet.html``) also written there and beside it
        (``sheet-key.html``), both or neither: when either cannot be
        written (``OSError``), no file is changed, so a sheet is never
        left without its key. A symbolic link at the key's name (named
        after ``out``, not by the caller) is refused (``ValueError``)
        before either is written, as ``handout --exercise`` refuses it."""
        dynamics = _Dynamics(mass, fluctuation, gas_force, indicator, bore)
        args = (theta_deg, rpm, omega, torque, friction, paper, dynamics)
        sheet = self._handout("exercise", *args)
        key = self._handout("key", *args)
        if out is not None:
            path = os.fspath(out)
            stem = path[: -len(".html")] if path.endswith(".html") else path
            _write((path, sheet), (stem + "-key.html", key), derived=[stem + "-key.html"])
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


@dataclass(frozen=True)
class _Dynamics:
    """The dynamics keywords of a handout or exercise, as given."""

    mass: Optional[float] = None
    fluctuation: Optional[float] = None
    gas_force: Optional[float] = None
    indicator: Union[None, str, "os.PathLike[str]"] = None
    bore: Optional[float] = None


def _write(
    *files: Tuple[Union[str, "os.PathLike[str]"], str], derived: Sequence[str] = ()
) -> None:
    """Writes each ``(path, text)`` of ``files`` whole, or none of them,
    as the command line writes its files (the library's writer): each
    staged under an unpredictable temporary name in its target's
    directory and renamed into place once all are written; a symbolic
    link at a target is kept and the file it points to replaced; a
    failure (``OSError``) leaves every old file as it was. A path of
    ``derived`` (named after the one the caller gave: an exercise's key)
    that is a symbolic link is refused (``ValueError``) before anything
    is written, as the command line refuses it."""
    _core.write_files([(os.fspath(path), text) for path, text in files], list(derived))


class Figure:
    """A figure drawn by the library: its SVG text (``svg``), shown inline
    by Jupyter (``_repr_svg_``), and written as SVG, PNG (2 pixels per page
    unit), PDF (vector, the bundled faces embedded) or TikZ (a picture for
    a LaTeX book, :meth:`tikz`) by :meth:`save`."""

    __slots__ = ("_svg", "_request")

    def __init__(self, svg: str, request: Optional[Tuple[str, Dict[str, Any]]] = None) -> None:
        self._svg = svg
        self._request = request

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

    def tikz(self, standalone: bool = False) -> str:
        """The figure as a TikZ picture for a LaTeX book (docs/tikz.md): its
        lines TikZ paths, its letters nodes that LaTeX sets in the book's
        fonts, placed as in the SVG; with ``standalone`` a document of its
        own that pdfLaTeX and LuaLaTeX compile, as ``figure --out FILE.tex
        --tikz-standalone`` writes it. A figure not drawn by :func:`figure`
        raises ``ValueError``."""
        if self._request is None:
            raise ValueError("this figure was not drawn by figure(): it has no TikZ")
        name, options = self._request
        return _core.figure(name, tikz=bool(standalone), **options)

    def save(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Writes the figure to ``path`` in the format its extension names
        (.svg, .png, .pdf, .tex for :meth:`tikz`'s picture; SVG without
        one), whole or not at all, as ``figure --out`` does; any other
        extension raises ``ValueError``."""
        target = os.fspath(path)
        if os.path.splitext(target)[1].lower() == ".tex":
            _write((target, self.tikz()))
        else:
            _core.save(self._svg, target)

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
    mass: Optional[float] = None,
    fluctuation: Optional[float] = None,
    bore: Optional[float] = None,
    gas_force: Optional[float] = None,
    mirror: Optional[bool] = None,
    width: Union[None, float, str] = None,
    height: Union[None, float, str] = None,
    title: Optional[str] = None,
    coupler: Union[None, float, Tuple[float, float]] = None,
    rod_mass: Optional[float] = None,
    rod_cg: Optional[float] = None,
    rod_gyration: Optional[float] = None,
    cranks: Union[None, str, Sequence[float]] = None,
    planes: Union[None, str, Sequence[float]] = None,
    gravity: Optional[str] = None,
    friction: Optional[float] = None,
) -> Figure:
    """The named figure (one of :data:`FIGURES`), as ``slider-crank figure
    NAME`` draws it; each option is the flag of that name (``None``: the
    figure's own).

    ``crank``, ``rod``, ``offset``: the mechanism; ``angle``: the crank
    angle drawn (degrees; the plane's tilt for ``ng-fig-2-incline``);
    ``rpm`` or ``omega``: the crank speed; ``layers``: a list or a
    comma-separated string (mechanism, angles, dimensions, centrodes,
    coupler, polar, virtual-centres, velocity, klein, kisch, ritterhaus,
    bennett, torque, motion, polygons, scales); ``style``: ``textbook`` or ``handout``; ``font``:
    ``new-computer-modern`` or ``libertinus-serif``; ``data``: a CSV file
    of measured data; ``fit``: ``origin``, ``intercept`` or ``both``;
    ``unit``, ``force_unit``: unit names; ``notation``: ``textbook`` or
    ``ng``; ``mass``: the reciprocating mass of the engine dynamics
    figures (default 10); ``fluctuation``: the flywheel's coefficient of
    fluctuation of speed (default 0.02); ``bore``: the cylinder's bore on
    which the indicator diagram ``data`` acts; ``gas_force``: a constant
    gas force in place of a diagram; ``mirror``: the cylinder on the left
    (True) or right (False);
    ``width``, ``height``: page units (800) or a size (``"120mm"``,
    ``"4.5in"``); ``title``: set below the figure; ``coupler``: the
    point Q of a mechanism figure's rod, ``t`` along it from A (0) to B
    (1) or ``(t, h)`` with ``h`` rod lengths off its line, to the left of
    A to B (default 0.5, the rod's middle); ``rod_mass``,
    ``rod_cg``, ``rod_gyration``: the connecting rod of
    ``crank-pin-loads`` (default 0.6 of ``mass``, ``l/3`` from the crank
    pin, ``0.3 l``); ``cranks``, ``planes``: the cylinders of
    ``inline-balance``, a list or a comma-separated string, read by the
    library as the flag's value is (default cranks 0, 120, 240 and a pitch
    of 1 about the middle of the engine); ``gravity``
    (``"towards-crank"``, the cylinder above the crank, or
    ``"away-from-crank"``) and ``friction`` (the slider's coefficient of
    friction in its guides) of ``turning-moment``, ``flywheel`` and
    ``crank-pin-loads``.
    """
    options = _figure_options(locals())
    return Figure(_core.figure(name, **options), (name, options))


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
    dynamics = {
        k: _option(given.get(k))
        for k in (
            "mass", "fluctuation", "bore", "gas_force", "rod_mass", "rod_cg", "rod_gyration",
            "friction",
        )
    }
    lists = {k: _numbers(given.get(k)) for k in ("cranks", "planes")}
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
        **dynamics,
        mirror=mirror,
        width=_length(width),
        height=_length(height),
        title=title,
        coupler=_coupler(given.get("coupler")),
        **lists,
        gravity=given.get("gravity"),
    )


def _coupler(given: Union[None, float, Tuple[float, float]]) -> Optional[Tuple[float, float]]:
    """``coupler`` as the native call takes it: ``(t, h)``."""
    if given is None:
        return None
    if isinstance(given, tuple):
        t, h = given
        return (_real(t), _real(h))
    return (_real(given), 0.0)


def _numbers(given: Union[None, str, Sequence[float]]) -> Union[None, str, "list[float]"]:
    """A list of numbers given as a list, or a comma-separated string,
    which the library reads as the command line reads the flag's value."""
    if isinstance(given, str):
        return given
    return _reals(given)



def table(
    name: str,
    format: str = "text",
    *,
    n: Optional["list[float]"] = None,
    angles: Optional[npt.ArrayLike] = None,
    crank: Optional[float] = None,
    rod: Optional[float] = None,
    offset: Optional[float] = None,
    rpm: Optional[float] = None,
    omega: Optional[float] = None,
    torque: Optional[float] = None,
    friction: Optional[float] = None,
    decimals: Optional[int] = None,
    unit: Optional[str] = None,
    force_unit: Optional[str] = None,
    mass: Optional[float] = None,
    rod_mass: Optional[float] = None,
    rod_cg: Optional[float] = None,
    rod_gyration: Optional[float] = None,
    gas_force: Optional[float] = None,
    indicator: Union[None, str, "os.PathLike[str]"] = None,
    bore: Optional[float] = None,
    phases: Optional[Sequence[float]] = None,
    fluctuation: Optional[float] = None,
    flywheel: Optional[float] = None,
    cranks: Optional[Sequence[float]] = None,
    planes: Optional[Sequence[float]] = None,
    order: Optional[int] = None,
    fractions: Optional[Sequence[float]] = None,
    wheel: Optional[float] = None,
    speed: Optional[float] = None,
    load: Optional[float] = None,
    axes: Optional[Sequence[float]] = None,
    inversion: Optional[int] = None,
    lever: Optional[float] = None,
    max_cells: int = _core.DEFAULT_MAX_CELLS,
    gravity: Optional[str] = None,
) -> str:
    """A table as ``slider-crank table NAME`` prints it: ``obliquity``,
    ``acceleration-factor`` (the textbook's), ``kinematics`` (a θ sweep),
    ``forces`` (Ng's Table 2), ``dynamics`` (an engine's forces and
    torques against θ, the turn's mean torque, fluctuation of energy and
    flywheel in its notes), ``balance`` (an in-line engine's unbalanced
    primary and secondary forces and couples against θ, the polygons'
    resultants and the verdict in its notes; see :func:`balance`) or
    ``harmonics`` (the piston acceleration's series of harmonics and each
    cut's error; see :func:`harmonics`); ``format`` is ``text``, ``markdown`` or
    ``csv``. Each keyword is the flag of that name (``None``: the table's
    default): ``n`` the ratios l/r (``math.inf`` for the infinitely long
    rod), ``angles`` the crank angles in degrees (any array-like),
    ``crank``, ``rod``, ``offset`` the mechanism of ``kinematics``,
    ``forces`` and ``dynamics``, ``rpm`` or ``omega`` the speed, ``torque``
    and ``friction`` the load of ``forces``, ``decimals`` the digits
    printed; ``mass`` … ``bore`` the engine of ``dynamics`` (as in
    :meth:`SliderCrank.at`; without any, the example mass m = 10), with
    ``gravity`` and ``friction`` (the guides' friction, 0 by default),
    ``phases`` its cylinders' crank angles, ``fluctuation`` (C_s) or
    ``flywheel`` (I) its flywheel note; ``cranks`` the crank angles of the
    cylinders of ``balance`` (degrees ahead of the first; the flat four
    0, 180, 180, 0 by default) and ``planes`` their distances from the
    reference plane (a pitch of 1 about the middle by default), ``order``
    the harmonics cos 2θ … cos 2Kθ of ``harmonics`` (3 by default); for
    both, n = l/r is ``rod`` / ``crank`` (§35's 6 by default).
    ``partial-balance`` (a single cylinder's unbalanced force for each of
    the ``fractions`` c balanced, 0, ½, ⅔ and 1 by default) takes
    ``wheel``, ``speed``, ``mass`` and ``crank`` (and ``load``) for a
    locomotive's hammer blow (see :func:`hammer_blow`); ``radial``
    (cylinders on one crank, see :func:`radial`) takes their ``axes``
    (the 90° V-twin, −45 and 45, by default) and n = ``rod`` / ``crank``;
    ``quick-return`` (the tool's motion of inversion 3, or 2 with
    ``inversion=2``) takes ``lever``, the arm of the slotted link that
    drives the tool (l + r by default), and the mechanism (Fig. 60's chain
    r = 0.5, l = 1.5 by default) and speed. The keywords fill the
    library's request of the table, the one the command line's flags
    fill, and it checks them: a keyword the table does not use raises
    ``ValueError``, as the command line refuses the flag, and so does
    every value the command line refuses, in its words.

    ``max_cells`` bounds the values the table computes, rows × columns,
    with the command line's guard and default (``--max-cells``, 50 000 000,
    about a gigabyte of text): a larger table raises ``ValueError`` naming
    its size and the ``max_cells`` that would allow it, before any row is
    computed (``angles`` are read in place, not copied). The text is built
    in memory, about 15 to 20 bytes a value.
    """
    return _core.table(
        name,
        format,
        n=_reals(n),
        angles=None if angles is None else _angles(angles).reshape(-1),
        crank=_option(crank),
        rod=_option(rod),
        offset=_option(offset),
        rpm=_option(rpm),
        omega=_option(omega),
        torque=_option(torque),
        friction=_option(friction),
        decimals=decimals,
        unit=unit,
        force_unit=force_unit,
        mass=_option(mass),
        rod_mass=_option(rod_mass),
        rod_cg=_option(rod_cg),
        rod_gyration=_option(rod_gyration),
        gas_force=_option(gas_force),
        indicator=None if indicator is None else os.fspath(indicator),
        bore=_option(bore),
        phases=_reals(phases),
        fluctuation=_option(fluctuation),
        flywheel=_option(flywheel),
        cranks=_reals(cranks),
        planes=_reals(planes),
        order=None if order is None else _order(order),
        fractions=_reals(fractions),
        wheel=_option(wheel),
        speed=_option(speed),
        load=_option(load),
        axes=_reals(axes),
        inversion=inversion,
        lever=_option(lever),
        max_cells=_max_cells(max_cells),
        gravity=gravity,
    )


def _reals(values: Optional[Sequence[float]]) -> Optional["list[float]"]:
    return None if values is None else [_real(x) for x in values]


def _order(order: int) -> int:
    """``order`` checked as a count of harmonics (the library refuses 0
    and more than it gives)."""
    if isinstance(order, bool) or not isinstance(order, numbers.Integral):
        raise TypeError(f"order must be an integer, got {type(order).__name__} {order!r}")
    if not 0 <= order < 2**64:
        raise ValueError(
            f"order = {order} is out of range: the series runs to cos 2kθ "
            f"with k from 1 to {_core.MAX_ORDER}"
        )
    return int(order)


def balance(
    cranks: Optional[Sequence[float]] = None,
    planes: Optional[Sequence[float]] = None,
    n: float = 6.0,
) -> InlineBalance:
    """The balance of the reciprocating masses of an in-line engine, as
    ``table balance --cranks … --planes …`` works it out in its notes
    (:class:`InlineBalance`): cylinder i's crank at ``cranks[i]`` degrees
    ahead of the first's (the flat four 0, 180, 180, 0 by default), its
    line of stroke at ``planes[i]`` from the reference plane along the
    shaft (a pitch of 1 about the middle of the engine by default, where
    the textbooks take the plane: a couple depends on the plane where its
    force is not balanced), and the ratio ``n`` = l/r of every cylinder
    (§35's 6 by default; the command line's ``--rod`` / ``--crank``).
    Values are per unit m r ω². Bad input (no cylinder or more than 64,
    lists of different lengths, a value not finite, n ≤ 1) raises
    ``ValueError`` with the command line's message.

    >>> four = balance([0, 180, 180, 0], n=4)
    >>> four.primary_force.balanced, four.primary_couple.balanced, four.secondary_force.amplitude
    (True, True, 1.0)
    >>> balance([0, 120, 240, 240, 120, 0]).balanced
    True
    """
    return InlineBalance._from_json(_core.inline_balance(_reals(cranks), _reals(planes), _real(n)))


def harmonics(n: float = 6.0, order: int = _core.DEFAULT_ORDER) -> Harmonics:
    """The piston's acceleration of an in-line engine of ratio ``n`` = l/r
    (§35's 6 by default; at least 1.01) as its series of harmonics to
    cos 2kθ, k = ``order`` (3 by default, at most 1000), with the largest
    error of each truncation, as ``table harmonics --order K`` gives them
    (:class:`Harmonics`); bad input raises ``ValueError`` with the command
    line's message.

    >>> h = harmonics(4, order=2)
    >>> round(h.coefficients[0], 6), len(h.truncation_error)   # A₂ ≈ 1/n + 1/(4n³)
    (0.254025, 3)
    """
    v = json.loads(_core.harmonics(_real(n), _order(order)))
    return Harmonics(v["n"], tuple(v["coefficients"]), tuple(v["truncation_error"]))


def radial(axes: Optional[Sequence[float]] = None, n: float = 6.0) -> RadialBalance:
    """Cylinders working on one crank, as ``table radial --axes …`` works
    them out in its notes (:class:`RadialBalance`): their axes at ``axes``
    degrees from the reference line (the 90° V-twin, −45 and 45, by
    default; a V of included angle 2α is −α, α, a radial engine of k
    cylinders 360/k apart) and the ratio ``n`` = l/r of every cylinder
    (§35's 6 by default). Values are per unit m r ω². Bad input (no
    cylinder or more than 64, an axis not finite, n ≤ 1) raises
    ``ValueError`` with the command line's message.

    >>> v = radial()
    >>> v.primary_direct.amplitude, v.primary_reverse.balanced
    (1.0, True)
    >>> radial([0, 120, 240], n=4).secondary_reverse.amplitude
    0.375
    """
    return RadialBalance._from_json(_core.radial(_reals(axes), _real(n)))


def hammer_blow(
    fraction: float,
    mass: float,
    crank: float,
    wheel: float,
    speed: float,
    load: Optional[float] = None,
) -> Tuple[float, Optional[float]]:
    """The hammer blow c m r ω² of a locomotive's coupled wheel of diameter
    ``wheel`` rolling at ``speed`` (length unit per second; ω = 2v/D), with
    the fraction ``fraction`` of the reciprocating mass
    ``mass`` on the crank of radius ``crank`` balanced, in the force unit,
    and the speed at which it equals the wheel's static ``load`` on the
    rail (``None`` without a load, or with nothing balanced), as ``table
    partial-balance --wheel D --speed V --mass M --crank R --load P`` notes
    them. Bad values raise ``ValueError`` with the command line's message.

    >>> round(hammer_blow(2 / 3, 180, 0.3, 1.8, 25)[0], 1)
    27777.8
    """
    return _core.hammer_blow(
        _real(fraction), _real(mass), _real(crank), _real(wheel), _real(speed), _option(load)
    )


def two_plane_balance(
    masses: Sequence[Tuple[float, float, float]], planes: Tuple[float, float]
) -> "list[Tuple[float, float, float]]":
    """The two balance masses, in the planes ``planes`` (the wheels' of a
    locomotive, the ends of a crank shaft), that balance the revolving
    ``masses``, each ``(m r, angle, plane)``: the mass times its radius,
    its angle in degrees from the first crank in the sense of rotation and
    its plane's distance along the shaft. Each balance is returned the
    same way, its angle in [0, 360). Bad values (no mass, one not finite,
    the two planes the same) raise ``ValueError`` with the library's
    message (docs/dynamics.md §6).

    >>> [tuple(round(v, 6) for v in b) for b in two_plane_balance([(1, 0, 0)], (-1, 1))]
    [(0.5, 180.0, -1.0), (0.5, 180.0, 1.0)]
    """
    given = [(_real(m), _real(a), _real(x)) for m, a, x in masses]
    return _core.two_plane_balance(given, (_real(planes[0]), _real(planes[1])))


def _gallery_asked(
    only: Union[None, str, "list[str]", Tuple[str, ...]],
    manifest: Union[None, str, "os.PathLike[str]"],
) -> "Tuple[Optional[list[str]], Optional[str]]":
    """The keywords ``only`` and ``manifest`` as the library takes them (a
    string is one entry, which the library splits at its commas as it
    splits ``--only``)."""
    if isinstance(only, str):
        only = [only]
    return (
        None if only is None else list(only),
        None if manifest is None else os.fspath(manifest),
    )


def gallery(
    out: Union[str, "os.PathLike[str]"] = "gallery",
    only: Union[None, str, "list[str]", Tuple[str, ...]] = None,
    manifest: Union[None, str, "os.PathLike[str]"] = None,
) -> "list[str]":
    """Writes the gallery into the directory ``out`` (made if missing), as
    ``slider-crank gallery --out DIR`` does: every named figure as SVG,
    PNG and PDF, the textbook's tables and an ``index.html`` captioning
    each figure with the section it reproduces; ``only`` limits it to
    some figures (a list or a comma-separated string), or ``manifest``,
    a TOML file, says what it holds (figures, scene files, formats, style
    and face, as `gallery --manifest` reads it), not both. The files are
    written all or none, by the command's own writer: each staged under
    a ``.slider-crank-gallery-`` name in ``out`` and renamed into place
    only when every one is made (a symbolic link of a gallery's name
    replaced, not followed; a name that is a directory or write-protected
    refused first, with ``OSError``), so a failure leaves the old gallery
    whole. Returns the names of the files. :func:`gallery_differences`
    compares a directory with the gallery instead."""
    asked = _gallery_asked(only, manifest)
    return _core.gallery(os.fspath(out), *asked)


def gallery_differences(
    out: Union[str, "os.PathLike[str]"] = "gallery",
    only: Union[None, str, "list[str]", Tuple[str, ...]] = None,
    manifest: Union[None, str, "os.PathLike[str]"] = None,
) -> "list[tuple[str, str]]":
    """Compares the gallery :func:`gallery` would write into ``out`` with
    the files there, writing nothing, as ``slider-crank gallery --check``
    does: each file that differs, is missing, is not a regular file or
    was left by an interrupted gallery, as its path and those words
    (``"differs"``, ``"is missing"``). An empty list: ``out`` holds the
    gallery this build makes."""
    asked = _gallery_asked(only, manifest)
    return [(os.fspath(p), w) for p, w in _core.gallery_differences(os.fspath(out), *asked)]


def animate(
    name: str = "fig-66-kisch",
    out: Union[None, str, "os.PathLike[str]"] = None,
    *,
    frames: int = _core.DEFAULT_FRAMES,
    period: float = _core.DEFAULT_PERIOD,
    projector: bool = False,
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
    coupler: Union[None, float, Tuple[float, float]] = None,
) -> str:
    """One revolution of a mechanism figure in ``frames`` poses played in
    ``period`` seconds, as ``slider-crank animate NAME --out FILE`` makes
    it: a self-playing SVG, or an HTML page with a slider when ``out``
    ends in ``.html`` (or, without ``out``, ``html=True``). The options
    are :func:`figure`'s (``angle``: the first frame's); ``projector``
    leaves out the enlarged detail about the crank, for a page shown
    large. Returns the text; writes it to ``out`` too when given."""
    options = _figure_options({**locals(), "data": None, "fit": None})
    path = os.fspath(out) if out is not None else ("animation.html" if html else "animation.svg")
    asked = (int(frames), _real(period), bool(projector), path)
    text = _core.figure(name, animate=asked, **options)
    if out is not None:
        _write((out, text))
    return text


class ChainAnalysis:
    """What ``slider-crank analyze --json`` prints at one angle for a
    chain of Fig. 60 (``--links``, ``--slot-radius`` or ``--inversion``):
    :meth:`to_dict` gives that object whole, ``chain["analytic"]`` (or any
    other member) a part of it; ``points`` and ``virtual_centres`` are
    those members with each point as in :class:`Analysis` (an
    :class:`AtInfinity` or :class:`Indeterminate` where the JSON writes
    one; empty where the JSON has none). Rates the pose leaves undefined
    (at a toggle) are ``None``, the JSON's ``null``. ``assumed_rpm`` is
    the crank speed assumed because none was given (250 rpm), ``None`` when
    ``rpm`` or ``omega`` was (see :meth:`SliderCrank.at`)."""

    __slots__ = ("_json", "points", "virtual_centres", "assumed_rpm")

    def __init__(self, text: str, assumed_rpm: Optional[float] = None) -> None:
        self._json: Dict[str, Any] = json.loads(text)
        self.assumed_rpm: Optional[float] = assumed_rpm
        points = self._json.get("points", {})
        self.points: Dict[str, Optional[Centre]] = {
            k: None if p is None else _centre(p) for k, p in points.items()
        }
        self.virtual_centres: Dict[str, Centre] = {
            k: _centre(c) for k, c in self._json["virtual_centres"].items()
        }

    @property
    def angle_deg(self) -> float:
        """The crank angle θ in degrees."""
        return float(self._json["angle_deg"])

    @property
    def omega(self) -> float:
        """The driving link's speed in rad/s."""
        return float(self._json["omega"])

    def __getitem__(self, key: str) -> Any:
        value = self._json[key]
        return json.loads(json.dumps(value)) if isinstance(value, (dict, list)) else value

    def to_dict(self) -> Dict[str, Any]:
        """The object ``analyze --json`` prints, as a new dict."""
        copy: Dict[str, Any] = json.loads(json.dumps(self._json))
        return copy

    def __repr__(self) -> str:
        return f"<ChainAnalysis at θ = {self.angle_deg}°: {', '.join(self._json)}>"


@dataclass(frozen=True)
class CheckRow:
    """One quantity of a check: the worst scaled difference between the
    two formulations (a construction and the analytic core for the
    engine), the condition number κ there, the crank angle where it is,
    the poses compared and whether it passed (worst ≤ tolerance × κ; for
    the engine, the worst of difference / κ in ulps, ``ulps``, within the
    allowance, else ``ulps`` is ``None``)."""

    name: str
    worst: float
    condition: float
    at_deg: float
    poses: int
    passed: bool
    ulps: Optional[float] = None


@dataclass(frozen=True)
class CheckReport:
    """The result of ``slider-crank check``: the report it
    prints (``text``, also ``str(report)``), whether every quantity passed
    (the command's exit status 0) and the rows."""

    text: str
    passed: bool
    rows: Tuple[CheckRow, ...]

    def __str__(self) -> str:
        return self.text

    @classmethod
    def _from(cls, result: Tuple[str, bool, "list[Any]"]) -> "CheckReport":
        text, passed, rows = result
        return cls(text, passed, tuple(CheckRow(*r) for r in rows))


def _chain_report(samples: int, tolerance: Optional[float], max_cells: int, **chain: Any) -> CheckReport:
    """``slider-crank check`` of the chain ``chain`` names (``links``,
    ``slot`` or ``inversion``, as the native ``chain_check`` takes it),
    its options checked as the command line checks them."""
    result = _core.chain_check(
        samples=_samples(samples),
        tolerance=_option(tolerance),
        max_cells=_max_cells(max_cells),
        **chain,
    )
    return CheckReport._from(result)


def _assumed_rpm(rpm: Optional[float], omega: Optional[float]) -> Optional[float]:
    """The speed assumed when neither ``rpm`` nor ``omega`` is given (the
    command line's default), else ``None``."""
    return _core.DEFAULT_RPM if rpm is None and omega is None else None


def _max_cells(max_cells: int) -> int:
    """``max_cells`` checked as ``--max-cells`` is: a count of values."""
    if isinstance(max_cells, bool) or not isinstance(max_cells, numbers.Integral):
        raise TypeError(
            f"max_cells must be an integer, got {type(max_cells).__name__} {max_cells!r}"
        )
    if not 0 <= max_cells < 2**64:
        raise ValueError(f"invalid max_cells {max_cells}: expected a count from 0 to 2⁶⁴ − 1")
    return int(max_cells)


def _samples(samples: int) -> int:
    if isinstance(samples, bool) or not isinstance(samples, numbers.Integral):
        raise TypeError(f"samples must be an integer, got {type(samples).__name__} {samples!r}")
    if samples < 0:
        raise ValueError(f"samples = {samples} is out of range: give at least 1 pose")
    return int(samples)


class QuadricChain:
    """The quadric crank chain of Fig. 60 a (``analyze --links
    a,b,c,d``): crank ``crank`` a, coupler ``coupler`` b, lever ``lever``
    c and frame ``frame`` d, in the length unit ``unit``; ``assembly``
    ``"open"`` (A to the left of the diagonal from B to O_cd) or
    ``"crossed"``. Lengths are validated as the command line validates
    them (positive, finite, the chain closes), errors raised as
    ``ValueError`` with its messages.

    >>> chain = QuadricChain(1, 3, 2.5, 3)
    >>> chain.at(30, omega=1)["mechanism"]["grashof"]
    'crank_rocker'
    """

    __slots__ = ("_links", "_assembly", "_unit", "_force_unit")

    def __init__(
        self,
        crank: float,
        coupler: float,
        lever: float,
        frame: float,
        assembly: str = "open",
        unit: str = "ft",
        force_unit: str = "lbf",
    ) -> None:
        links = (_real(crank), _real(coupler), _real(lever), _real(frame))
        _core.check_quadric(links, assembly)
        _core.check_engine(1.0, 2.0, 0.0, unit, force_unit)
        self._links: Tuple[float, float, float, float] = links
        self._assembly: str = assembly
        self._unit: str = unit
        self._force_unit: str = force_unit

    @property
    def links(self) -> Tuple[float, float, float, float]:
        """The lengths a, b, c, d."""
        return self._links

    @property
    def assembly(self) -> str:
        """The assembly mode, ``open`` or ``crossed``."""
        return self._assembly

    def __repr__(self) -> str:
        a, b, c, d = self._links
        return (
            f"QuadricChain(crank={a!r}, coupler={b!r}, lever={c!r}, frame={d!r}, "
            f"assembly={self._assembly!r}, unit={self._unit!r}, force_unit={self._force_unit!r})"
        )

    def at(
        self, theta_deg: float, rpm: Optional[float] = None, omega: Optional[float] = None
    ) -> ChainAnalysis:
        """The chain at crank angle ``theta_deg`` as ``analyze --links
        --json`` prints it: points, the coupler's and lever's angles and
        rates (``None`` at a toggle), the Grashof class, the crank's reach
        and the six virtual centres. A crank angle the crank cannot reach
        (a rocker) raises ``ValueError``. Speed as in :meth:`SliderCrank.at`."""
        text = _core.analyze(
            links=self._links,
            assembly=self._assembly,
            angle=_real(theta_deg),
            rpm=_option(rpm),
            omega=_option(omega),
            unit=self._unit,
            force_unit=self._force_unit,
        )
        return ChainAnalysis(text, _assumed_rpm(rpm, omega))

    def check(
        self,
        samples: int = 100_000,
        tolerance: Optional[float] = None,
        *,
        max_cells: int = _core.DEFAULT_MAX_CELLS,
    ) -> CheckReport:
        """``slider-crank check --links``: the chain's two formulations
        compared over ``samples`` crank angles in both assembly modes; a
        difference passes when at most ``tolerance`` (1e-12 by default) × κ;
        ``max_cells`` as in :meth:`SliderCrank.check`."""
        return _chain_report(samples, tolerance, max_cells, links=self._links)


class CurvedSlot:
    """An engine with its block in a circular slot (Fig. 60 b, ``analyze
    --slot-radius ρ``): the slot's centre O_cd at (0, e − ρ), below the
    stroke for ρ > 0, above it for ρ < 0; |ρ| must exceed (l + r + e)/2
    (ρ > 0) or (l + r − e)/2 (ρ < 0). Made by
    :meth:`SliderCrank.curved_slot`."""

    __slots__ = ("_engine", "_radius")

    def __init__(self, engine: SliderCrank, slot_radius: float) -> None:
        radius = _real(slot_radius)
        _core.check_slot(engine.crank, engine.rod, engine.offset, radius)
        self._engine: SliderCrank = engine
        self._radius: float = radius

    @property
    def slot_radius(self) -> float:
        """The slot's radius ρ."""
        return self._radius

    def __repr__(self) -> str:
        return f"{self._engine!r}.curved_slot({self._radius!r})"

    def at(
        self, theta_deg: float, rpm: Optional[float] = None, omega: Optional[float] = None
    ) -> ChainAnalysis:
        """The chain at crank angle ``theta_deg`` as ``analyze
        --slot-radius --json`` prints it: the block's arc position and its
        rates, exact and read off the construction (``None`` where the
        construction leaves them undefined), the rod's and lever's angles
        and rates, and the six virtual centres."""
        return self._engine._chain_at(
            theta_deg, rpm, omega, slot_radius=self._radius
        )

    def check(
        self,
        samples: int = 100_000,
        tolerance: Optional[float] = None,
        *,
        max_cells: int = _core.DEFAULT_MAX_CELLS,
    ) -> CheckReport:
        """``slider-crank check --slot-radius``: the slot's construction
        against the exact values over ``samples`` crank angles; a
        difference passes when at most ``tolerance`` (1e-12 by default) × κ;
        ``max_cells`` as in :meth:`SliderCrank.check`."""
        e = self._engine
        slot = (e.crank, e.rod, e.offset, self._radius)
        return _chain_report(samples, tolerance, max_cells, slot=slot)


class Inversion:
    """An inversion of the slider-crank chain (``analyze --inversion
    N``): the same four links with another fixed. ``number`` 1 fixes the
    frame d (the engine), 2 the crank a (the rotating block), 3 the rod b
    (the oscillating cylinder), 4 the slider c (the hand pump). The crank
    angle is the crank's against the frame and the speed that of the
    driving link. Made by :meth:`SliderCrank.inversion`."""

    __slots__ = ("_engine", "_number")

    def __init__(self, engine: SliderCrank, number: int) -> None:
        if isinstance(number, bool) or not isinstance(number, numbers.Integral):
            raise TypeError(f"the inversion is a number 1 to 4, got {number!r}")
        n = int(number)
        if not 0 <= n < 2**32:
            raise ValueError(f"invalid inversion {n}: expected 1, 2, 3 or 4")
        _core.check_inversion(engine.crank, engine.rod, engine.offset, n)
        self._engine: SliderCrank = engine
        self._number: int = n

    @property
    def number(self) -> int:
        """The inversion's number, 1 to 4."""
        return self._number

    @property
    def figure_name(self) -> str:
        """The name of this inversion's figure (``inversion-2-rotating-block``)."""
        prefix = f"inversion-{self._number}-"
        return next(n for n in FIGURES if n.startswith(prefix))

    def __repr__(self) -> str:
        return f"{self._engine!r}.inversion({self._number})"

    def at(
        self, theta_deg: float, rpm: Optional[float] = None, omega: Optional[float] = None
    ) -> ChainAnalysis:
        """The inversion at crank angle ``theta_deg`` as ``analyze
        --inversion --json`` prints it: its name, the fixed and driving
        links, each link's angular velocity and acceleration, the sliding
        velocity and acceleration (``None`` where the driver stands at a
        dead point), the quick-return time ratio and the six virtual
        centres."""
        return self._engine._chain_at(theta_deg, rpm, omega, inversion=self._number)

    def check(
        self,
        samples: int = 100_000,
        tolerance: Optional[float] = None,
        *,
        max_cells: int = _core.DEFAULT_MAX_CELLS,
    ) -> CheckReport:
        """``slider-crank check --inversion N``: the velocity and
        acceleration polygons of inversion 2 or 3, the Coriolis component
        among them, against the exact values over ``samples`` crank angles
        and the dead centres; a difference passes when at most
        ``tolerance`` (1e-12 by default) × κ; ``max_cells`` as in
        :meth:`SliderCrank.check`. Inversions 1 and 4 have no polygons of
        their own (the engine's check covers their relative motion) and
        raise ``ValueError``, as the command refuses them."""
        e = self._engine
        inversion = (e.crank, e.rod, e.offset, self._number)
        return _chain_report(samples, tolerance, max_cells, inversion=inversion)

    def figure(self, **options: Any) -> Figure:
        """This inversion's figure drawn for the engine (see
        :meth:`SliderCrank.figure`)."""
        return self._engine.figure(self.figure_name, **options)
