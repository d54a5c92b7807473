"""Draws docs/conventions.png, the load and displacement convention of every fidelity (docs/conventions.md).

Run: .venv/bin/python docs/conventions_figure.py. The ball positions come from the kernel that places the balls
(bearing_fmu.kernels.geometry.ball_direction), so the figure shows what the code does.
"""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Circle, FancyArrowPatch  # noqa: E402

from bearing_fmu.kernels.geometry import ball_direction  # noqa: E402

Z = 9  # drawn (an odd count: the case where the ball positions decide whether a ball sits on the load line)
PITCH, BALL = 1.0, 0.2
OUT = Path(__file__).with_name("conventions.png")


def arrow(ax, start, end, color="black", **kw):
    ax.add_patch(FancyArrowPatch(start, end, arrowstyle="-|>", mutation_scale=14, color=color, lw=1.6, **kw))


def main():
    fig, ax = plt.subplots(figsize=(8.4, 6.0))
    ax.set_aspect("equal")
    ax.axis("off")
    ax.add_patch(Circle((0, 0), PITCH + BALL + 0.16, fc="0.88", ec="k"))
    ax.add_patch(Circle((0, 0), PITCH + BALL, fc="white", ec="k"))
    ax.add_patch(Circle((0, 0), PITCH - BALL, fc="#d0d8e8", ec="k"))
    ax.add_patch(Circle((0, 0), PITCH - BALL - 0.2, fc="white", ec="k"))
    for j in range(Z):
        c, s = ball_direction(j, Z)
        ax.add_patch(Circle((PITCH * c, PITCH * s), BALL, fc="#f5c542" if j == 0 else "0.75", ec="k"))
        label = dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.8)
        ax.text(PITCH * c, PITCH * s, str(j + 1), ha="center", va="center", fontsize=11, zorder=5, bbox=label)
    arrow(ax, (0, 0), (1.75, 0))
    arrow(ax, (0, 0), (0, 1.75))
    ax.text(1.8, 0, "x", va="center", fontsize=13)
    ax.text(0.05, 1.8, "y", fontsize=13)
    ax.add_patch(Circle((0, 0), 0.06, fc="white", ec="k"))
    ax.plot(0, 0, "k.", ms=4)
    ax.text(-0.22, -0.2, "z", fontsize=13)
    arrow(ax, (-0.35, -0.3), (-0.35, 0.45), color="#c0392b")
    ax.text(-0.55, -0.45, "$F_y$, $y$", color="#c0392b", fontsize=12)
    arrow(ax, (0.5, 0.0), (0.5 * -0.643, 0.5 * 0.766), color="#1f5fa8", connectionstyle="arc3,rad=0.55")
    ax.text(0.42, 0.42, r"$\psi$", color="#1f5fa8", fontsize=14)
    arrow(ax, (1.5 * 0.866, -1.5 * 0.5), (1.5 * 0.985, 1.5 * 0.174), connectionstyle="arc3,rad=0.25")
    ax.text(1.5, 0.32, r"$\omega > 0$", fontsize=12)
    legend = (
        "z: bearing axis, toward the reader",
        r"$\psi$: azimuth from +x toward +y",
        r"ball 1 (index 0) on +y: $\psi$ = 90°",
        r"ball j+1 at $\psi$ = 90° + 360° j / Z",
        r"$F_y$ > 0 pushes the inner ring",
        "   toward +y and loads ball 1",
        r"$\theta_x$, $M_x$ and $\theta_y$, $M_y$:",
        "   right-handed about x and y",
        r"$F_z$ > 0: the thrust a single",
        "   angular-contact bearing carries",
        r"$\omega$ > 0: inner ring turns about +z",
        f"Z = {Z} drawn",
    )
    for k, line in enumerate(legend):
        ax.text(2.25, 1.45 - 0.24 * k, line, fontsize=10.5)
    ax.set_xlim(-1.6, 4.6)
    ax.set_ylim(-1.6, 1.7)
    fig.tight_layout()
    fig.savefig(OUT, dpi=110)


if __name__ == "__main__":
    main()
