"""The native half of the ``slider_crank`` package (PyO3): plain values in,
JSON text, SVG text, bytes or filled numpy arrays out. Use the classes of
``slider_crank``; these functions are their implementation."""

from typing import Optional

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
    "VERSION",
]

VERSION: str

def check_engine(
    crank: float, rod: float, offset: float, unit: str, force_unit: str
) -> None: ...
def crank_speed(rpm: Optional[float] = None, omega: Optional[float] = None) -> float: ...
def analyze(
    crank: float,
    rod: float,
    offset: float,
    unit: str,
    force_unit: str,
    degrees: float,
    omega: float,
    torque: Optional[float] = None,
    friction: float = 0.0,
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
    mirror: Optional[bool] = None,
    width: Optional[str] = None,
    height: Optional[str] = None,
    title: Optional[str] = None,
    animate: Optional[tuple[int, float, str]] = None,
) -> str: ...
def encode(svg: str, format: str) -> bytes: ...
def save(svg: str, path: str) -> None: ...
def figure_names() -> list[str]: ...
def handout(
    crank: float,
    rod: float,
    offset: float,
    unit: str,
    force_unit: str,
    degrees: float,
    omega: float,
    which: str,
    paper: str = "a4",
    torque: Optional[float] = None,
    friction: float = 0.0,
) -> str: ...
def table(
    name: str,
    format: str = "text",
    n: Optional[list[float]] = None,
    angles: Optional[list[float]] = None,
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
) -> str: ...
def gallery(out: str, only: Optional[list[str]] = None) -> list[str]: ...
