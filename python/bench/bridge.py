"""The matplotlib bridge's time against matplotlib's own export, figure by figure.

    python python/bench/bridge.py [--runs N]

Prints a Markdown table: each figure saved as SVG by ``fig.savefig`` and by
``limn.matplotlib.savefig`` (median of N runs in this process), their ratio and the
files' sizes. "box drawn by" says who draws the panes, grid and axis lines in the
bridge's file: matplotlib when the data stay inside the axes' box, limn (as scene
content, hidden exactly) when they leave it, nobody with the axes off.
"""

import argparse
import statistics
import tempfile
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import limn.matplotlib as lm  # noqa: E402


def crossing(n):
    """A height field and a tilted plane crossing it, n × n samples each."""
    fig = plt.figure(figsize=(5, 4))
    ax = fig.add_subplot(projection="3d")
    x, y = np.meshgrid(np.linspace(-1, 1, n), np.linspace(-1, 1, n))
    ax.plot_surface(x, y, 0.6 * np.exp(-2 * (x**2 + y**2)), cmap="viridis", linewidth=0)
    ax.plot_surface(x, y, 0.35 * x + 0.1, color="tab:orange", alpha=0.9, linewidth=0)
    return fig, ax, 2 * (n - 1) ** 2


def readme():
    """The figure of README's From Python example."""
    fig, ax, quads = crossing(24)
    x, y = np.meshgrid(np.linspace(-1, 1, 24), np.linspace(-1, 1, 24))
    ax.scatter(x[::4, ::4], y[::4, ::4], 0.3, c="k")
    ax.text(0, 0, 0.7, "peak")
    ax.set_zlim(-0.15, 0.6)
    return fig, ax, quads


def timed(save, path, runs):
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        save(path)
        times.append(time.perf_counter() - t0)
    return statistics.median(times), path.stat().st_size


def poking(n):
    """``crossing(n)`` with the z limits narrowed so that both surfaces leave the box:
    the panes, grid and axis lines go into limn's scene."""
    fig, ax, quads = crossing(n)
    ax.set_zlim(0.0, 0.4)
    return fig, ax, quads


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=3)
    runs = ap.parse_args().runs
    figures = [
        ("crossing 12×12", "matplotlib", lambda: crossing(12)),
        ("crossing 12×12 beyond the box", "limn", lambda: poking(12)),
        ("crossing 40×40", "matplotlib", lambda: crossing(40)),
        ("crossing 40×40 beyond the box", "limn", lambda: poking(40)),
        ("crossing 40×40, axes off", "none", lambda: crossing(40)),
        ("README example", "limn", readme),
    ]
    print(
        "| figure | quads | box drawn by | matplotlib | bridge | ratio | bytes matplotlib | bytes bridge |"
    )
    print("|---|---:|---|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as d:
        for name, box, make in figures:
            fig, ax, quads = make()
            if box == "none":
                ax.set_axis_off()
            theirs, b_theirs = timed(fig.savefig, Path(d, "mpl.svg"), runs)
            mine, b_mine = timed(lambda p: lm.savefig(fig, p), Path(d, "limn.svg"), runs)
            print(
                f"| {name} | {quads} | {box} | {theirs * 1e3:.0f} ms "
                f"| {mine * 1e3:.0f} ms | {mine / theirs:.1f}× | {b_theirs:,} | {b_mine:,} |"
            )
            plt.close(fig)


if __name__ == "__main__":
    main()
