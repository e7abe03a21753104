"""matplotlib's own 3D gallery through the bridge, figure by figure.

    python python/gallery/run.py [--quick] [--only NAME ...] [--out DIR] [--jobs N]

Takes the sdist of the installed matplotlib from PyPI (once, into a cache folder under
the build folder; it carries ``galleries/``), runs every example of
``galleries/examples/mplot3d`` and ``galleries/plot_types/3D`` headless (Agg, ``plt.show``
and ``plt.pause`` do nothing), each in a process of its own, and saves every figure it
leaves open four times: matplotlib's PNG at 100 dpi (the reference), matplotlib's SVG,
limn's SVG and limn's PDF (``limn.matplotlib.savefig``). Both SVGs are rasterised the
same way (resvg, 100 pixels per inch, on white) and compared with the PNG: a pixel
differs when one of its channels differs by more than ``--threshold`` (of 255).

Prints a Markdown table: per figure whether something raised, the percentage of pixels
of matplotlib's SVG and of limn's SVG that differ from matplotlib's PNG, the time of
each SVG savefig (the best of ``--runs``, matplotlib's and limn's alternating, after
matplotlib has drawn the figure once for its PNG) and their ratio, and the files'
sizes. matplotlib's SVG shows what
rasterising alone changes (antialiasing, fonts, images); a limn column well above it
points at a figure to look at (the pictures are kept in ``--out``: ``NAME.mpl.png``,
``NAME.mpl-svg.png``, ``NAME.limn-svg.png``). Exits with 1 when something raised.

Every figure gets a verdict. It passes when limn's SVG differs from matplotlib's PNG by
at most ``MARGIN`` percentage points more than matplotlib's own SVG does. A figure where
matplotlib's PNG is not the picture of the scene is listed in ``MATPLOTLIB_WRONG`` with
why, and the reason is checked, not taken on trust: ``"seams"`` (Agg leaves light seams
between the abutting polygons of a surface, which limn closes) compares both SVGs with
matplotlib's PNG drawn at four times the resolution and averaged down (the picture
Agg's rendering converges to, its seams a quarter as wide), where limn must pass;
``"panes"`` (data lie outside the axes' box behind a pane, which mplot3d paints under
everything and limn hides exactly) saves limn's SVG again with ``box="matplotlib"``,
which must pass. The exit status is 1 when a figure raised or failed its verdict.

``--quick`` runs a handful of small figures (under a minute). Without LaTeX on the path,
``usetex=True`` in an example becomes ``usetex=False`` (matplotlib's mathtext, without
``\\displaystyle``).
"""

from __future__ import annotations

import argparse
import hashlib
import io
import json
import os
import shutil
import subprocess
import sys
import tarfile
import time
import urllib.request
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Dict, List, Optional

HERE = Path(__file__).resolve()
ROOT = HERE.parents[2]
FOLDERS = ("galleries/examples/mplot3d", "galleries/plot_types/3D")
QUICK = ("surface3d", "axlim_clip", "scales3d", "contourf3d_2", "fillunder3d", "bar3d_simple")
MARGIN = 0.5
"""Percentage points of pixels by which limn's SVG may differ from matplotlib's PNG more
than matplotlib's own SVG does."""
SEAMS = "Agg leaves light seams between abutting polygons that limn closes"
PANES = "data outside the axes' box lie behind a pane that mplot3d paints under everything"
MATPLOTLIB_WRONG = {
    # Surfaces and solids of abutting polygons: matplotlib's PNG shows the seams.
    "bar3d_simple": ("seams", SEAMS),
    "offset": ("seams", SEAMS),
    "surface3d_3": ("seams", SEAMS),
    "surface3d_radial": ("seams", SEAMS),
    "surface3d_simple": ("seams", SEAMS),
    "trisurf3d": ("seams", SEAMS),
    "trisurf3d_simple": ("seams", SEAMS),
    "voxels_simple": ("seams", SEAMS),
    # Data drawn with axlim_clip=False and quiver arrows reach out of the box.
    "axlim_clip": ("panes", PANES),
    "quiver3d_simple": ("panes", PANES),
}
"""Figures where matplotlib's PNG is not the picture of the scene: how the claim is
checked, and why."""
# The animations (rotate_axes3d_sgskip, wire3d_animation) call plt.pause, which does
# nothing here: their last frame is saved.


def cache_folder() -> Path:
    target = os.environ.get("CARGO_TARGET_DIR") or str(ROOT / "target")
    return Path(target) / "gallery"


def sdist(version: str, cache: Path) -> Path:
    """The folder holding the gallery of matplotlib ``version``: its sdist from PyPI's
    simple index (PEP 691 JSON, the index pip reads), its hash checked, only the 3D
    galleries unpacked."""
    base = cache / f"matplotlib-{version}"
    if all((base / f).is_dir() for f in FOLDERS):
        return base
    cache.mkdir(parents=True, exist_ok=True)
    name = f"matplotlib-{version}.tar.gz"
    archive = cache / name
    if not archive.exists():
        req = urllib.request.Request(
            "https://pypi.org/simple/matplotlib/",
            headers={"Accept": "application/vnd.pypi.simple.v1+json"},
        )
        with urllib.request.urlopen(req, timeout=60) as r:
            files = json.load(r)["files"]
        entry = next((f for f in files if f["filename"] == name), None)
        if entry is None:
            raise SystemExit(f"PyPI has no sdist {name}")
        with urllib.request.urlopen(entry["url"], timeout=300) as r:
            data = r.read()
        if hashlib.sha256(data).hexdigest() != entry["hashes"]["sha256"]:
            raise SystemExit(f"{name}: sha256 does not match PyPI's")
        part = archive.with_suffix(".part")
        part.write_bytes(data)
        part.replace(archive)
    with tarfile.open(archive) as tar:
        prefix = f"matplotlib-{version}/"
        members = [
            m
            for m in tar.getmembers()
            if m.isfile() and any(m.name.startswith(prefix + f + "/") for f in FOLDERS)
        ]
        tar.extractall(cache, members=members)
    return base


def examples(base: Path) -> List[Path]:
    return sorted(p for f in FOLDERS for p in (base / f).glob("*.py"))


# --- one example, in a process of its own ------------------------------------------------


def run_one(script: Path, out: Path, threshold: int, runs: int = 1) -> List[dict]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    import limn.matplotlib as lm

    plt.show = lambda *a, **k: None
    plt.pause = lambda *a, **k: None
    name = script.stem
    rows: List[dict] = []
    os.chdir(script.parent)
    sys.path.insert(0, str(script.parent))
    try:
        source = script.read_text()
        if shutil.which("latex") is None:
            # Without LaTeX, TeX strings are drawn by matplotlib's mathtext instead.
            source = source.replace("usetex=True", "usetex=False")
            source = source.replace("\\displaystyle ", "")
        code = compile(source, str(script), "exec")
        exec(code, {"__name__": "__main__", "__file__": str(script)})
    except BaseException as e:  # noqa: BLE001 - reported, not raised
        return [{"figure": name, "error": f"example: {type(e).__name__}: {e}"}]
    nums = plt.get_fignums()
    for k, num in enumerate(nums):
        fig = plt.figure(num)
        fname = name if len(nums) == 1 else f"{name}-{k + 1}"
        row: Dict[str, object] = {"figure": fname, "error": ""}
        try:
            fig.savefig(out / f"{fname}.mpl.png", dpi=100)
            # Each SVG savefig timed ``runs`` times, the two alternating; the best kept.
            row["mpl_time"] = row["limn_time"] = float("inf")
            for _ in range(runs):
                buf = io.BytesIO()
                t0 = time.perf_counter()
                fig.savefig(buf, format="svg")
                row["mpl_time"] = min(row["mpl_time"], time.perf_counter() - t0)
                mpl_svg = buf.getvalue()
                t0 = time.perf_counter()
                lm.savefig(fig, out / f"{fname}.limn.svg")
                row["limn_time"] = min(row["limn_time"], time.perf_counter() - t0)
            limn_svg = (out / f"{fname}.limn.svg").read_bytes()
            t0 = time.perf_counter()
            lm.savefig(fig, out / f"{fname}.limn.pdf")
            row["limn_pdf_time"] = time.perf_counter() - t0
            row["mpl_bytes"] = len(mpl_svg)
            row["limn_bytes"] = len(limn_svg)
            row["limn_pdf_bytes"] = (out / f"{fname}.limn.pdf").stat().st_size
            ref = _png(out / f"{fname}.mpl.png")
            imgs = {}
            for key, svg in (("mpl", mpl_svg), ("limn", limn_svg)):
                imgs[key] = _raster(svg)
                _save_png(imgs[key], out / f"{fname}.{key}-svg.png")
                row[f"{key}_diff"] = _differ(ref, imgs[key], threshold)
            check = MATPLOTLIB_WRONG.get(fname, (None, ""))[0]
            if row["limn_diff"] > row["mpl_diff"] + MARGIN and check == "seams":
                fine = _supersampled(fig, ref.shape)
                _save_png(fine, out / f"{fname}.mpl-4x.png")
                row["mpl_check"] = _differ(fine, imgs["mpl"], threshold)
                row["limn_check"] = _differ(fine, imgs["limn"], threshold)
            elif row["limn_diff"] > row["mpl_diff"] + MARGIN and check == "panes":
                buf = io.BytesIO()
                lm.savefig(fig, buf, format="svg", box="matplotlib")
                img = _raster(buf.getvalue())
                _save_png(img, out / f"{fname}.limn-mplbox-svg.png")
                row["mpl_check"] = row["mpl_diff"]
                row["limn_check"] = _differ(ref, img, threshold)
            row["verdict"] = verdict(row)
        except BaseException as e:  # noqa: BLE001 - reported, not raised
            row["error"] = f"{type(e).__name__}: {e}"
        rows.append(row)
        plt.close(fig)
    return rows or [{"figure": name, "error": "", "nofig": True}]


def verdict(row: dict) -> str:
    """``pass``, ``pass (seams)`` / ``pass (panes)`` for a listed figure whose reason
    holds, or ``FAIL``."""
    if row["limn_diff"] <= row["mpl_diff"] + MARGIN:
        return "pass"
    if "limn_check" in row and row["limn_check"] <= row["mpl_check"] + MARGIN:
        return f"pass ({MATPLOTLIB_WRONG[row['figure']][0]})"
    return "FAIL"


def _supersampled(fig, shape):
    """matplotlib's PNG of ``fig`` at 400 dpi averaged over 4 × 4 blocks, cut to
    ``shape``: Agg's picture with its seams between abutting polygons a quarter as wide."""
    import numpy as np
    from PIL import Image

    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=400)
    big = np.asarray(Image.open(buf).convert("RGB"), dtype=np.float64)
    h, w = big.shape[0] // 4, big.shape[1] // 4
    small = big[: 4 * h, : 4 * w].reshape(h, 4, w, 4, 3).mean(axis=(1, 3))
    return np.rint(small[: shape[0], : shape[1]]).astype(np.int16)


def _png(path: Path):
    import numpy as np
    from PIL import Image

    return np.asarray(Image.open(path).convert("RGB"), dtype=np.int16)


def _raster(svg: bytes):
    """The SVG (in points) at 100 pixels per inch on white, as (h, w, 3) integers."""
    import numpy as np
    import resvg_py
    from PIL import Image

    png = resvg_py.svg_to_bytes(
        svg_string=svg.decode(), dpi=72, zoom=100 / 72, background="#ffffff"
    )
    return np.asarray(Image.open(io.BytesIO(bytes(png))).convert("RGB"), dtype=np.int16)


def _save_png(img, path: Path) -> None:
    import numpy as np
    from PIL import Image

    Image.fromarray(img.astype(np.uint8)).save(path)


def _differ(ref, img, threshold: int) -> float:
    """Percentage of the reference's pixels where ``img`` differs by more than
    ``threshold`` in some channel (pixels outside ``img`` differ)."""
    import numpy as np

    h, w = min(ref.shape[0], img.shape[0]), min(ref.shape[1], img.shape[1])
    bad = (np.abs(ref[:h, :w] - img[:h, :w]) > threshold).any(axis=2)
    total = ref.shape[0] * ref.shape[1]
    return 100.0 * (int(bad.sum()) + total - h * w) / total


# --- the table ----------------------------------------------------------------------------


def table(rows: List[dict]) -> str:
    ms = lambda t: f"{1000 * t:.0f} ms" if t is not None else ""  # noqa: E731
    lines = [
        "| figure | raised | mpl SVG diff | limn SVG diff | verdict | checked: mpl | limn "
        "| mpl SVG time | limn SVG time | ratio | limn PDF time | mpl SVG bytes "
        "| limn SVG bytes | limn PDF bytes |",
        "|---|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in rows:
        if r.get("nofig"):
            continue
        err = r.get("error") or ""
        short = err.splitlines()[0][:80].replace("|", "/") if err else "no"
        pct = lambda k: f"{r[k]:.2f} %" if k in r else ""  # noqa: E731
        num = lambda k: f"{r[k]:,}" if k in r else ""  # noqa: E731
        ratio = (
            f"{r['limn_time'] / r['mpl_time']:.1f}×"
            if "limn_time" in r and r.get("mpl_time")
            else ""
        )
        lines.append(
            f"| {r['figure']} | {short} | {pct('mpl_diff')} | {pct('limn_diff')} | "
            f"{r.get('verdict', '')} | {pct('mpl_check')} | {pct('limn_check')} | "
            f"{ms(r.get('mpl_time'))} | {ms(r.get('limn_time'))} | {ratio} | "
            f"{ms(r.get('limn_pdf_time'))} | {num('mpl_bytes')} | {num('limn_bytes')} | "
            f"{num('limn_pdf_bytes')} |"
        )
    return "\n".join(lines) + "\n"


def main(argv: Optional[List[str]] = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="a handful of small figures")
    ap.add_argument("--only", nargs="+", metavar="NAME", help="only these examples")
    ap.add_argument("--out", type=Path, help="where the pictures go (default: cache)")
    ap.add_argument("--jobs", type=int, default=1, help="examples run at once")
    ap.add_argument("--threshold", type=int, default=32, help="per-channel, of 255")
    ap.add_argument("--timeout", type=float, default=600, help="seconds per example")
    ap.add_argument(
        "--runs", type=int, default=3, help="SVG savefigs timed per figure (the best kept)"
    )
    ap.add_argument("--one", type=Path, help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.runs < 1:
        ap.error("--runs must be at least 1")
    if args.one is not None:
        found = run_one(args.one.resolve(), args.out.resolve(), args.threshold, args.runs)
        print(json.dumps(found))
        return 0

    import matplotlib

    base = sdist(matplotlib.__version__, cache_folder())
    scripts = examples(base)
    names = args.only or (QUICK if args.quick else None)
    if names:
        unknown = set(names) - {s.stem for s in scripts}
        if unknown:
            raise SystemExit(f"no such example: {', '.join(sorted(unknown))}")
        scripts = [s for s in scripts if s.stem in names]
    out = (args.out or cache_folder() / "out").resolve()
    out.mkdir(parents=True, exist_ok=True)

    def one(script: Path) -> List[dict]:
        cmd = [sys.executable, str(HERE), "--one", str(script), "--out", str(out)]
        cmd += ["--threshold", str(args.threshold), "--runs", str(args.runs)]
        env = dict(os.environ, MPLBACKEND="Agg")
        try:
            p = subprocess.run(
                cmd, capture_output=True, text=True, timeout=args.timeout, env=env
            )
        except subprocess.TimeoutExpired:
            return [{"figure": script.stem, "error": f"timed out after {args.timeout:.0f} s"}]
        last = p.stdout.strip().splitlines()[-1:] if p.returncode == 0 else []
        if not last:
            tail = (p.stderr.strip().splitlines() or ["no output"])[-1]
            return [{"figure": script.stem, "error": f"process: {tail}"}]
        return json.loads(last[0])

    with ThreadPoolExecutor(max(1, args.jobs)) as pool:
        rows = [r for rs in pool.map(one, scripts) for r in rs]
    text = table(rows)
    (out / "table.md").write_text(text)
    sys.stdout.write(text)
    raised = [r for r in rows if r.get("error")]
    for r in raised:
        print(f"{r['figure']}: {r['error']}", file=sys.stderr)
    failed = [r for r in rows if r.get("verdict") == "FAIL"]
    for r in failed:
        print(
            f"{r['figure']}: limn's SVG differs from matplotlib's PNG on "
            f"{r['limn_diff']:.2f} % of pixels, matplotlib's own SVG on {r['mpl_diff']:.2f} %",
            file=sys.stderr,
        )
    return 1 if raised or failed else 0


if __name__ == "__main__":
    sys.exit(main())
