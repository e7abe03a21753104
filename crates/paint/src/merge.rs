//! A face's pieces written on the writer's grid as one path: with
//! [`Picture::merge_pieces`] the union of a run's polygons, with holes where needed, so
//! that the edges between the pieces of one face (T-junctions included) are not in the
//! file; without, each piece a subpath, snap-rounded together so that no crack opens
//! between them ([`crate::snap`]).
//!
//! The union is taken of the polygons *as written*: every corner is first rounded to the
//! writer's grid (`decimals` decimals, half away from zero, as [`crate::number`] writes
//! numbers), every edge passed through the grid points of the run's corners it meets
//! (snap rounding: a T-junction's corner and its neighbour's edge then meet on the grid),
//! and the union of those integer polygons is computed by `i_overlay` with exact integer
//! predicates under the non-zero rule, each polygon turned as the writers turn the
//! subpaths of a run (see [`reversals`]). The outline written is thus the area the
//! subpaths would fill, decided without any tolerance; the only rounding is that of the
//! points where two rounded edges cross, to the same grid, less than half a unit of the
//! last decimal from the exact crossing. Collinear corners are dropped.
//!
//! [`Picture::merge_pieces`]: crate::Picture::merge_pieces

use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay::IntOverlayOptions;
use i_overlay::core::simplify::Simplify;
use i_overlay::i_float::int::point::IntPoint;

use crate::number::{push_scaled, round_scaled, MAX_DECIMALS};
use crate::runs::{reversals, Frag};
use crate::snap::{snapped_rings, GridRing};

/// A run's outline: shapes, each its outer ring then its holes (turned the other way),
/// corners in units of `10^-decimals` of the page's unit, in the writer's page
/// coordinates.
pub(crate) type Shapes = Vec<Vec<GridRing>>;

/// The largest magnitude of a grid coordinate `i_overlay`'s 32-bit engine takes.
const MAX_GRID: i64 = (1 << 30) - 1;

/// A run of several fragments on the writer's grid, each corner first mapped to page
/// coordinates by `page` (as the writer maps it before writing it): with `merge`, the
/// union of its polygons ([`union`]); without, each polygon a shape of one ring, the
/// polygons snap-rounded together (see [`crate::snap`]) so that no crack opens between
/// them once written. `None` when the run is one fragment or a coordinate is beyond the
/// grid's range: the writer then writes the run's subpaths as they are. The union is
/// empty when every polygon is degenerate once rounded (it fills no point): a writer
/// leaves such a run out, unless it strokes its fills.
pub(crate) fn run_shapes(
    run: &[Frag<'_>],
    decimals: u8,
    merge: bool,
    page: impl Fn([f64; 2]) -> [f64; 2],
) -> Option<Shapes> {
    if merge {
        return union(run, decimals, page);
    }
    if run.len() < 2 {
        return None;
    }
    let rings = snapped_rings(oriented(run), decimals, page)?;
    Some(rings.into_iter().map(|r| vec![r]).collect())
}

/// Each fragment's corners, turned as the writers turn the subpaths of a run.
fn oriented<'r>(
    run: &'r [Frag<'_>],
) -> impl Iterator<Item = impl Iterator<Item = [f64; 2]> + 'r> + 'r {
    run.iter()
        .zip(reversals(run))
        .map(|(f, reverse)| f.oriented(reverse))
}

/// The union of `run`'s polygons on the grid of `decimals` decimals, snap-rounded
/// together first, each corner first mapped to page coordinates by `page` (as the writer
/// maps it before writing it). `None` when there is nothing to merge (one fragment) or
/// when a coordinate is beyond the integer engine's range: the writer then writes the
/// run's subpaths as they are. The union is empty when every polygon is degenerate once
/// rounded (it fills no point): a writer leaves such a run out, unless it strokes its
/// fills.
pub(crate) fn union(
    run: &[Frag<'_>],
    decimals: u8,
    page: impl Fn([f64; 2]) -> [f64; 2],
) -> Option<Shapes> {
    if run.len() < 2 {
        return None;
    }
    union_of_rings(snapped_rings(oriented(run), decimals, page)?)
}

/// The union under the non-zero rule of grid `rings`; `None` when a coordinate is beyond
/// the integer engine's range.
fn union_of_rings(rings: Vec<GridRing>) -> Option<Shapes> {
    let mut contours: Vec<Vec<IntPoint<i32>>> = Vec::with_capacity(rings.len());
    for ring in rings {
        let mut contour = Vec::with_capacity(ring.len());
        for [x, y] in ring {
            if x.abs() > MAX_GRID || y.abs() > MAX_GRID {
                return None;
            }
            // In range: the casts are exact.
            contour.push(IntPoint::new(x as i32, y as i32));
        }
        contours.push(contour);
    }
    let shapes = contours.simplify(FillRule::NonZero, IntOverlayOptions::default());
    Some(map_corners(shapes, |q| [i64::from(q.x), i64::from(q.y)]))
}

/// `shapes` with every corner mapped by `f`.
fn map_corners<P, Q>(shapes: Vec<Vec<Vec<P>>>, f: impl Fn(P) -> Q + Copy) -> Vec<Vec<Vec<Q>>> {
    shapes
        .into_iter()
        .map(|shape| {
            shape
                .into_iter()
                .map(|ring| ring.into_iter().map(f).collect())
                .collect()
        })
        .collect()
}

/// The area polygons fill together, as few outlines as it takes: the union under the
/// non-zero rule of `polygons`, each first turned the way the first one turns (as the
/// vector writers turn the subpaths of one path), its corners rounded to the grid of
/// `decimals` decimals (half away from zero; at most 9) and its edges passed through the
/// grid points of the corners they meet (snap rounding: no crack opens where a corner
/// lies on another polygon's edge). Returns shapes, each an outer
/// ring and its holes (turned the other way), corners on that grid; collinear corners
/// dropped. The outline is that of the snapped polygons, decided with exact integer
/// predicates; only where two snapped edges cross is a corner rounded again, to the same
/// grid.
/// `None` when a coordinate times `10^decimals` is beyond ±2³⁰ (the integer engine's
/// range). Polygons that fill nothing once rounded add nothing.
pub fn union_of_polygons(
    polygons: &[&[[f64; 2]]],
    decimals: u8,
) -> Option<Vec<Vec<Vec<[f64; 2]>>>> {
    let decimals = decimals.min(MAX_DECIMALS);
    let area2 = |p: &[[f64; 2]]| -> f64 {
        (0..p.len())
            .map(|i| {
                let (a, b) = (p[i], p[(i + 1) % p.len()]);
                a[0] * b[1] - b[0] * a[1]
            })
            .sum()
    };
    let first = polygons.first().map_or(0.0, |p| area2(p));
    let rings = snapped_rings(
        polygons.iter().map(|p| {
            let reverse = area2(p) * first < 0.0;
            let n = p.len();
            (0..n).map(move |k| p[if reverse { n - 1 - k } else { k }])
        }),
        decimals,
        |q| q,
    )?;
    let shapes = union_of_rings(rings)?;
    let unit = 10f64.powi(i32::from(decimals));
    Some(map_corners(shapes, |q: [i64; 2]| {
        [q[0] as f64 / unit, q[1] as f64 / unit]
    }))
}

/// Whether polygon `points`, mapped to the page by `page` and rounded to the grid of
/// `decimals` decimals as a writer writes it, fills no point: all its rounded corners
/// lie on one line (exact integer cross products). `false` when a coordinate cannot be
/// rounded so (the polygon is then written as it is).
pub(crate) fn fills_nothing(
    points: &[[f64; 2]],
    decimals: u8,
    page: impl Fn([f64; 2]) -> [f64; 2],
) -> bool {
    let mut grid = Vec::with_capacity(points.len());
    for &p in points {
        let q = page(p);
        match (round_scaled(q[0], decimals), round_scaled(q[1], decimals)) {
            (Some(x), Some(y)) => grid.push([i128::from(x), i128::from(y)]),
            _ => return false,
        }
    }
    let a = grid[0];
    let Some(b) = grid.iter().copied().find(|&q| q != a) else {
        return true;
    };
    grid.iter()
        .all(|q| (b[0] - a[0]) * (q[1] - a[1]) == (b[1] - a[1]) * (q[0] - a[0]))
}

/// The number of corners of a shape (its outer ring and holes).
pub(crate) fn corners(shape: &[GridRing]) -> usize {
    shape.iter().map(Vec::len).sum()
}

/// Appends rings as SVG path data (`M x y L x y x y … Z` each).
pub(crate) fn push_svg_rings<'r>(
    b: &mut Vec<u8>,
    rings: impl Iterator<Item = &'r GridRing>,
    decimals: u8,
) {
    for ring in rings {
        for (k, p) in ring.iter().enumerate() {
            b.push(match k {
                0 => b'M',
                1 => b'L',
                _ => b' ',
            });
            push_scaled(b, p[0], decimals);
            b.push(b' ');
            push_scaled(b, p[1], decimals);
        }
        b.push(b'Z');
    }
}

/// Appends a shape's rings as PDF and PostScript path operators (`x y m`, `x y l`, `h`),
/// one line per ring.
pub(crate) fn push_moveto_lineto(b: &mut Vec<u8>, shape: &[GridRing], decimals: u8) {
    for ring in shape {
        for (k, p) in ring.iter().enumerate() {
            push_scaled(b, p[0], decimals);
            b.push(b' ');
            push_scaled(b, p[1], decimals);
            b.extend_from_slice(if k == 0 { b" m " } else { b" l " });
        }
        b.extend_from_slice(b"h\n");
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::runs::{check, walk};
    use crate::{PaintFragment, Picture};

    /// The shapes of the one run of `frags` (one face, one colour) on a grid of 2
    /// decimals.
    fn shapes_of(frags: Vec<Vec<[f64; 2]>>) -> Option<Shapes> {
        let mut p = Picture::new(100, 100);
        for pts in frags {
            p.fragments
                .push(PaintFragment::new(pts, [1.0, 0.0, 0.0, 1.0]));
        }
        let guard = check(&p).unwrap().guard;
        let mut out = None;
        walk(
            &p,
            &guard,
            |_| (),
            |run, _| {
                out = union(run, 2, |q| q);
                Ok(())
            },
        )
        .unwrap();
        out
    }

    fn sq(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<[f64; 2]> {
        vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
    }

    #[test]
    fn a_t_junction_dissolves_into_one_ring() {
        // The left half's right edge is split by the corner the two right quarters
        // share: a T-junction. Either turn of the pieces.
        let mut right_top = sq(5.0, 0.0, 10.0, 5.0);
        right_top.reverse();
        let s = shapes_of(vec![
            sq(0.0, 0.0, 5.0, 10.0),
            right_top,
            sq(5.0, 5.0, 10.0, 10.0),
        ])
        .unwrap();
        assert_eq!(s.len(), 1);
        assert_eq!(s[0].len(), 1);
        let mut corners: Vec<(i64, i64)> = s[0][0].iter().map(|p| (p[0], p[1])).collect();
        corners.sort();
        assert_eq!(corners, vec![(0, 0), (0, 1000), (1000, 0), (1000, 1000)]);
    }

    #[test]
    fn a_ring_of_pieces_keeps_its_hole() {
        let s = shapes_of(vec![
            sq(0.0, 0.0, 10.0, 3.0),
            sq(0.0, 3.0, 3.0, 7.0),
            sq(7.0, 3.0, 10.0, 7.0),
            sq(0.0, 7.0, 10.0, 10.0),
        ])
        .unwrap();
        assert_eq!(s.len(), 1);
        assert_eq!(s[0].len(), 2, "an outer ring and a hole");
        let area2 = |ring: &[[i64; 2]]| -> i64 {
            (0..ring.len())
                .map(|i| {
                    let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
                    a[0] * b[1] - b[0] * a[1]
                })
                .sum()
        };
        let (outer, hole) = (area2(&s[0][0]), area2(&s[0][1]));
        assert_eq!(outer.abs(), 2 * 1000 * 1000);
        assert_eq!(hole.abs(), 2 * 400 * 400);
        assert!(outer * hole < 0, "the hole turns the other way");
    }

    #[test]
    fn slivers_that_round_to_a_line_fill_nothing() {
        let id = |q: [f64; 2]| q;
        assert!(fills_nothing(
            &[[1.0, 1.0], [2.0, 2.0], [3.001, 3.0]],
            2,
            id
        ));
        assert!(fills_nothing(
            &[[1.0, 1.0], [1.001, 1.0], [1.0, 1.004]],
            2,
            id
        ));
        assert!(!fills_nothing(
            &[[1.0, 1.0], [2.0, 2.0], [3.01, 3.0]],
            2,
            id
        ));
        // A bow tie has no signed area but fills two triangles.
        let bow = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
        assert!(!fills_nothing(&bow, 2, id));
        let s = shapes_of(vec![
            vec![[1.0, 1.0], [2.0, 2.0], [3.001, 3.0]],
            vec![[5.0, 1.0], [5.0, 2.0], [5.0, 3.0]],
        ]);
        assert_eq!(s, Some(Vec::new()));
    }

    #[test]
    fn disjoint_pieces_stay_apart_and_one_piece_is_left_alone() {
        let s = shapes_of(vec![sq(0.0, 0.0, 1.0, 1.0), sq(2.0, 0.0, 3.0, 1.0)]).unwrap();
        assert_eq!(s.len(), 2);
        assert!(shapes_of(vec![sq(0.0, 0.0, 1.0, 1.0)]).is_none());
    }
}
