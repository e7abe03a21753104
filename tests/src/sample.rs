//! Which face a painter's order shows at pixel centres (the last fragment containing the
//! centre), in floats; centres within a small distance of a fragment edge are reported as
//! ambiguous rather than guessed.

use limn_depthsort::Fragment;

/// The face seen at one sample, or that the sample is too close to an edge to tell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Seen {
    /// No fragment covers the sample.
    Nothing,
    /// This face covers it.
    Face(u32),
    /// The sample lies within the tolerance of some fragment edge.
    Ambiguous,
}

/// Samples a `w`×`h` grid of pixel centres; `tol` is the edge tolerance in pixels.
pub fn sample(fragments: &[Fragment], w: u32, h: u32, tol: f64) -> Vec<Seen> {
    let mut out = vec![Seen::Nothing; (w * h) as usize];
    for f in fragments {
        let pts = &f.points;
        let n = pts.len();
        let (mut x0, mut y0, mut x1, mut y1) = (
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        );
        for p in pts {
            x0 = x0.min(p[0]);
            y0 = y0.min(p[1]);
            x1 = x1.max(p[0]);
            y1 = y1.max(p[1]);
        }
        let area: f64 = (0..n)
            .map(|i| {
                let (a, b) = (pts[i], pts[(i + 1) % n]);
                a[0] * b[1] - a[1] * b[0]
            })
            .sum();
        if area == 0.0 {
            continue;
        }
        let s = area.signum();
        let jy0 = ((y0 - tol - 0.5).floor().max(0.0)) as u32;
        let jy1 = ((y1 + tol - 0.5).ceil().min(h as f64 - 1.0)).max(-1.0) as i64;
        let ix0 = ((x0 - tol - 0.5).floor().max(0.0)) as u32;
        let ix1 = ((x1 + tol - 0.5).ceil().min(w as f64 - 1.0)).max(-1.0) as i64;
        for j in jy0 as i64..=jy1 {
            for i in ix0 as i64..=ix1 {
                let c = [i as f64 + 0.5, j as f64 + 0.5];
                let mut inside = true;
                let mut near = false;
                for k in 0..n {
                    let (a, b) = (pts[k], pts[(k + 1) % n]);
                    let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
                    let len = (ex * ex + ey * ey).sqrt();
                    if len == 0.0 {
                        continue;
                    }
                    let d = s * (ex * (c[1] - a[1]) - ey * (c[0] - a[0])) / len;
                    if d < -tol {
                        inside = false;
                        break;
                    }
                    if d <= tol {
                        near = true;
                    }
                }
                if !inside {
                    continue;
                }
                let slot = &mut out[(j as u32 * w + i as u32) as usize];
                *slot = if near {
                    Seen::Ambiguous
                } else {
                    Seen::Face(f.face)
                };
            }
        }
    }
    out
}

/// Number of samples where both are definite and differ.
pub fn disagreements(a: &[Seen], b: &[Seen]) -> usize {
    a.iter()
        .zip(b)
        .filter(|(x, y)| match (x, y) {
            (Seen::Ambiguous, _) | (_, Seen::Ambiguous) => false,
            _ => x != y,
        })
        .count()
}
