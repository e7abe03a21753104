//! Phong interpolation for painters whose smooth shading is linear (PDF and EPS type-4
//! meshes, the PNG painter's Gouraud fill): a triangle is split, adaptively, into
//! Gouraud triangles until the linear interpolation of their corner colours is within a
//! tolerance of per-point Phong shading.
//!
//! Splitting is done in world space (edge midpoints of the planar face), so the pieces
//! tile the projected triangle exactly as the projection maps them. A triangle is
//! accepted when, at seven sample points (the three edge midpoints, the centroid and the
//! three points half-way between the centroid and the corners), the colour the painter
//! will show there — the screen-space linear interpolation of the corner colours — is
//! within *half* the tolerance of the Phong colour of the world point that projects
//! there, in every channel; the other half is the margin for the points between samples
//! (where clamping at full intensity puts kinks in the colour, sampling at the full
//! tolerance let differences of 1.15 times the tolerance through; with the margin the
//! worst seen on a glossy sphere is 0.66 of it, `tests/phong_shading.rs`).
//!
//! Two guards make the sampling trustworthy on highlights smaller than a triangle: a
//! triangle of a specular material is also split while the angle `θ` between two of its
//! corner normals has `θ² · Ns > 1` (`Ns` capped at 1000; a highlight is about `1/√Ns`
//! radians wide, so it cannot hide between samples); and splitting stops when the
//! longest projected edge is at most [`MIN_EDGE_PX`] or after [`MAX_DEPTH`] levels,
//! where per-pixel output could not show more.
//!
//! Pieces meeting at a T-junction may disagree along it by up to twice the tolerance;
//! each of them is within the tolerance of Phong.

use glam::DVec3;
use limn_scene::Rgb;

/// Splitting stops when the longest projected edge is at most this many pixels.
pub const MIN_EDGE_PX: f64 = 0.125;

/// Splitting stops after this many levels (4^12 pieces at most per triangle).
pub const MAX_DEPTH: u32 = 12;

/// The default tolerance: one 8-bit step per channel.
pub const DEFAULT_TOLERANCE: f64 = 1.0 / 255.0;

/// A triangle corner: where it is, where it projects, its Phong colour.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Corner {
    /// World position.
    pub world: DVec3,
    /// Pixel position.
    pub screen: [f64; 2],
    /// Colour by per-point shading.
    pub color: Rgb,
}

/// One Gouraud triangle of the result.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GouraudTriangle {
    /// The corners.
    pub corners: [Corner; 3],
    /// Per edge `i` (corner `i` → corner `i + 1`): does it lie on an edge of the
    /// triangle given to [`subdivide`] that was flagged?
    pub edges: [bool; 3],
}

/// What the subdivision needs to know about the surface.
pub struct Surface<'a> {
    /// Per-point shading at a world point of the face.
    pub shade: &'a dyn Fn(DVec3) -> Rgb,
    /// The interpolated unit normal at a world point (for the highlight guard).
    pub normal: &'a dyn Fn(DVec3) -> DVec3,
    /// World point to pixel position.
    pub project: &'a dyn Fn(DVec3) -> [f64; 2],
    /// The material's specular exponent when it has a highlight, else 0 (no guard).
    pub highlight: f64,
    /// Largest accepted difference per channel, > 0.
    pub tolerance: f64,
}

impl Surface<'_> {
    /// A corner at world point `p`.
    pub fn corner(&self, p: DVec3) -> Corner {
        Corner {
            world: p,
            screen: (self.project)(p),
            color: (self.shade)(p),
        }
    }
}

/// Splits the triangle `t` (corners with their Phong colours) into Gouraud triangles
/// within the surface's tolerance (see the module docs), appended to `out` so that
/// they tile `t`. `edges` flags `t`'s edges; the pieces' edges along them inherit the
/// flag, inner edges are unflagged.
pub fn subdivide(
    s: &Surface<'_>,
    t: [Corner; 3],
    edges: [bool; 3],
    out: &mut Vec<GouraudTriangle>,
) {
    refine(s, t, edges, 0, out);
}

fn refine(
    s: &Surface<'_>,
    t: [Corner; 3],
    edges: [bool; 3],
    depth: u32,
    out: &mut Vec<GouraudTriangle>,
) {
    let longest = (0..3)
        .map(|i| dist(t[i].screen, t[(i + 1) % 3].screen))
        .fold(0.0, f64::max);
    let can_split = depth < MAX_DEPTH && longest > MIN_EDGE_PX && longest.is_finite();
    if !can_split {
        out.push(GouraudTriangle { corners: t, edges });
        return;
    }
    let mids = [0, 1, 2].map(|i| s.corner((t[i].world + t[(i + 1) % 3].world) * 0.5));
    if !too_curved(s, &t) && within(s, &t, &mids) {
        out.push(GouraudTriangle { corners: t, edges });
        return;
    }
    let [a, b, c] = t;
    let [ab, bc, ca] = mids;
    refine(s, [a, ab, ca], [edges[0], false, edges[2]], depth + 1, out);
    refine(s, [ab, b, bc], [edges[0], edges[1], false], depth + 1, out);
    refine(s, [ca, bc, c], [false, edges[1], edges[2]], depth + 1, out);
    refine(s, [ab, bc, ca], [false; 3], depth + 1, out);
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// The highlight guard: some pair of corner normals `θ` apart with `θ² · Ns > 1`.
fn too_curved(s: &Surface<'_>, t: &[Corner; 3]) -> bool {
    if s.highlight <= 0.0 {
        return false;
    }
    let n = t.map(|c| (s.normal)(c.world));
    (0..3).any(|i| {
        let cos = n[i].dot(n[(i + 1) % 3]).clamp(-1.0, 1.0);
        let theta = cos.acos();
        theta * theta * s.highlight > 1.0
    })
}

/// Is the screen-linear interpolation of the corner colours within the tolerance of
/// Phong at the edge midpoints `mids` and four inner points?
fn within(s: &Surface<'_>, t: &[Corner; 3], mids: &[Corner; 3]) -> bool {
    let Some(bary) = Barycentric::new(t) else {
        return true; // edge-on: nothing of it shows
    };
    let close = |c: &Corner| {
        let w = bary.at(c.screen);
        (0..3).all(|k| {
            let g = w[0] * t[0].color[k] + w[1] * t[1].color[k] + w[2] * t[2].color[k];
            (g - c.color[k]).abs() <= 0.5 * s.tolerance
        })
    };
    if !mids.iter().all(close) {
        return false;
    }
    let w = t.map(|c| c.world);
    INNER
        .iter()
        .all(|b| close(&s.corner(w[0] * b[0] + w[1] * b[1] + w[2] * b[2])))
}

/// The sample points besides the edge midpoints (barycentric): the centroid and the
/// points half-way between it and the corners.
const INNER: [[f64; 3]; 4] = [
    [1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0],
    [2.0 / 3.0, 1.0 / 6.0, 1.0 / 6.0],
    [1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0],
    [1.0 / 6.0, 1.0 / 6.0, 2.0 / 3.0],
];

/// Screen-space barycentric coordinates in one triangle.
struct Barycentric {
    origin: [f64; 2],
    inv: [[f64; 2]; 2],
}

impl Barycentric {
    fn new(t: &[Corner; 3]) -> Option<Barycentric> {
        let o = t[0].screen;
        let (ux, uy) = (t[1].screen[0] - o[0], t[1].screen[1] - o[1]);
        let (vx, vy) = (t[2].screen[0] - o[0], t[2].screen[1] - o[1]);
        let det = ux * vy - uy * vx;
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        Some(Barycentric {
            origin: o,
            inv: [[vy / det, -vx / det], [-uy / det, ux / det]],
        })
    }

    fn at(&self, p: [f64; 2]) -> [f64; 3] {
        let (dx, dy) = (p[0] - self.origin[0], p[1] - self.origin[1]);
        let b1 = self.inv[0][0] * dx + self.inv[0][1] * dy;
        let b2 = self.inv[1][0] * dx + self.inv[1][1] * dy;
        [1.0 - b1 - b2, b1, b2]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A plane z = 0 seen by an orthographic projection scaled by 100 px per unit,
    /// with a "highlight" colour peaking at the origin.
    fn run(tolerance: f64, highlight: f64) -> Vec<GouraudTriangle> {
        let shade = |p: DVec3| {
            let v = (-(p.x * p.x + p.y * p.y) * 20.0).exp();
            [v, 0.5 * v, 0.25]
        };
        let normal = |p: DVec3| DVec3::new(p.x, p.y, 1.0).normalize();
        let project = |p: DVec3| [p.x * 100.0, p.y * 100.0];
        let s = Surface {
            shade: &shade,
            normal: &normal,
            project: &project,
            highlight,
            tolerance,
        };
        let t = [
            DVec3::new(-1.0, -1.0, 0.0),
            DVec3::new(2.0, -1.0, 0.0),
            DVec3::new(-1.0, 2.0, 0.0),
        ]
        .map(|p| s.corner(p));
        let mut out = Vec::new();
        subdivide(&s, t, [true, false, true], &mut out);
        out
    }

    #[test]
    fn pieces_tile_the_triangle_and_keep_edge_flags() {
        let out = run(DEFAULT_TOLERANCE, 0.0);
        assert!(out.len() > 4);
        let area = |t: &GouraudTriangle| {
            let [a, b, c] = t.corners.map(|c| c.world);
            (b - a).cross(c - a).length() / 2.0
        };
        let total: f64 = out.iter().map(area).sum();
        assert!((total - 4.5).abs() < 1e-9, "{total}");
        // Flagged edges survive only along the outer edges 0 (y = -1) and 2 (x = -1).
        for t in &out {
            for i in 0..3 {
                let (a, b) = (t.corners[i].world, t.corners[(i + 1) % 3].world);
                let on0 = a.y == -1.0 && b.y == -1.0;
                let on2 = a.x == -1.0 && b.x == -1.0;
                assert_eq!(t.edges[i], on0 || on2, "{a} {b}");
            }
        }
    }

    #[test]
    fn subdivision_is_adaptive_where_the_colour_bends() {
        let out = run(DEFAULT_TOLERANCE, 0.0);
        let small_near = out
            .iter()
            .filter(|t| t.corners.iter().all(|c| c.world.length() < 0.5))
            .count();
        let small_far = out
            .iter()
            .filter(|t| t.corners.iter().all(|c| c.world.x > 1.0 || c.world.y > 1.0))
            .count();
        assert!(
            small_near > 4 * small_far.max(1),
            "{small_near} {small_far}"
        );
        // A looser tolerance needs fewer pieces.
        assert!(run(0.05, 0.0).len() < out.len());
    }

    #[test]
    fn highlight_guard_splits_curved_triangles() {
        // With a huge exponent every triangle whose normals differ visibly is split,
        // even where the colour is flat (tolerance 2 accepts any colour).
        assert_eq!(run(2.0, 0.0).len(), 1);
        assert!(run(2.0, 1000.0).len() > 16);
    }
}
