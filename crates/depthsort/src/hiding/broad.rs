//! The broad phase of the hiding: which occluders may hide a receiver from a source,
//! found in a view from the source (in floats, with margins: a false candidate only
//! costs an exact clip, a missed one would be a bug, so every bound is widened).
//!
//! A light at infinity projects along its direction; a point light outside the scene's
//! box projects centrally onto a plane across the axis on which it lies outside the
//! box (every point of the scene then has positive depth, and the projection of a
//! convex polygon lies in the box of its projected corners). A point light inside the
//! box, or too close to it for the projection to be well conditioned, has no such
//! view: every occluder is then a candidate of every receiver. A finite eye projects
//! centrally along the camera's axis (everything it sees lies beyond the near plane).
//! A point seen at depth zero or less has no position in a central view: a polygon
//! with such a corner has no extent, and is then tested against every occluder.

use glam::DVec3;

/// How points are seen from the light.
#[derive(Debug, Clone, Copy)]
pub(crate) enum LightView {
    /// Parallel along `-dir`: screen `(x·e1, x·e2)`, depth `−x·dir` (larger is farther
    /// from the light).
    Parallel { e1: DVec3, e2: DVec3, dir: DVec3 },
    /// Central from `at` along the unit vector `axis`, `e1` and `e2` across it.
    Central {
        at: DVec3,
        axis: DVec3,
        e1: DVec3,
        e2: DVec3,
    },
    /// No usable view: every occluder is a candidate.
    All,
}

impl LightView {
    /// The view of a light at infinity in direction `d`.
    pub fn parallel(d: DVec3) -> LightView {
        let dir = d.normalize();
        let e1 = dir.any_orthonormal_vector();
        LightView::Parallel {
            e1,
            e2: dir.cross(e1),
            dir,
        }
    }

    /// The view of a point light at `at` for a scene within `lo..=hi`.
    pub fn central(at: DVec3, lo: DVec3, hi: DVec3) -> LightView {
        let size = (hi - lo).max_element().max(f64::MIN_POSITIVE);
        let mut best: Option<(f64, usize, f64)> = None;
        for k in 0..3 {
            for (gap, sign) in [(lo[k] - at[k], 1.0), (at[k] - hi[k], -1.0)] {
                if best.is_none_or(|(g, ..)| gap > g) {
                    best = Some((gap, k, sign));
                }
            }
        }
        match best {
            // Depth at least 1e-6 of the box: the projection's rounding stays far
            // below the margins.
            Some((gap, k, sign)) if gap > 1e-6 * size => {
                let axis = DVec3::AXES[k] * sign;
                LightView::Central {
                    at,
                    axis,
                    e1: DVec3::AXES[(k + 1) % 3],
                    e2: DVec3::AXES[(k + 2) % 3],
                }
            }
            _ => LightView::All,
        }
    }

    /// The central view from `at` along `axis` (not zero), for points that lie beyond
    /// `at` along it.
    pub fn along(at: DVec3, axis: DVec3) -> LightView {
        let axis = axis.normalize();
        let e1 = axis.any_orthonormal_vector();
        LightView::Central {
            at,
            axis,
            e1,
            e2: axis.cross(e1),
        }
    }

    /// Screen position and depth of `x` (`None` for [`LightView::All`], and for a point
    /// at depth zero or less in a central view).
    fn project(&self, x: DVec3) -> Option<([f64; 2], f64)> {
        match *self {
            LightView::Parallel { e1, e2, dir } => Some(([x.dot(e1), x.dot(e2)], -x.dot(dir))),
            LightView::Central { at, axis, e1, e2 } => {
                let v = x - at;
                let z = v.dot(axis);
                if z.is_nan() || z <= 0.0 {
                    return None;
                }
                Some(([v.dot(e1) / z, v.dot(e2) / z], z))
            }
            LightView::All => None,
        }
    }

    /// The screen box and depth range of a polygon's corners.
    pub fn extent(&self, corners: &[DVec3]) -> Option<Extent> {
        let mut e = Extent::EMPTY;
        for &c in corners {
            e.add(self.project(c)?);
        }
        Some(e)
    }

    /// The screen box and depth range of a polygon whose corners are known only within
    /// boxes: `(position, half-width)` each, the corner within `half-width` of the
    /// position in every coordinate. The extent holds every point of every box (a box's
    /// eight corners are projected; a convex set seen at positive depth projects into
    /// the hull of its corners' projections), so that it bounds the polygon without
    /// rounding its implicit corners.
    pub fn extent_of_boxes(&self, boxes: &[(DVec3, f64)]) -> Option<Extent> {
        let mut e = Extent::EMPTY;
        for &(c, r) in boxes {
            if r == 0.0 {
                e.add(self.project(c)?);
                continue;
            }
            for k in 0..8 {
                let sign = |b: usize| if k & b == 0 { -r } else { r };
                e.add(self.project(c + DVec3::new(sign(1), sign(2), sign(4)))?);
            }
        }
        Some(e)
    }
}

/// A box on the light's screen and a depth range.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Extent {
    pub lo: [f64; 2],
    pub hi: [f64; 2],
    pub near: f64,
    pub far: f64,
}

impl Extent {
    /// The extent of no point.
    const EMPTY: Extent = Extent {
        lo: [f64::INFINITY; 2],
        hi: [f64::NEG_INFINITY; 2],
        near: f64::INFINITY,
        far: f64::NEG_INFINITY,
    };

    /// Widens the extent to a point seen at screen position `s` and depth `z`.
    fn add(&mut self, (s, z): ([f64; 2], f64)) {
        for (i, v) in s.into_iter().enumerate() {
            self.lo[i] = self.lo[i].min(v);
            self.hi[i] = self.hi[i].max(v);
        }
        self.near = self.near.min(z);
        self.far = self.far.max(z);
    }
}

/// One occluder as a cell of a grid level lists it: its number, the first cell of its
/// box on that level (so that a query reports it once, in the first cell both boxes
/// cover) and its extent, held in the cell so that a query reads the cell's memory in
/// order.
#[derive(Debug, Clone, Copy)]
struct Entry {
    index: u32,
    first: [u16; 2],
    lo: [f64; 2],
    hi: [f64; 2],
    near: f64,
}

/// One level of the grid: `n × n` cells over the occluders' screen box.
struct Level {
    n: usize,
    cell: [f64; 2],
    /// Where each cell's entries start in `entries` (one more offset than cells).
    starts: Vec<u32>,
    /// The cells' entries, cell after cell, each cell's in increasing number.
    entries: Vec<Entry>,
}

/// Occluders binned by their box on the light's screen, in levels of cells of doubling
/// size, each occluder on the finest level where its box (with the margin) covers at
/// most two cells across each way (so that a large occluder is not listed in, and read
/// from, hundreds of cells); those without a box (a corner at depth zero or less in a
/// central view) are candidates of every receiver.
pub(crate) struct Grid {
    extents: Vec<Option<Extent>>,
    /// The occluders without an extent.
    everywhere: Vec<u32>,
    lo: [f64; 2],
    levels: Vec<Level>,
    /// Whether the occluders are numbered nearest first (their `near` never decreases
    /// with the number): then a cell's walk stops at the first one beyond a receiver.
    nearest_first: bool,
    /// Screen and depth margins.
    margin: f64,
    dmargin: f64,
}

impl Grid {
    /// Bins `extents` (one per occluder; all `None` when the view is
    /// [`LightView::All`]).
    pub fn new(extents: Vec<Option<Extent>>) -> Grid {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        let (mut dlo, mut dhi) = (f64::INFINITY, f64::NEG_INFINITY);
        for e in extents.iter().flatten() {
            for i in 0..2 {
                lo[i] = lo[i].min(e.lo[i]);
                hi[i] = hi[i].max(e.hi[i]);
            }
            dlo = dlo.min(e.near);
            dhi = dhi.max(e.far);
        }
        let span = |a: f64, b: f64| {
            if a.is_finite() && b.is_finite() {
                (b - a).max(a.abs()).max(b.abs())
            } else {
                1.0
            }
        };
        let margin = 1e-9 * span(lo[0], hi[0]).max(span(lo[1], hi[1])) + 1e-300;
        let dmargin = 1e-9 * span(dlo, dhi) + 1e-300;
        let finest = ((extents.len() as f64).sqrt().ceil() as usize).clamp(1, 1024);
        let everywhere = (0..extents.len() as u32)
            .filter(|&i| extents[i as usize].is_none())
            .collect();
        let nearest_first = extents
            .iter()
            .flatten()
            .zip(extents.iter().flatten().skip(1))
            .all(|(a, b)| a.near <= b.near);
        let mut grid = Grid {
            extents,
            everywhere,
            lo,
            levels: Vec::new(),
            nearest_first,
            margin,
            dmargin,
        };
        // Cells per side halve from level to level, down to one cell.
        let mut n = finest;
        loop {
            let size = |i: usize| {
                let s = (hi[i] - lo[i]) / n as f64;
                if s.is_finite() && s > 0.0 {
                    s
                } else {
                    1.0
                }
            };
            grid.levels.push(Level {
                n,
                cell: [size(0), size(1)],
                starts: Vec::new(),
                entries: Vec::new(),
            });
            if n == 1 {
                break;
            }
            n = n.div_ceil(2);
        }
        // Each occluder's level: the finest where it covers at most two cells each way.
        let level_of: Vec<usize> = grid
            .extents
            .iter()
            .map(|e| match e {
                Some(e) => (0..grid.levels.len())
                    .find(|&l| {
                        let (x0, x1, y0, y1) = grid.range(l, e);
                        x1 - x0 <= 1 && y1 - y0 <= 1
                    })
                    .unwrap_or(grid.levels.len() - 1),
                None => 0,
            })
            .collect();
        for l in 0..grid.levels.len() {
            let n = grid.levels[l].n;
            // Count per cell, then place (in increasing number within each cell).
            let mut starts = vec![0u32; n * n + 1];
            let on_level = || {
                grid.extents
                    .iter()
                    .enumerate()
                    .filter_map(|(i, e)| e.filter(|_| level_of[i] == l).map(|e| (i, e)))
            };
            for (_, e) in on_level() {
                let (x0, x1, y0, y1) = grid.range(l, &e);
                for y in y0..=y1 {
                    for x in x0..=x1 {
                        starts[y * n + x + 1] += 1;
                    }
                }
            }
            for c in 1..starts.len() {
                starts[c] += starts[c - 1];
            }
            let mut next = starts.clone();
            let mut entries = Vec::with_capacity(starts[n * n] as usize);
            entries.resize(
                starts[n * n] as usize,
                Entry {
                    index: 0,
                    first: [0; 2],
                    lo: [0.0; 2],
                    hi: [0.0; 2],
                    near: 0.0,
                },
            );
            for (i, e) in on_level() {
                let (x0, x1, y0, y1) = grid.range(l, &e);
                let entry = Entry {
                    index: i as u32,
                    first: [x0 as u16, y0 as u16],
                    lo: e.lo,
                    hi: e.hi,
                    near: e.near,
                };
                for y in y0..=y1 {
                    for x in x0..=x1 {
                        let slot = &mut next[y * n + x];
                        entries[*slot as usize] = entry;
                        *slot += 1;
                    }
                }
            }
            grid.levels[l].starts = starts;
            grid.levels[l].entries = entries;
        }
        grid
    }

    /// The cells of level `l` a box (widened by the margin) covers.
    fn range(&self, l: usize, e: &Extent) -> (usize, usize, usize, usize) {
        let level = &self.levels[l];
        let at = |v: f64, i: usize| {
            let c = ((v - self.lo[i]) / level.cell[i]).floor();
            if c.is_nan() {
                0
            } else {
                c.clamp(0.0, (level.n - 1) as f64) as usize
            }
        };
        let m = self.margin;
        (
            at(e.lo[0] - m, 0),
            at(e.hi[0] + m, 0),
            at(e.lo[1] - m, 1),
            at(e.hi[1] + m, 1),
        )
    }

    /// Occluder `i`'s extent.
    pub fn extent(&self, i: u32) -> Option<Extent> {
        self.extents[i as usize]
    }

    /// Whether an occluder of extent `o` may hide a part of extent `r` (boxes meet and
    /// the occluder reaches nearer to the light than the part's farthest point, within
    /// the margins).
    pub fn may_hide(&self, o: Extent, r: &Extent) -> bool {
        self.boxes_meet(o.lo, o.hi, r) && o.near <= r.far + self.dmargin
    }

    /// Whether the screen box `lo..hi` meets `r`'s, within the margin.
    #[inline]
    fn boxes_meet(&self, lo: [f64; 2], hi: [f64; 2], r: &Extent) -> bool {
        let m = self.margin;
        lo[0] <= r.hi[0] + m && r.lo[0] <= hi[0] + m && lo[1] <= r.hi[1] + m && r.lo[1] <= hi[1] + m
    }

    /// Whether an occluder of extent `o` may hide all of a part of extent `r`: every
    /// point it hides is seen inside its box and farther than its nearest point, so `r`
    /// must lie in `o`'s box and no nearer than `o` (within the margins).
    pub fn may_cover(&self, o: Extent, r: &Extent) -> bool {
        let m = self.margin;
        o.lo[0] <= r.lo[0] + m
            && r.hi[0] <= o.hi[0] + m
            && o.lo[1] <= r.lo[1] + m
            && r.hi[1] <= o.hi[1] + m
            && o.near <= r.near + self.dmargin
    }

    /// The occluders whose box meets `r`'s and which reach nearer to the light than
    /// `r`'s farthest point ([`Grid::may_hide`]), each once, in increasing index order.
    ///
    /// On each level, an occluder is looked at only in the first cell that both its
    /// cells and `r`'s cover (so once, without marks); occluders numbered nearest first
    /// are looked at only up to the first one in a cell that reaches no nearer than
    /// `r`'s farthest point.
    pub fn candidates(&self, r: &Extent, out: &mut Vec<u32>) {
        out.clear();
        let far = r.far + self.dmargin;
        for (l, level) in self.levels.iter().enumerate() {
            if level.entries.is_empty() {
                continue;
            }
            let (x0, x1, y0, y1) = self.range(l, r);
            for y in y0..=y1 {
                for x in x0..=x1 {
                    let c = y * level.n + x;
                    let cell =
                        &level.entries[level.starts[c] as usize..level.starts[c + 1] as usize];
                    for e in cell {
                        let reaches = e.near <= far;
                        if !reaches {
                            if self.nearest_first {
                                break;
                            }
                            continue;
                        }
                        let first = (e.first[0] as usize).max(x0) == x
                            && (e.first[1] as usize).max(y0) == y;
                        if first && self.boxes_meet(e.lo, e.hi, r) {
                            out.push(e.index);
                        }
                    }
                }
            }
        }
        out.extend(&self.everywhere);
        out.sort_unstable();
    }
}
