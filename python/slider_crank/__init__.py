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

# No module is imported here but the package's own: what this namespace
# holds is the API (``__all__``), its version and two private modules.
# ``tests/test_api.py`` holds it to that.
from . import _api, _core
from ._api import (
    FIGURES,
    Analysis,
    AtInfinity,
    BalanceSweep,
    Centre,
    ChainAnalysis,
    CheckReport,
    CheckRow,
    CurvedSlot,
    Dynamics,
    DynamicsSweep,
    EngineLoads,
    Figure,
    Flywheel,
    GraphicalSweep,
    GraphicalValues,
    Harmonics,
    Indeterminate,
    InlineBalance,
    Inversion,
    Lobe,
    Point,
    QuadricChain,
    RadialBalance,
    Resultant,
    RodDynamics,
    SliderCrank,
    Statics,
    Sweep,
    TurningMoment,
    Unbalanced,
    Values,
    animate,
    balance,
    figure,
    gallery,
    gallery_differences,
    hammer_blow,
    harmonics,
    radial,
    table,
    two_plane_balance,
)

__all__ = [
    "SliderCrank",
    "Analysis",
    "Values",
    "GraphicalValues",
    "Statics",
    "Dynamics",
    "RodDynamics",
    "Unbalanced",
    "EngineLoads",
    "DynamicsSweep",
    "TurningMoment",
    "Lobe",
    "Flywheel",
    "InlineBalance",
    "Resultant",
    "BalanceSweep",
    "Harmonics",
    "RadialBalance",
    "QuadricChain",
    "CurvedSlot",
    "Inversion",
    "ChainAnalysis",
    "CheckReport",
    "CheckRow",
    "AtInfinity",
    "Indeterminate",
    "Point",
    "Centre",
    "Sweep",
    "GraphicalSweep",
    "Figure",
    "figure",
    "table",
    "gallery",
    "gallery_differences",
    "animate",
    "balance",
    "harmonics",
    "radial",
    "hammer_blow",
    "two_plane_balance",
    "FIGURES",
]

__version__: str = _core.VERSION


def _claim(item: object) -> None:
    """Names this package as the home of ``item`` (a class or function of
    ``_api``) and of its methods, so that ``help()``, ``repr``, pickling
    and doctest see ``slider_crank.SliderCrank`` rather than the private
    module that defines it."""
    if not isinstance(item, type) and not callable(item):
        return
    if getattr(item, "__module__", None) != _api.__name__:
        return
    item.__module__ = __name__
    if isinstance(item, type):
        for member in vars(item).values():
            inner = getattr(member, "__func__", member)
            if callable(inner) and getattr(inner, "__module__", None) == _api.__name__:
                inner.__module__ = __name__


for _item in (globals()[_n] for _n in __all__):
    _claim(_item)
del _item
