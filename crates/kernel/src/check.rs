//! Invariant checks for tests and fuzzing (compiled with `cfg(test)` or the
//! `check-invariants` feature).

use crate::plane::Plane;
use crate::polygon::ExactPolygon;
use crate::predicates::homogeneous;
use crate::side::{PolygonSide, Side};

/// Checks the invariants of one exact polygon with exact predicates only (no filter):
/// at least three vertices; every vertex is the intersection of three independent
/// planes; it lies on the support plane and on its two edge planes, and strictly behind
/// every other edge plane (strict convexity, hence non-zero area); every cached
/// approximation is within its error bound of a position the exact predicates agree with.
pub fn check_polygon(poly: &ExactPolygon) -> Result<(), String> {
    let n = poly.len();
    if n < 3 {
        return Err(format!("polygon with {n} vertices"));
    }
    for i in 0..n {
        let [s, a, b] = poly.vertex_planes(i);
        let (_, d) = homogeneous(&s, &a, &b);
        if d.is_zero() {
            return Err(format!("vertex {i}: planes do not meet in a point"));
        }
        if poly.side_exact(i, &s) != Side::On {
            return Err(format!("vertex {i} is off the support plane"));
        }
        for j in 0..n {
            let e = poly.edge_plane(j);
            let incident = j == i || (j + 1) % n == i;
            let side = poly.side_exact(i, &e);
            if incident && side != Side::On {
                return Err(format!("vertex {i} is off its edge plane {j}"));
            }
            if !incident && side != Side::Back {
                return Err(format!(
                    "vertex {i} is {side:?} of edge plane {j} (expected Back)"
                ));
            }
        }
        check_approx(poly, i)?;
    }
    Ok(())
}

/// The cached approximation of vertex `i` must be consistent with the exact vertex: the
/// exact vertex lies inside the box `pos ± err`, checked exactly with six axis planes
/// through the (outward-rounded) bounds.
fn check_approx(poly: &ExactPolygon, i: usize) -> Result<(), String> {
    let (pos, err) = poly.vertex_approx(i);
    if err.is_nan() {
        return Err(format!("vertex {i}: error bound is NaN"));
    }
    if err.is_infinite() {
        return Ok(());
    }
    let [s, a, b] = poly.vertex_planes(i);
    for (axis, &x) in pos.iter().enumerate() {
        let lo = (x - err).next_down();
        let hi = (x + err).next_up();
        if !lo.is_finite() || !hi.is_finite() {
            continue;
        }
        let mut n = [0.0; 3];
        n[axis] = 1.0;
        let mut p_lo = [0.0; 3];
        p_lo[axis] = lo;
        let mut p_hi = [0.0; 3];
        p_hi[axis] = hi;
        let below = Plane::point_normal(p_lo, n).map_err(|e| e.to_string())?;
        let above = Plane::point_normal(p_hi, n).map_err(|e| e.to_string())?;
        let s_lo = crate::predicates::side_of_intersection(&s, &a, &b, &below);
        let s_hi = crate::predicates::side_of_intersection(&s, &a, &b, &above);
        if s_lo == Some(Side::Back) || s_hi == Some(Side::Front) {
            return Err(format!(
                "vertex {i}: approximation {x} ± {err} on axis {axis} misses the exact vertex"
            ));
        }
    }
    Ok(())
}

/// Checks one split: both pieces valid, each on its side of `plane`, and the pieces
/// present exactly when the original has vertices strictly on that side (or is coplanar
/// and faces that way).
pub fn check_split(
    original: &ExactPolygon,
    plane: &Plane,
    front: Option<&ExactPolygon>,
    back: Option<&ExactPolygon>,
) -> Result<(), String> {
    check_polygon(original)?;
    let sides: Vec<Side> = (0..original.len())
        .map(|i| original.side_exact(i, plane))
        .collect();
    let has_front = sides.contains(&Side::Front);
    let has_back = sides.contains(&Side::Back);
    let coplanar_front = !has_front && !has_back && original.support().same_facing(plane);
    let coplanar_back = !has_front && !has_back && !coplanar_front;
    if front.is_some() != (has_front || coplanar_front) {
        return Err(format!("front piece presence wrong (sides {sides:?})"));
    }
    if back.is_some() != (has_back || coplanar_back) {
        return Err(format!("back piece presence wrong (sides {sides:?})"));
    }
    for (piece, want) in [(front, Side::Front), (back, Side::Back)] {
        let Some(p) = piece else { continue };
        check_polygon(p)?;
        if p.support() != original.support() {
            return Err("piece changed its support plane".into());
        }
        let mut strict = false;
        for i in 0..p.len() {
            let s = p.side_exact(i, plane);
            if s == want.flip() {
                return Err(format!(
                    "piece vertex {i} on the wrong side of the splitter"
                ));
            }
            strict |= s == want;
        }
        let coplanar =
            (want == Side::Front && coplanar_front) || (want == Side::Back && coplanar_back);
        if !strict && !coplanar {
            return Err("piece without a vertex strictly on its side".into());
        }
        let expect = if coplanar {
            if want == Side::Front {
                PolygonSide::Coplanar
            } else {
                PolygonSide::CoplanarOpposite
            }
        } else if want == Side::Front {
            PolygonSide::Front
        } else {
            PolygonSide::Back
        };
        let got = p.classify(plane, false, &mut 0);
        if got != expect {
            return Err(format!("piece classifies as {got:?}, expected {expect:?}"));
        }
    }
    Ok(())
}
