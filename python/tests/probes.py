"""Looking at saved figures: rasterise an SVG and read colours where 3D points project."""

import io

import numpy as np


def raster(svg: bytes, zoom: float):
    """The SVG rasterised by resvg on white, as an (h, w, 4) float image."""
    import resvg_py
    from matplotlib.image import imread

    # dpi 72: one pt of the SVG is one pixel before the zoom.
    png = resvg_py.svg_to_bytes(svg_string=svg.decode(), dpi=72, zoom=zoom, background="#ffffff")
    return imread(io.BytesIO(bytes(png)), format="png")


def pixel_of(fig, ax, img, p):
    """The (row, column) of ``img`` (a raster of ``fig``) where the 3D point p projects."""
    from mpl_toolkits.mplot3d import proj3d

    if fig.stale:
        fig.canvas.draw()  # the axes' projection and transforms as drawn
    xp, yp, _ = proj3d.proj_transform(*p, ax.get_proj())
    X, Y = ax.transData.transform((xp, yp))
    h, w = img.shape[:2]
    W, H = fig.canvas.get_width_height()
    return int((H - Y) * h / H), int(X * w / W)


def colour_at(fig, ax, img, p):
    """The colour of the rasterised figure where the 3D point p projects."""
    i, j = pixel_of(fig, ax, img, p)
    return img[i, j, :3]


def near(c, want, tol=0.08):
    return np.abs(np.asarray(c) - np.asarray(want)).max() < tol


def count_colour(img, want, tol=0.08):
    """How many pixels of ``img`` have the colour ``want``."""
    return int((np.abs(img[:, :, :3] - np.asarray(want)).max(axis=2) < tol).sum())
