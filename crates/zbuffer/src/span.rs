//! Triangle setup shared by every screen-space method: exact coverage of pixel centres
//! with the top-left rule, spans per row, and the depth plane.
//!
//! Coverage is decided with exact `orient2d` on the projected (f64) vertices: pixel
//! centre `p` is inside when, for every edge `a → b` of the counter-clockwise
//! (math orientation) triangle, `orient2d(a, b, p) > 0`, or `= 0` and the edge is a top
//! or left edge. In pixel coordinates (y down) an edge is *left* when it goes up
//! (`b.y < a.y`) and *top* when it is horizontal with the interior below (`b.y = a.y`,
//! `b.x > a.x`). Since `orient2d(b, a, p) = −orient2d(a, b, p)` exactly and the top-left
//! test flips with the edge direction, a centre on an edge shared by two triangles goes
//! to exactly one of them.
//!
//! Spans are found per row from the edges whose y-range contains the row's centre line
//! (the third edge cannot cut the span there): an approximate crossing is computed, then
//! corrected with the exact test, so every method that uses this module covers exactly
//! the same pixels.

use robust::{orient2d, Coord};

use crate::setup::ScreenVert;

/// A triangle ready for rasterisation.
#[derive(Debug, Clone, Copy)]
pub(crate) struct TriSetup {
    v: [Coord<f64>; 3],
    tl: [bool; 3],
    ymin: f64,
    ymax: f64,
    /// First and last row whose centre may be covered (clamped to the picture).
    pub row_lo: u32,
    pub row_hi: u32,
    col_lo: u32,
    col_end: u32,
    /// Depth plane: `d(x, y) = d0 + gx·(x − x0) + gy·(y − y0)`, clamped to [dmin, dmax].
    x0: f64,
    y0: f64,
    d0: f64,
    pub gx: f64,
    gy: f64,
    pub dmin: f64,
    pub dmax: f64,
}

impl TriSetup {
    /// Sets up a triangle for a `width × height` picture; `None` when it has zero area,
    /// is not finite, or covers no row or column of the picture.
    pub fn new(
        a: ScreenVert,
        b: ScreenVert,
        c: ScreenVert,
        width: u32,
        height: u32,
    ) -> Option<Self> {
        let (mut p, mut q, r) = (a, b, c);
        let pt = |s: ScreenVert| Coord { x: s.x, y: s.y };
        let o = orient2d(pt(p), pt(q), pt(r));
        if o == 0.0 || o.is_nan() {
            return None;
        }
        if o < 0.0 {
            std::mem::swap(&mut p, &mut q);
        }
        let vs = [p, q, r];
        if vs
            .iter()
            .any(|s| !(s.x.is_finite() && s.y.is_finite() && s.d.is_finite()))
        {
            return None;
        }
        let ymin = p.y.min(q.y).min(r.y);
        let ymax = p.y.max(q.y).max(r.y);
        let xmin = p.x.min(q.x).min(r.x);
        let xmax = p.x.max(q.x).max(r.x);
        let (rl, rh) = index_range(ymin, ymax, height)?;
        let (cl, ch) = index_range(xmin, xmax, width)?;
        let v = vs.map(pt);
        let tl = [0, 1, 2].map(|i| {
            let (s, e) = (v[i], v[(i + 1) % 3]);
            e.y < s.y || (e.y == s.y && e.x > s.x)
        });
        // Depth plane through the three vertices.
        let (e1x, e1y, e1d) = (q.x - p.x, q.y - p.y, q.d - p.d);
        let (e2x, e2y, e2d) = (r.x - p.x, r.y - p.y, r.d - p.d);
        let det = e1x * e2y - e2x * e1y;
        let (mut gx, mut gy) = ((e1d * e2y - e2d * e1y) / det, (e2d * e1x - e1d * e2x) / det);
        if !(gx.is_finite() && gy.is_finite()) {
            gx = 0.0;
            gy = 0.0;
        }
        Some(TriSetup {
            v,
            tl,
            ymin,
            ymax,
            row_lo: rl,
            row_hi: rh,
            col_lo: cl,
            col_end: ch + 1,
            x0: p.x,
            y0: p.y,
            d0: p.d,
            gx,
            gy,
            dmin: p.d.min(q.d).min(r.d),
            dmax: p.d.max(q.d).max(r.d),
        })
    }

    /// Whether pixel centre `(x, y)` is covered, with the top-left rule.
    #[inline]
    pub fn covers(&self, x: f64, y: f64) -> bool {
        let p = Coord { x, y };
        (0..3).all(|i| self.pass(i, p))
    }

    #[inline]
    fn pass(&self, i: usize, p: Coord<f64>) -> bool {
        let e = orient2d(self.v[i], self.v[(i + 1) % 3], p);
        e > 0.0 || (e == 0.0 && self.tl[i])
    }

    /// Whether every edge test fails or passes at all four corners: `Some(true)` when
    /// the four centres (hence every centre between them) are covered, `Some(false)`
    /// when one edge rejects all four (none is covered), `None` otherwise.
    pub fn classify_corners(&self, corners: [(f64, f64); 4]) -> Option<bool> {
        let mut all_in = true;
        for i in 0..3 {
            let mut n = 0;
            for &(x, y) in &corners {
                if self.pass(i, Coord { x, y }) {
                    n += 1;
                }
            }
            if n == 0 {
                return Some(false);
            }
            all_in &= n == 4;
        }
        all_in.then_some(true)
    }

    /// Bounding box `(xmin, ymin, xmax, ymax)` of the projected triangle.
    pub fn bbox(&self) -> (f64, f64, f64, f64) {
        let xs = self.v.map(|c| c.x);
        let ys = self.v.map(|c| c.y);
        (
            xs[0].min(xs[1]).min(xs[2]),
            ys[0].min(ys[1]).min(ys[2]),
            xs[0].max(xs[1]).max(xs[2]),
            ys[0].max(ys[1]).max(ys[2]),
        )
    }

    /// Depth of the plane at `(x, y)`, not clamped.
    #[inline]
    pub fn plane_depth(&self, x: f64, y: f64) -> f64 {
        self.d0 + self.gx * (x - self.x0) + self.gy * (y - self.y0)
    }

    /// Depth at a covered pixel centre: the plane, clamped to the vertices' range.
    #[inline]
    pub fn depth_at(&self, x: f64, y: f64) -> f64 {
        self.plane_depth(x, y).clamp(self.dmin, self.dmax)
    }

    /// The covered columns `[x0, x1)` of row `row`, intersected with `[lo, hi)`.
    pub fn span_within(&self, row: u32, lo: u32, hi: u32) -> Option<(u32, u32)> {
        let yc = row as f64 + 0.5;
        if yc < self.ymin || yc > self.ymax {
            return None;
        }
        let mut lo = lo.max(self.col_lo);
        let mut hi = hi.min(self.col_end);
        for i in 0..3 {
            if lo >= hi {
                return None;
            }
            let (a, b) = (self.v[i], self.v[(i + 1) % 3]);
            if yc < a.y.min(b.y) || yc > a.y.max(b.y) {
                continue;
            }
            if a.y == b.y {
                if !self.pass(i, Coord { x: a.x, y: yc }) {
                    return None;
                }
                continue;
            }
            let xs = a.x + (b.x - a.x) * ((yc - a.y) / (b.y - a.y));
            let pass = |k: u32| {
                self.pass(
                    i,
                    Coord {
                        x: k as f64 + 0.5,
                        y: yc,
                    },
                )
            };
            // Clamped first, so the integer conversions below are exact floors.
            let guess = (xs - 0.5).clamp(lo as f64 - 1.0, hi as f64 + 1.0);
            let g = if guess.is_nan() {
                lo as f64
            } else {
                floor(guess)
            };
            if b.y < a.y {
                // The test passes to the right of the edge: first passing column.
                let g = if g < guess { g + 1.0 } else { g };
                lo = first_true(lo, hi, g, pass);
            } else {
                // Passes to the left: first failing column ends the span.
                hi = first_true(lo, hi, g + 1.0, |k| !pass(k));
            }
        }
        (lo < hi).then_some((lo, hi))
    }

    /// The covered columns of row `row`.
    #[inline]
    pub fn span(&self, row: u32) -> Option<(u32, u32)> {
        self.span_within(row, 0, u32::MAX)
    }

    /// Calls `f(x, depth)` for every covered pixel of row `row` within `[lo, hi)`, with
    /// depth stepped incrementally along the span from its first pixel.
    #[inline]
    pub fn for_each_in_row(&self, row: u32, lo: u32, hi: u32, mut f: impl FnMut(u32, f64)) {
        if let Some((x0, x1)) = self.span_within(row, lo, hi) {
            let mut d = self.plane_depth(x0 as f64 + 0.5, row as f64 + 0.5);
            for x in x0..x1 {
                f(x, d.clamp(self.dmin, self.dmax));
                d += self.gx;
            }
        }
    }
}

/// `x.floor()` for |x| < 2⁶², without a call into libm (the baseline x86-64 target has
/// no rounding instruction).
#[inline]
fn floor(x: f64) -> f64 {
    let t = x as i64 as f64;
    if t > x {
        t - 1.0
    } else {
        t
    }
}

/// Indices `k` in `[0, n)` whose centre `k + ½` may lie in `[lo, hi]` (a superset by at
/// most one on each side), or `None`.
fn index_range(lo: f64, hi: f64, n: u32) -> Option<(u32, u32)> {
    // Clamp first so that the conversions are exact; floor(lo − ½) may be one below
    // the ceiling, which the superset allows.
    let a = floor((lo - 0.5).clamp(-1.0, n as f64)) - 1.0;
    let b = floor((hi - 0.5).clamp(-2.0, n as f64)) + 1.0;
    let a = a.max(0.0);
    let b = b.min(n as f64 - 1.0);
    (a <= b).then_some((a as u32, b as u32))
}

/// The first `k` in `[lo, hi)` with `pred(k)` (`pred` false then true), or `hi`; starts
/// from `guess` and falls back to bisection when the guess is poor.
#[inline]
fn first_true(lo: u32, hi: u32, guess: f64, pred: impl Fn(u32) -> bool) -> u32 {
    if lo >= hi {
        return hi;
    }
    let g = if guess.is_nan() {
        lo
    } else {
        guess.clamp(lo as f64, hi as f64) as u32
    };
    // Typical case: the guess is exact or one off.
    let here = g < hi && pred(g);
    let before = g > lo && pred(g - 1);
    if here && !before {
        return g;
    }
    if !here && !before && (g + 1 >= hi || pred(g + 1)) {
        return (g + 1).min(hi);
    }
    // Bisection on the monotone predicate.
    let (mut a, mut b) = if before { (lo, g - 1) } else { (g, hi) };
    while a < b {
        let m = a + (b - a) / 2;
        if pred(m) {
            b = m;
        } else {
            a = m + 1;
        }
    }
    a
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_true_finds_the_boundary_from_any_guess() {
        for boundary in 0..=10u32 {
            for guess in [-5.0, 0.0, 3.0, 9.0, 10.0, 50.0, f64::NAN] {
                assert_eq!(first_true(0, 10, guess, |k| k >= boundary), boundary);
            }
        }
        assert_eq!(first_true(4, 4, 2.0, |_| true), 4);
    }

    #[test]
    fn spans_match_the_pointwise_test() {
        let sv = |x, y| ScreenVert { x, y, d: 0.5 };
        let t = TriSetup::new(sv(1.3, 0.2), sv(17.9, 5.5), sv(4.0, 12.0), 20, 14).unwrap();
        for row in 0..14 {
            for x in 0..20 {
                let inside = t.span(row).is_some_and(|(a, b)| (a..b).contains(&x));
                assert_eq!(inside, t.covers(x as f64 + 0.5, row as f64 + 0.5));
            }
        }
    }
}
