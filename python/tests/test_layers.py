"""The split of limn's paint order under and over matplotlib's ticks (``limn._layers``)."""

import numpy as np

from limn._layers import under_axes


def square(x, y, s=1.0):
    return np.array([[x, y], [x + s, y], [x + s, y + s], [x, y + s]], float)


def test_items_before_a_background_item_that_overlap_it_go_under():
    parts = [
        [square(10, 10)],  # far from everything
        [square(0.5, 0.5)],  # overlaps the pane, painted before it
        [square(0, 0, 2)],  # the pane
        [square(2, 0)],  # shares an edge with the pane: only touches
        [square(1, 1)],  # overlaps the pane but is painted after it
        [np.array([[3.0, 0.5]])],  # a marker whose reach touches the pane's neighbour
    ]
    pads = np.array([0, 0, 0, 0, 0, 0.5])
    background = np.array([False, False, True, False, False, False])
    assert list(under_axes(parts, pads, background)) == [False, True, True, False, False, False]
    # A line over the pane's neighbour, painted last and part of the box: the neighbour
    # (touching nothing else earlier) and the marker under the line go under too.
    parts.append([np.array([[2.0, 0.5], [3.5, 0.5]])])
    pads = np.r_[pads, 0.1]
    background = np.r_[background, True]
    got = under_axes(parts, pads, background)
    assert list(got) == [False, True, True, True, False, True, True]


def test_no_overlapping_pair_changes_places():
    from matplotlib.path import Path

    rng = np.random.default_rng(7)
    n = 120
    tris = [rng.uniform(0, 100, 2) + rng.uniform(-8, 8, (3, 2)) for _ in range(n)]
    background = rng.random(n) < 0.1
    under = under_axes([[t] for t in tris], np.zeros(n), background)
    assert under[background].all()
    meets = lambda a, b: Path(a).intersects_path(Path(b), filled=True)  # noqa: E731
    for j in np.nonzero(under)[0]:
        for i in range(j):
            if not under[i]:
                # An item left over the ticks never overlaps one under them painted later.
                assert not meets(tris[i], tris[j]), (i, j)
    assert 0 < under.sum() < n
