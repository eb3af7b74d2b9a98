"""Per-pose cost of `SliderCrank.sweep` against numpy's vectorised closed
form, and one figure drawn in-process against matplotlib drawing the same
figure (docs/benchmarks.md). Run in the package's environment:

    python python/benchmarks/sweep_and_figure.py
"""

from __future__ import annotations

import io
import time
from typing import Callable, Dict

import numpy as np

import slider_crank as sc

N = 100_000


def best(f: Callable[[], object], repeat: int = 30) -> float:
    """The fastest of `repeat` runs, in seconds."""
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        times.append(time.perf_counter() - t)
    return min(times)


def numpy_closed_form(
    r: float, l: float, e: float, w: float, deg: np.ndarray
) -> Dict[str, np.ndarray]:
    t = np.radians(deg)
    sin, cos = np.sin(t), np.cos(t)
    s, s1 = r * sin - e, r * cos
    c = np.sqrt(l * l - s * s)
    x1 = -r * sin - s * s1 / c
    x2 = -r * cos - (s1 * s1 - s * r * sin) / c - (s * s1) ** 2 / c**3
    return {"x": r * cos + c, "v": w * x1, "a": w * w * x2}


def matplotlib_figure(engine: sc.SliderCrank, theta: float) -> str:
    """The mechanism and its velocity line CE (Fig. 63's construction),
    drawn by matplotlib as SVG text."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle, Rectangle

    p = engine.at(theta).points
    C, B, A, E = (p[k] for k in "CBAE")
    assert isinstance(C, tuple) and isinstance(B, tuple)
    assert isinstance(A, tuple) and isinstance(E, tuple)
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot([C[0], B[0], A[0]], [C[1], B[1], A[1]], "k-", lw=2)
    ax.plot([A[0], E[0]], [A[1], E[1]], "k--", lw=0.8)
    ax.plot([C[0], E[0]], [C[1], E[1]], "k-", lw=1.5)
    ax.add_patch(Circle(C, engine.crank, fill=False, lw=0.5))
    ax.add_patch(Rectangle((A[0] - 0.15, A[1] - 0.1), 0.3, 0.2, fill=False))
    ax.axhline(engine.offset, color="k", lw=0.5)
    for name, q in zip("CBAE", (C, B, A, E)):
        ax.annotate(name, q, textcoords="offset points", xytext=(4, 4), style="italic")
    ax.set_aspect("equal")
    ax.axis("off")
    out = io.StringIO()
    fig.savefig(out, format="svg")
    plt.close(fig)
    return out.getvalue()


def main() -> None:
    r, l, e, w = 0.5, 3.0, 0.1, 26.16
    engine = sc.SliderCrank(r, l, e)
    deg = np.linspace(0.0, 360.0, N)
    ns = 1e9 / N
    t_np = best(lambda: numpy_closed_form(r, l, e, w, deg))
    t_sweep = best(lambda: engine.sweep(deg, omega=w))
    t_graph = best(lambda: engine.sweep(deg, omega=w, graphical=True))
    print(f"{N} poses, ns per pose (best of 30):")
    print(f"  numpy closed form x, v, a        {t_np * ns:7.1f}")
    print(f"  sweep (x, v, a, phi, rod rates)  {t_sweep * ns:7.1f}  ({t_sweep / t_np:.2f} of numpy)")
    print(f"  sweep with the graphical values  {t_graph * ns:7.1f}  ({t_graph / t_np:.2f} of numpy)")
    t_forces = best(lambda: engine.sweep(deg, omega=w, mass=10.0, gas_force=2000.0))
    print(f"  sweep with the forces and torque {t_forces * ns:7.1f}  ({t_forces / t_np:.2f} of numpy)")
    small = deg[:1000]
    t_np_small = best(lambda: numpy_closed_form(r, l, e, w, small), repeat=200)
    t_small = best(lambda: engine.sweep(small, omega=w, graphical=True), repeat=200)
    print("1000 poses, µs a call (best of 200):")
    print(f"  numpy closed form x, v, a        {t_np_small * 1e6:7.1f}")
    print(f"  sweep with the graphical values  {t_small * 1e6:7.1f}  ({t_small / t_np_small:.2f} of numpy)")
    # a new pose for each repetition
    angles = iter(range(1, 1000))
    t_fig = best(lambda: sc.figure("fig-63-velocity", angle=next(angles)), repeat=20)
    print(f"figure fig-63-velocity in-process (SVG text)   {t_fig * 1e3:7.2f} ms")
    try:
        t_mpl = best(lambda: matplotlib_figure(engine, float(next(angles))), repeat=20)
        print(f"matplotlib, the mechanism and CE (SVG text)    {t_mpl * 1e3:7.2f} ms")
    except ImportError:
        print("matplotlib is not installed")


if __name__ == "__main__":
    main()
