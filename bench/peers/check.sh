#!/usr/bin/env bash
# Self-test of the peer drivers: builds gl2ps_driver, draws small scenes
# with gl2ps (bsp and simple sorts) and with matplotlib, rasterises each SVG
# at W x H with rsvg-convert (anti-aliasing off through a crispEdges
# stylesheet; pixels sampled at centres away from edges anyway) and checks
# placement (y down, x right), depth (nearer wins), exact colours, no
# background, no strokes, and the error path.
# Needs what install.sh installs. Exits non-zero on the first failure.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
PY="${PYTHON:-python3}"

# Build the C driver next to its source (ignored by git), only if stale.
if [ ! -x "$here/gl2ps_driver" ] || [ "$here/gl2ps_driver.c" -nt "$here/gl2ps_driver" ]; then
    echo "build: gcc -O2 -o gl2ps_driver gl2ps_driver.c -lgl2ps -lOSMesa -lm"
    gcc -O2 -Wall -o "$here/gl2ps_driver" "$here/gl2ps_driver.c" -lgl2ps -lOSMesa -lm
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Run from the empty work directory: a script read from stdin imports from
# the current directory first.
cd "$work"
"$PY" - "$here" "$work" <<'EOF'
import os, re, subprocess, sys
from PIL import Image

here, work = sys.argv[1], sys.argv[2]
passed = failed = 0

def check(cond, what):
    global passed, failed
    if cond:
        passed += 1
    else:
        failed += 1
        print(f"FAIL: {what}")

def write_scene(name, w, h, polys):
    path = os.path.join(work, name + ".txt")
    with open(path, "w") as f:
        f.write(f"limn-projected 1\n{w} {h}\n{len(polys)}\n")
        for (r, g, b), pts in polys:
            f.write(f"{r} {g} {b} {len(pts)} " + " ".join(f"{x:.6f} {y:.6f} {z:.6f}" for x, y, z in pts) + "\n")
    return path

DRIVERS = {
    "gl2ps-bsp": [os.path.join(here, "gl2ps_driver"), "bsp"],
    "gl2ps-simple": [os.path.join(here, "gl2ps_driver"), "simple"],
    "mpl": [sys.executable, os.path.join(here, "mpl_driver.py")],
}
CSS = os.path.join(work, "crisp.css")
with open(CSS, "w") as f:
    f.write("* { shape-rendering: crispEdges; }\n")

def run(driver, scene, name, w, h):
    svg = os.path.join(work, f"{name}-{driver}.svg")
    png = svg[:-4] + ".png"
    p = subprocess.run(DRIVERS[driver] + [scene, svg], capture_output=True, text=True)
    check(p.returncode == 0, f"{driver} {name}: exit {p.returncode}: {p.stderr.strip()}")
    if p.returncode != 0:
        return None, None, None
    m = re.fullmatch(r"primitives (\d+)\n", p.stdout)
    check(m is not None, f"{driver} {name}: stdout is not 'primitives N': {p.stdout!r}")
    text = open(svg).read()
    check(re.search(rf'<svg[^>]*width="{w}" height="{h}"', text) is not None,
          f"{driver} {name}: root width/height are not {w}/{h} user units")
    check(f'viewBox="0 0 {w} {h}"' in text, f"{driver} {name}: viewBox is not 0 0 {w} {h}")
    check(re.search(r'stroke(-width)?\s*[:=]', text) is None, f"{driver} {name}: SVG strokes something")
    check("<rect" not in text and "<image" not in text, f"{driver} {name}: SVG has a rect or image")
    subprocess.run(["rsvg-convert", "-s", CSS, "-w", str(w), "-h", str(h), "-o", png, svg], check=True)
    img = Image.open(png).convert("RGBA")
    check(img.size == (w, h), f"{driver} {name}: raster is {img.size}, not {(w, h)}")
    return img, text, int(m.group(1)) if m else None

def px(img, x, y):
    return img.getpixel((x, y))

BG = (0, 0, 0, 0)  # transparent: no driver draws a background
NEAR, FAR, CORNER = (10, 200, 10), (200, 10, 10), (10, 10, 200)

# Scene 1: 64 x 48. The nearer triangle comes FIRST in input order, so a
# driver that ignores depth (paints in input order) or inverts it fails.
W, H = 64, 48
s1 = write_scene("overlap", W, H, [
    (NEAR, [(20, 12, -0.5), (56, 12, -0.5), (40, 44, -0.5)]),
    (FAR, [(8, 8, 0.5), (40, 8, 0.5), (24, 40, 0.5)]),
    (CORNER, [(0, 0, 0.0), (10, 0, 0.0), (0, 10, 0.0)]),
])
probes = [
    ((30, 16), NEAR, "overlap of the two triangles shows the nearer one"),
    ((13, 12), FAR, "interior of the far triangle alone"),
    ((48, 16), NEAR, "interior of the near triangle alone"),
    ((2, 2), CORNER, "corner triangle at the top-left (y down, x right)"),
    ((2, 45), None, "bottom-left is background (y not flipped)"),
    ((61, 2), None, "top-right is background (x not flipped)"),
    ((60, 45), None, "bottom-right is background"),
    ((2, 30), None, "left middle is background"),
]
for drv in DRIVERS:
    img, text, n = run(drv, s1, "overlap", W, H)
    if img is None:
        continue
    for (x, y), want, what in probes:
        got = px(img, x, y)
        exp = BG if want is None else want + (255,)
        check(got == exp, f"{drv}: pixel ({x},{y}) is {got}, want {exp}: {what}")
    check(n is not None and n >= 3, f"{drv}: primitives {n} < 3")

# Scene 2: depth sign alone, nearer polygon LAST; and the mirror of scene 1
# with the far triangle first. Both orders must give the nearer colour.
for order, name in ((1, "nearlast"), (-1, "nearfirst")):
    a = (NEAR, [(4, 4, -0.9), (60, 4, -0.9), (4, 44, -0.9)])
    b = (FAR, [(60, 44, 0.9), (4, 44, 0.9), (4, 4, 0.9), (60, 4, 0.9)])
    s = write_scene(name, W, H, [b, a][::order])
    for drv in DRIVERS:
        img, _, _ = run(drv, s, name, W, H)
        if img is None:
            continue
        check(px(img, 10, 10) == NEAR + (255,), f"{drv} {name}: nearer square/triangle does not win at (10,10): {px(img, 10, 10)}")
        check(px(img, 55, 40) == FAR + (255,), f"{drv} {name}: far quad missing at (55,40): {px(img, 55, 40)}")

# Scene 3: exact colours. 256 squares of 4x4 px in a 64x64 picture, colours
# covering every value 0..255 in each channel.
cells = []
for i in range(256):
    cx, cy = (i % 16) * 4, (i // 16) * 4
    rgb = (i, (i * 7 + 3) % 256, 255 - i)
    cells.append((rgb, [(cx, cy, 0.0), (cx + 4, cy, 0.0), (cx + 4, cy + 4, 0.0), (cx, cy + 4, 0.0)]))
s3 = write_scene("colours", 64, 64, cells)
for drv in DRIVERS:
    img, text, _ = run(drv, s3, "colours", 64, 64)
    if img is None:
        continue
    bad = [(i, px(img, (i % 16) * 4 + 2, (i // 16) * 4 + 2), rgb) for i, (rgb, _) in enumerate(cells)
           if px(img, (i % 16) * 4 + 2, (i // 16) * 4 + 2) != rgb + (255,)]
    check(not bad, f"{drv} colours: {len(bad)} cells with a wrong colour, first {bad[:3]}")
    fills = set(re.findall(r'fill[=:]\s*"?#([0-9a-f]{6})', text))
    want = {"%02x%02x%02x" % rgb for rgb, _ in cells}
    check(fills == want, f"{drv} colours: SVG fills differ: {len(fills ^ want)} mismatches")

# Scene 4: clipping. A 3 x 3 grid of quads, 8 of them crossing the picture's
# edges; the parts inside must keep their exact colours (OpenGL clipping
# makes new vertices whose colours gl2ps reads back).
xs, ys = (-28, 12, 52, 92), (-24, 8, 40, 72)
probe_x, probe_y = (4, 32, 58), (3, 24, 44)
grid = []
for j in range(3):
    for i in range(3):
        rgb = ((37 * (3 * j + i) + 11) % 256, (91 * (3 * j + i) + 5) % 256, (53 * (3 * j + i) + 200) % 256)
        z = 0.1 * (3 * j + i) - 0.4
        grid.append((rgb, [(xs[i], ys[j], z), (xs[i + 1], ys[j], z), (xs[i + 1], ys[j + 1], z), (xs[i], ys[j + 1], z)]))
s4 = write_scene("clipped", 64, 48, grid)
for drv in DRIVERS:
    img, text, _ = run(drv, s4, "clipped", 64, 48)
    if img is None:
        continue
    for j in range(3):
        for i in range(3):
            got, rgb = px(img, probe_x[i], probe_y[j]), grid[3 * j + i][0]
            check(got == rgb + (255,), f"{drv} clipped: cell ({i},{j}) at ({probe_x[i]},{probe_y[j]}) is {got}, want {rgb}")
    fills = set(re.findall(r'fill[=:]\s*"?#([0-9a-f]{6})', text))
    want = {"%02x%02x%02x" % rgb for rgb, _ in grid}
    check(fills == want, f"{drv} clipped: SVG fills {sorted(fills - want)} not in the scene, {sorted(want - fills)} missing")

# Error path: bad input -> exit 1, message on stderr, no output file.
bad_in = os.path.join(work, "bad.txt")
with open(bad_in, "w") as f:
    f.write("limn-projected 1\n10 10\n2\n1 2 3 3 0 0 0 1 0 0\n")
for drv in DRIVERS:
    out = os.path.join(work, f"bad-{drv}.svg")
    p = subprocess.run(DRIVERS[drv] + [bad_in, out], capture_output=True, text=True)
    check(p.returncode == 1 and p.stderr.strip() and not os.path.exists(out) and not os.path.exists(out + ".tmp"),
          f"{drv}: malformed input gave exit {p.returncode}, stderr {p.stderr!r}, output exists {os.path.exists(out)}")

print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
EOF
