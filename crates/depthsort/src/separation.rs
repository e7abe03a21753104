//! The separating-axis test of [`crate::geom::convex_disjoint`] for the many pairs of one
//! large set: each polygon's edge normals, margins and its own extent along them are
//! computed once per set instead of once per pair, so a pair costs only the other
//! polygon's extents, read from one contiguous table. The float operations are those of
//! `convex_disjoint`, in the same order, so the answers are the same bit for bit (a unit
//! test compares them).

use crate::geom::{higher, lower};

/// The edge axes of a set of convex polygons, side by side.
pub(crate) struct SeparatingAxes {
    /// Every polygon's corners, polygon after polygon.
    pts: Vec<[f64; 2]>,
    /// Every polygon's usable edge axes `(nx, ny, margin × length, own min, own max)`,
    /// polygon after polygon.
    axes: Vec<[f64; 5]>,
    /// `pts[corners[i]..corners[i + 1]]` and `axes[first_axis[i]..first_axis[i + 1]]`
    /// belong to polygon `i`.
    corners: Vec<u32>,
    first_axis: Vec<u32>,
}

impl SeparatingAxes {
    /// The axes of `polygons` (each convex, as projected pieces are) for `margin`.
    /// The tables are sized from the corners before they are filled (growing them by
    /// doubling touched twice the memory of a large set).
    pub(crate) fn new<'a>(
        polygons: impl Iterator<Item = &'a [[f64; 2]]> + Clone,
        margin: f64,
    ) -> Self {
        let (count, corners) = polygons
            .clone()
            .fold((0, 0), |(c, k), a| (c + 1, k + a.len()));
        let mut s = SeparatingAxes {
            pts: Vec::with_capacity(corners),
            axes: Vec::with_capacity(corners),
            corners: Vec::with_capacity(count + 1),
            first_axis: Vec::with_capacity(count + 1),
        };
        s.corners.push(0);
        s.first_axis.push(0);
        for a in polygons {
            let n = a.len();
            for i in 0..n {
                let (p, q) = (a[i], a[(i + 1) % n]);
                let (nx, ny) = (q[1] - p[1], p[0] - q[0]);
                let len = nx.abs() + ny.abs();
                if len.is_nan() || len <= 0.0 {
                    continue;
                }
                let (mut amin, mut amax) = (f64::INFINITY, f64::NEG_INFINITY);
                for v in a {
                    let d = v[0] * nx + v[1] * ny;
                    amin = lower(d, amin);
                    amax = higher(d, amax);
                }
                s.axes.push([nx, ny, margin * len, amin, amax]);
            }
            s.pts.extend_from_slice(a);
            s.corners.push(s.pts.len() as u32);
            s.first_axis.push(s.axes.len() as u32);
        }
        s
    }

    /// Whether polygons `i` and `j` are separated by a gap wider than the margin along
    /// one of their edge normals: [`crate::geom::convex_disjoint`] of the two.
    pub(crate) fn disjoint(&self, i: usize, j: usize) -> bool {
        self.separated_by_axes_of(i, j) || self.separated_by_axes_of(j, i)
    }

    fn separated_by_axes_of(&self, a: usize, b: usize) -> bool {
        let axes = &self.axes[self.first_axis[a] as usize..self.first_axis[a + 1] as usize];
        let pts = &self.pts[self.corners[b] as usize..self.corners[b + 1] as usize];
        axes.iter().any(|&[nx, ny, m, amin, amax]| {
            let (mut bmin, mut bmax) = (f64::INFINITY, f64::NEG_INFINITY);
            for v in pts {
                let d = v[0] * nx + v[1] * ny;
                bmin = lower(d, bmin);
                bmax = higher(d, bmax);
            }
            amax + m < bmin || bmax + m < amin
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::convex_disjoint;

    #[test]
    fn the_same_answers_as_convex_disjoint() {
        let mut r = crate::rng::SplitMix::new(5);
        let mut u = || (r.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        // Triangles, quads and hexagons (regular, turned, scaled), some degenerate, many
        // nearly touching.
        let polys: Vec<Vec<[f64; 2]>> = (0..300)
            .map(|k| {
                let (cx, cy, s, t) = (u() * 20.0, u() * 20.0, u() * 3.0, u() * 6.3);
                let n = [3, 4, 6][k % 3];
                let s = if k % 37 == 0 { 0.0 } else { s };
                (0..n)
                    .map(|i| {
                        let a = t + i as f64 * std::f64::consts::TAU / n as f64;
                        [cx + s * a.cos(), cy + s * a.sin()]
                    })
                    .collect()
            })
            .collect();
        for margin in [0.0, 1e-7, 0.5] {
            let axes = SeparatingAxes::new(polys.iter().map(|p| p.as_slice()), margin);
            let mut disjoint = 0;
            for i in 0..polys.len() {
                for j in 0..polys.len() {
                    let want = convex_disjoint(&polys[i], &polys[j], margin);
                    assert_eq!(axes.disjoint(i, j), want, "{i} {j} margin {margin}");
                    disjoint += usize::from(want);
                }
            }
            assert!(disjoint > 0 && disjoint < polys.len() * polys.len());
        }
    }
}
