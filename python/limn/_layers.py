"""Which of limn's painted items go under the axes' lines and ticks.

matplotlib draws a 3D axes' panes, then its grid, then its axis lines, ticks and tick
labels, then the data. With the panes and the grid in limn's scene, limn's paint order
mixes them with the data (a surface that pokes out of the box behind a pane is painted
before the pane). The bridge keeps matplotlib's layering where it can: it paints the
panes, the grid and every item that must come before one of them, then lets matplotlib
draw the axis lines, ticks and labels, then paints the rest. Moving an item past another
one whose drawing it does not overlap leaves the picture unchanged, so the split is
exact when overlaps are judged conservatively (here by bounding boxes that include the
stroke widths).
"""

from __future__ import annotations

import numpy as np


def under_axes(boxes: np.ndarray, background: np.ndarray) -> np.ndarray:
    """The items to paint before the axes' lines: every ``background`` item and, closed
    under this rule, every item painted before one of them whose box overlaps its box.

    boxes: (N, 4) ``(x0, y0, x1, y1)`` in paint order; background: (N,) bool. Painting
    the returned items in their order, then the others in theirs, gives the same picture
    as the paint order: no two overlapping items change places.
    """
    boxes = np.asarray(boxes, dtype=float).reshape(-1, 4)
    under = np.array(background, dtype=bool).copy()
    queue = list(np.nonzero(under)[0])
    while queue:
        k = queue.pop()
        x0, y0, x1, y1 = boxes[k]
        before = boxes[:k]
        meets = (
            (before[:, 0] <= x1) & (before[:, 2] >= x0) & (before[:, 1] <= y1) & (before[:, 3] >= y0)
        )
        new = np.nonzero(meets & ~under[:k])[0]
        under[new] = True
        queue.extend(new)
    return under
