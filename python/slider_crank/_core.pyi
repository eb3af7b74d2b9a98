"""The native half of the ``slider_crank`` package (PyO3): plain values in,
JSON text, SVG text, bytes or filled numpy arrays out. Use the classes of
``slider_crank``; these functions are their implementation."""

from typing import Optional, Tuple, Union, final

import numpy as np
import numpy.typing as npt

__all__ = [
    "check_engine",
    "crank_speed",
    "analyze",
    "sweep",
    "figure",
    "encode",
    "save",
    "figure_names",
    "handout",
    "table",
    "gallery",
    "gallery_differences",
    "write_files",
    "Engine",
    "check_quadric",
    "check_slot",
    "check_inversion",
    "chain_check",
    "engine_check",
    "inline_balance",
    "inline_sweep",
    "harmonics",
    "radial",
    "hammer_blow",
    "two_plane_balance",
    "VERSION",
    "EXAMPLE_MASS",
    "DYNAMICS_ROWS",
    "DEFAULT_MAX_CELLS",
    "DEFAULT_RPM",
    "DEFAULT_FRAMES",
    "DEFAULT_PERIOD",
    "BALANCE_ROWS",
    "DEFAULT_CRANKS",
    "DEFAULT_ORDER",
    "MAX_ORDER",
    "DEFAULT_FRACTIONS",
    "DEFAULT_AXES",
]

VERSION: str
EXAMPLE_MASS: float
DYNAMICS_ROWS: int
DEFAULT_MAX_CELLS: int
DEFAULT_RPM: float
DEFAULT_FRAMES: int
DEFAULT_PERIOD: float
BALANCE_ROWS: int
DEFAULT_CRANKS: list[float]
DEFAULT_ORDER: int
MAX_ORDER: int
DEFAULT_FRACTIONS: list[float]
DEFAULT_AXES: list[float]

def check_engine(
    crank: float, rod: float, offset: float, unit: str, force_unit: str
) -> None: ...
def crank_speed(rpm: Optional[float] = None, omega: Optional[float] = None) -> float: ...
def analyze(
    crank: Optional[float] = None,
    rod: Optional[float] = None,
    offset: Optional[float] = None,
    angle: Optional[float] = None,
    rpm: Optional[float] = None,
    omega: Optional[float] = None,
    torque: Optional[float] = None,
    friction: Optional[float] = None,
    unit: Optional[str] = None,
    force_unit: Optional[str] = None,
    mass: Optional[float] = None,
    rod_mass: Optional[float] = None,
    rod_cg: Optional[float] = None,
    rod_gyration: Optional[float] = None,
    gas_force: Optional[float] = None,
    indicator: Optional[str] = None,
    bore: Optional[float] = None,
    slot_radius: Optional[float] = None,
    links: Optional[Tuple[float, float, float, float]] = None,
    assembly: Optional[str] = None,
    inversion: Optional[int] = None,
    max_cells: int = ...,
    gravity: Optional[str] = None,
) -> str: ...
def sweep(
    crank: float,
    rod: float,
    offset: float,
    omega: float,
    thetas: npt.NDArray[np.float64],
    out: npt.NDArray[np.float64],
) -> None: ...
def figure(
    name: str,
    crank: Optional[float] = None,
    rod: Optional[float] = None,
    offset: Optional[float] = None,
    angle: Optional[float] = None,
    rpm: Optional[float] = None,
    omega: Optional[float] = None,
    layers: Optional[str] = None,
    style: Optional[str] = None,
    font: Optional[str] = None,
    data: Optional[str] = None,
    fit: Optional[str] = None,
    unit: Optional[str] = None,
    force_unit: Optional[str] = None,
    notation: Optional[str] = None,
    mass: Optional[float] = None,
    fluctuation: Optional[float] = None,
    bore: Optional[float] = None,
    gas_force: Optional[float] = None,
    mirror: Optional[bool] = None,
    width: Optional[str] = None,
    height: Optional[str] = None,
    title: Optional[str] = None,
    animate: Optional[tuple[int, float, bool, str]] = None,
    tikz: Optional[bool] = None,
    coupler: Optional[tuple[float, float]] = None,
    rod_mass: Optional[float] = None,
    rod_cg: Optional[float] = None,
    rod_gyration: Optional[float] = None,
    cranks: Union[None, str, list[float]] = None,
    planes: Union[None, str, list[float]] = None,
    gravity: Optional[str] = None,
    friction: Optional[float] = None,
) -> str: ...
def encode(svg: str, format: str) -> bytes: ...
def save(svg: str, path: str) -> None: ...
def figure_names() -> list[str]: ...
def handout(
    which: str,
    crank: Optional[float] = None,
    rod: Optional[float] = None,
    offset: Optional[float] = None,
    angle: Optional[float] = None,
    rpm: Optional[float] = None,
    omega: Optional[float] = None,
    unit: Optional[str] = None,
    force_unit: Optional[str] = None,
    torque: Optional[float] = None,
    friction: Optional[float] = None,
    mass: Optional[float] = None,
    fluctuation: Optional[float] = None,
    gas_force: Optional[float] = None,
    indicator: Optional[str] = None,
    bore: Optional[float] = None,
    paper: Optional[str] = None,
) -> str: ...
def table(
    name: str,
    format: str = "text",
    n: Optional[list[float]] = None,
    angles: Optional[npt.NDArray[np.float64]] = None,
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
    indicator: Optional[str] = None,
    bore: Optional[float] = None,
    phases: Optional[list[float]] = None,
    fluctuation: Optional[float] = None,
    flywheel: Optional[float] = None,
    cranks: Optional[list[float]] = None,
    planes: Optional[list[float]] = None,
    order: Optional[int] = None,
    fractions: Optional[list[float]] = None,
    wheel: Optional[float] = None,
    speed: Optional[float] = None,
    load: Optional[float] = None,
    axes: Optional[list[float]] = None,
    inversion: Optional[int] = None,
    lever: Optional[float] = None,
    max_cells: int = ...,
    gravity: Optional[str] = None,
) -> str: ...
def gallery(
    out: str, only: Optional[list[str]] = None, manifest: Optional[str] = None
) -> list[str]: ...
def gallery_differences(
    out: str, only: Optional[list[str]] = None, manifest: Optional[str] = None
) -> list[tuple[str, str]]: ...
def write_files(files: list[tuple[str, str]], derived: list[str] = ...) -> None: ...

@final
class Engine:
    def __new__(
        cls,
        crank: float,
        rod: float,
        offset: float,
        omega: float,
        mass: Optional[float] = None,
        rod_mass: Optional[float] = None,
        rod_cg: Optional[float] = None,
        rod_gyration: Optional[float] = None,
        gas_force: Optional[float] = None,
        indicator: Optional[str] = None,
        bore: Optional[float] = None,
        unit: Optional[str] = None,
        force_unit: Optional[str] = None,
        gravity: Optional[str] = None,
        friction: Optional[float] = None,
    ) -> Engine: ...
    def at(self, degrees: float, unit: str, force_unit: str) -> str: ...
    def sweep(
        self, thetas: npt.NDArray[np.float64], out: npt.NDArray[np.float64]
    ) -> None: ...
    def turning_moment(
        self,
        phases: list[float],
        fluctuation: Optional[float] = None,
        flywheel: Optional[float] = None,
    ) -> str: ...

def check_quadric(links: tuple[float, float, float, float], mode: str) -> None: ...
def check_slot(crank: float, rod: float, offset: float, rho: float) -> None: ...
def check_inversion(crank: float, rod: float, offset: float, n: int) -> None: ...
def chain_check(
    links: Optional[tuple[float, float, float, float]] = None,
    slot: Optional[tuple[float, float, float, float]] = None,
    inversion: Optional[tuple[float, float, float, int]] = None,
    samples: int = 100000,
    tolerance: Optional[float] = None,
    max_cells: int = ...,
) -> tuple[str, bool, list[tuple[str, float, float, float, int, bool]]]: ...
def engine_check(
    crank: float,
    rod: float,
    offset: float,
    samples: int = 100000,
    tolerance: Optional[float] = None,
    max_cells: int = ...,
) -> tuple[str, bool, list[tuple[str, float, float, float, int, bool, float]]]: ...
def inline_balance(
    cranks: Optional[list[float]], planes: Optional[list[float]], n: float
) -> str: ...
def inline_sweep(
    cranks: list[float],
    planes: list[float],
    n: float,
    thetas: npt.NDArray[np.float64],
    out: npt.NDArray[np.float64],
) -> None: ...
def harmonics(n: float, order: int) -> str: ...
def radial(axes: Optional[list[float]], n: float) -> str: ...
def hammer_blow(
    fraction: float,
    mass: float,
    crank: float,
    wheel: float,
    speed: float,
    load: Optional[float] = None,
) -> tuple[float, Optional[float]]: ...
def two_plane_balance(
    masses: list[tuple[float, float, float]], planes: tuple[float, float]
) -> list[tuple[float, float, float]]: ...
