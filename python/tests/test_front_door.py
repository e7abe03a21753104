"""Python at parity with the command: files read as ``limn render`` reads them, every
render option by the command's names, the same pictures, errors and file safety."""

import json
import os
import stat
import subprocess
import sys
import threading
import warnings
from pathlib import Path

import numpy as np
import pytest

import limn

LIMN_BIN = os.environ.get("LIMN_BIN")

CUBE_OBJ = """\
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
"""


@pytest.fixture
def cube(tmp_path: Path) -> Path:
    p = tmp_path / "cube.obj"
    p.write_text(CUBE_OBJ)
    return p


def command(*args: str) -> subprocess.CompletedProcess:
    if not LIMN_BIN:
        pytest.skip("LIMN_BIN is not set (the built `limn` command)")
    return subprocess.run([LIMN_BIN, *args], capture_output=True, text=True)


def test_load_renders_what_the_command_renders(cube: Path, tmp_path: Path) -> None:
    opts = ["--size", "320x240", "--eye", "3,2,4", "--outline", "--background", "#ffeedd"]
    r = command("render", str(cube), "-o", str(tmp_path / "c.svg"), "-q", *opts)
    assert r.returncode == 0, r.stderr
    s = limn.load(cube)
    s.set_camera(eye=(3, 2, 4), size=(320, 240))
    stats = s.render(tmp_path / "p.svg", outline=True, background="#ffeedd")
    assert (tmp_path / "p.svg").read_bytes() == (tmp_path / "c.svg").read_bytes()
    assert stats["faces_in"] == 6
    assert stats["faces_culled"] == 3
    assert "backface-culling" in stats["effects"]


@pytest.mark.parametrize(
    "flags,keywords",
    [
        (["--style", "hidden-line", "--hidden", "dashed"], dict(style="hidden-line", hidden="dashed")),
        (["--style", "hidden-line", "--fill", "none", "--crease", "20"], dict(style="hidden-line", fill="none", crease=20)),
        (["--sort", "bsp", "--arith", "float", "--cull", "off"], dict(sort="bsp", arith="float", cull="off")),
        (["--seams", "0", "--shading-tolerance", "0.01"], dict(seams=0, shading_tolerance=0.01)),
        (["--texture-samples", "1"], dict(texture_samples=1)),
        (["--ortho", "3"], None),
        (["--format", "tikz", "--standalone"], dict(format="tikz", standalone=True)),
        (["--method", "raycast", "--format", "png"], dict(method="raycast", format="png")),
    ],
)
def test_every_option_by_the_command_s_name(cube: Path, tmp_path: Path, flags, keywords) -> None:
    out_c, out_p = tmp_path / "c.out", tmp_path / "p.out"
    if "--format" not in flags:
        flags = flags + ["--format", "svg"]
    r = command("render", str(cube), "-o", str(out_c), "-q", "--threads", "1", *flags)
    assert r.returncode == 0, r.stderr
    s = limn.load(cube)
    if keywords is None:
        s.set_camera(projection="orthographic", height=3)
        keywords = {}
    keywords.setdefault("format", "svg")
    s.render(out_p, threads=1, **keywords)
    assert out_p.read_bytes() == out_c.read_bytes()


def test_scene_files_bring_their_settings(tmp_path: Path, cube: Path) -> None:
    (tmp_path / "s.toml").write_text(
        '[output]\nsize = [200, 100]\nbackground = [0, 0, 0]\n[[mesh]]\npath = "cube.obj"\n'
    )
    s = limn.load(tmp_path / "s.toml")
    stats = s.render(tmp_path / "s.png")
    assert stats["faces_in"] == 6
    from PIL import Image

    im = Image.open(tmp_path / "s.png")
    assert im.size == (200, 100)
    assert im.getpixel((0, 0))[:3] == (0, 0, 0)


def test_stats_are_the_command_s_keys(cube: Path, tmp_path: Path) -> None:
    r = command("render", str(cube), "-o", str(tmp_path / "c.svg"), "-q", "--stats", str(tmp_path / "c.json"))
    assert r.returncode == 0, r.stderr
    theirs = json.loads((tmp_path / "c.json").read_text())
    ours = limn.load(cube).render(tmp_path / "p.svg", stats=tmp_path / "p.json")
    written = json.loads((tmp_path / "p.json").read_text())

    def keys(d, at=""):
        return {at + k for k in d} | {
            k2 for k, v in d.items() if isinstance(v, dict) for k2 in keys(v, at + k + ".")
        }

    assert keys(ours) == keys(theirs) == keys(written)
    for k in ["faces_in", "faces_culled", "fragments_out", "paths_out", "bytes_out", "sort"]:
        assert ours[k] == theirs[k], k


def test_check_compares_the_rendered_picture(cube: Path, tmp_path: Path) -> None:
    s = limn.load(cube)
    report = s.check("raycast", diff=tmp_path / "d.png")
    assert report["agrees"] and report["failures"] == []
    assert report["mismatches_outside_band"] == 0
    assert report["seams"] == 1.0
    assert (tmp_path / "d.png").stat().st_size > 0
    r = command("check", str(cube), "-q")
    assert r.returncode == 0, r.stderr
    theirs = json.loads(r.stdout)
    for k in ["pixels", "mismatches", "band_pixels", "fragments", "against"]:
        assert report[k] == theirs[k], k


def test_load_errors_name_the_file_and_line(tmp_path: Path) -> None:
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
    with pytest.raises(ValueError, match=r"bad\.obj:4"):
        limn.load(bad)
    with pytest.raises(OSError, match="missing.obj"):
        limn.load(tmp_path / "missing.obj")
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "a.obj").write_text("mtllib ../x.mtl\n" + CUBE_OBJ)
    (tmp_path / "x.mtl").write_text("newmtl m\nKd 1 0 0\n")
    with pytest.raises(OSError, match="allow-outside"):
        limn.load(tmp_path / "sub" / "a.obj")
    assert limn.load(tmp_path / "sub" / "a.obj", allow_outside=True).face_count == 6


def test_bad_options_raise_value_error(cube: Path, tmp_path: Path) -> None:
    s = limn.load(cube)
    cases = [
        (dict(sort="fast"), "unknown sort `fast`"),
        (dict(style="sketch"), "unknown style"),
        (dict(seams=11), "seam width"),
        (dict(shading_tolerance=0), "shading tolerance"),
        (dict(texture_samples=17), "texture samples"),
        (dict(background="#12"), "#rrggbb"),
        (dict(method="zbuffer"), "renders a raster"),
        (dict(standalone=True), "TikZ output only"),
        (dict(near=-1), "positive"),
        (dict(threads=0), "at least 1"),
    ]
    for kw, msg in cases:
        with pytest.raises(ValueError, match=msg):
            s.render(tmp_path / "x.svg", **kw)
        assert not (tmp_path / "x.svg").exists()


def test_warnings_are_python_warnings(tmp_path: Path) -> None:
    v = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0]], float)
    with pytest.warns(UserWarning, match="zero area"):
        stats = limn.render_mesh(v, [[0, 1, 2], [0, 1, 3]], tmp_path / "w.svg")
    assert stats["faces_degenerate"] == 1
    assert any("zero area" in w for w in stats["warnings"])


# File safety: the command's rules, from Python.


def test_refuses_to_write_over_its_input(cube: Path) -> None:
    before = cube.read_bytes()
    with pytest.raises(OSError, match="the scene was read from"):
        limn.load(cube).render(cube, format="svg")
    assert cube.read_bytes() == before


def test_refuses_read_only_files_and_folders(cube: Path, tmp_path: Path) -> None:
    ro = tmp_path / "ro.svg"
    ro.write_text("keep")
    ro.chmod(stat.S_IRUSR)
    s = limn.load(cube)
    if os.geteuid() != 0:
        with pytest.raises(OSError):
            s.render(ro)
    else:
        with pytest.raises(OSError, match="read-only"):
            s.render(ro)
    assert ro.read_text() == "keep"
    with pytest.raises(OSError, match="folder"):
        s.render(tmp_path, format="svg")


def test_writes_through_symbolic_links(cube: Path, tmp_path: Path) -> None:
    target = tmp_path / "real.svg"
    target.write_text("old")
    link = tmp_path / "link.svg"
    link.symlink_to(target)
    limn.load(cube).render(link)
    assert link.is_symlink()
    assert target.read_text().startswith("<?xml") or target.read_text().startswith("<svg")


@pytest.mark.skipif(sys.platform == "win32", reason="FIFOs are POSIX")
def test_writes_fifos_directly(cube: Path, tmp_path: Path) -> None:
    fifo = tmp_path / "pipe.svg"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_bytes()))
    reader.start()
    limn.load(cube).render(fifo)
    reader.join(10)
    assert got and b"<svg" in got[0]
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)


def test_no_partial_file_on_error(tmp_path: Path) -> None:
    # Two triangles passing through each other: one must be split.
    v = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0], [0, -0.5, -1], [0, -0.5, 1], [0, 0.5, 0]], float)
    s = limn.Scene()
    s.add_mesh(v, [[0, 1, 2], [3, 4, 5]])
    s.set_camera(eye=(2, 1, 3))
    assert s.render(tmp_path / "ok.svg")["splits"] > 0
    (tmp_path / "ok.svg").unlink()
    with pytest.raises(ValueError, match="max-fragments"):
        s.render(tmp_path / "x.svg", max_fragments=2)
    assert list(tmp_path.iterdir()) == []
