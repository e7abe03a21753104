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

/// Occluders binned by their box on the light's screen; those without one (a corner
/// at depth zero or less in a central view) are candidates of every receiver.
pub(crate) struct Grid {
    extents: Vec<Option<Extent>>,
    /// The occluders without an extent.
    everywhere: Vec<u32>,
    lo: [f64; 2],
    cell: [f64; 2],
    n: usize,
    cells: Vec<Vec<u32>>,
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
        let n = ((extents.len() as f64).sqrt().ceil() as usize).clamp(1, 1024);
        let everywhere = (0..extents.len() as u32)
            .filter(|&i| extents[i as usize].is_none())
            .collect();
        let size = |i: usize| {
            let s = (hi[i] - lo[i]) / n as f64;
            if s.is_finite() && s > 0.0 {
                s
            } else {
                1.0
            }
        };
        let cell = [size(0), size(1)];
        let mut grid = Grid {
            extents,
            everywhere,
            lo,
            cell,
            n,
            cells: vec![Vec::new(); n * n],
            margin,
            dmargin,
        };
        for (i, e) in grid.extents.iter().enumerate() {
            let Some(e) = e else { continue };
            let (x0, x1, y0, y1) = grid.range(e);
            for y in y0..=y1 {
                for x in x0..=x1 {
                    grid.cells[y * n + x].push(i as u32);
                }
            }
        }
        grid
    }

    /// The cells a box (widened by the margin) covers.
    fn range(&self, e: &Extent) -> (usize, usize, usize, usize) {
        let at = |v: f64, i: usize| {
            let c = ((v - self.lo[i]) / self.cell[i]).floor();
            if c.is_nan() {
                0
            } else {
                c.clamp(0.0, (self.n - 1) as f64) as usize
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
        let m = self.margin;
        o.lo[0] <= r.hi[0] + m
            && r.lo[0] <= o.hi[0] + m
            && o.lo[1] <= r.hi[1] + m
            && r.lo[1] <= o.hi[1] + m
            && o.near <= r.far + self.dmargin
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
    /// `r`'s farthest point, each once, in increasing index order (`seen` is working
    /// space of one flag per occluder, left all `false`).
    pub fn candidates(&self, r: &Extent, seen: &mut Vec<bool>, out: &mut Vec<u32>) {
        out.clear();
        seen.resize(self.extents.len(), false);
        let (x0, x1, y0, y1) = self.range(r);
        for y in y0..=y1 {
            for x in x0..=x1 {
                for &i in &self.cells[y * self.n + x] {
                    if seen[i as usize] {
                        continue;
                    }
                    seen[i as usize] = true;
                    if self.extents[i as usize].is_some_and(|e| self.may_hide(e, r)) {
                        out.push(i);
                    }
                }
            }
        }
        for &i in out.iter() {
            seen[i as usize] = false;
        }
        // Reset the flags of the rejected ones too.
        for y in y0..=y1 {
            for x in x0..=x1 {
                for &i in &self.cells[y * self.n + x] {
                    seen[i as usize] = false;
                }
            }
        }
        out.extend(&self.everywhere);
        out.sort_unstable();
    }
}
