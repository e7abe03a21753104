//! Line drawing: DDA and Bresenham, and depth-tested wireframes.
//!
//! Both algorithms draw one pixel per step along the major axis (the axis of the larger
//! extent), so lines are 8-connected. For a line between pixel centres the minor
//! coordinate is the exact line's value rounded to the nearest pixel, ties (the line
//! exactly half-way between two pixel centres) going to the larger coordinate, which
//! makes the result independent of the drawing direction. [`bresenham`] computes that
//! with integers only (the midpoint decision variable); [`dda`] steps the minor
//! coordinate in floating point, so the two agree except where the line passes
//! exactly half-way and the float sum lands on either side.

use crate::image::{IdImage, NO_FACE};
use crate::setup::{prepare, Collect, Culling, Frame, ScreenVert};
use crate::zbuf::zbuffer;
use crate::{RenderOptions, ZError};
use limn_scene::{Camera, Scene};

/// Which line algorithm to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LineAlgorithm {
    /// Digital differential analyser (floating-point steps).
    Dda,
    /// Bresenham's midpoint algorithm (integer steps).
    #[default]
    Bresenham,
}

/// Calls `plot(x, y)` for every pixel of the line from pixel `(x0, y0)` to pixel
/// `(x1, y1)`, both included, in order from the first: `max(|dx|, |dy|) + 1` pixels.
/// Coordinates are clamped to ±2⁵⁹ (so the integer error term cannot overflow).
pub fn bresenham(x0: i64, y0: i64, x1: i64, y1: i64, mut plot: impl FnMut(i64, i64)) {
    const LIM: i64 = 1 << 59;
    let (x0, y0, x1, y1) = (
        x0.clamp(-LIM, LIM),
        y0.clamp(-LIM, LIM),
        x1.clamp(-LIM, LIM),
        y1.clamp(-LIM, LIM),
    );
    let (dx, dy) = (x1 - x0, y1 - y0);
    let steep = dy.abs() > dx.abs();
    // Work in (major, minor) coordinates.
    let (a0, b0, da, db) = if steep {
        (y0, x0, dy, dx)
    } else {
        (x0, y0, dx, dy)
    };
    let n = da.abs();
    let sa = if da >= 0 { 1 } else { -1 };
    // minor(k) = b0 + floor((2·k·db + n) / (2n)); r is the remainder, in [0, 2n).
    let two_n = 2 * n.max(1);
    let (mut q, mut r) = (0i64, n);
    let mut a = a0;
    for k in 0..=n {
        let b = b0 + q;
        if steep {
            plot(b, a);
        } else {
            plot(a, b);
        }
        if k == n {
            break;
        }
        a += sa;
        r += 2 * db;
        if r >= two_n {
            r -= two_n;
            q += 1;
        } else if r < 0 {
            r += two_n;
            q -= 1;
        }
    }
}

/// Calls `plot(x, y)` for the pixels of the line from `(x0, y0)` to `(x1, y1)` in
/// continuous pixel coordinates: at each pixel centre along the major axis, from the
/// pixel holding the first point to the pixel holding the last, the pixel containing
/// the line's point (the minor coordinate is stepped incrementally). Non-finite input
/// draws nothing; at most `max_steps + 1` pixels are drawn.
pub fn dda(x0: f64, y0: f64, x1: f64, y1: f64, max_steps: u64, mut plot: impl FnMut(i64, i64)) {
    if ![x0, y0, x1, y1].iter().all(|v| v.is_finite()) {
        return;
    }
    let (dx, dy) = (x1 - x0, y1 - y0);
    let steep = dy.abs() > dx.abs();
    let (a0, b0, a1, da, db) = if steep {
        (y0, x0, y1, dy, dx)
    } else {
        (x0, y0, x1, dx, dy)
    };
    let m = if da == 0.0 { 0.0 } else { db / da };
    let (i0, i1) = (a0.floor(), a1.floor());
    let step = if i1 >= i0 { 1.0 } else { -1.0 };
    let n = ((i1 - i0).abs() as u64).min(max_steps);
    let mut b = b0 + (i0 + 0.5 - a0) * m;
    let mut a = i0;
    for _ in 0..=n {
        let (pa, pb) = (a as i64, b.floor() as i64);
        if steep {
            plot(pb, pa);
        } else {
            plot(pa, pb);
        }
        a += step;
        b += step * m;
    }
}

/// Options of [`wireframe`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineOptions {
    /// Line algorithm (default Bresenham).
    pub algorithm: LineAlgorithm,
    /// Draw only the visible parts of edges (default `true`); `false` draws every edge.
    pub hidden_line: bool,
    /// A line pixel is visible when its window depth is at most the z-buffer's plus this
    /// bias (default 1e-6), or when the pixel shows the line's own face.
    pub depth_bias: f64,
}

impl Default for LineOptions {
    fn default() -> Self {
        LineOptions {
            algorithm: LineAlgorithm::Bresenham,
            hidden_line: true,
            depth_bias: 1e-6,
        }
    }
}

/// Draws the outline edges of every face (clipped at the near plane) as lines, tested
/// against an f64 z-buffer of the same scene when `lines.hidden_line` is set. Returns
/// the face id of the nearest edge drawn at each pixel ([`NO_FACE`] elsewhere).
pub fn wireframe(
    scene: &Scene,
    camera: &Camera,
    opts: &RenderOptions,
    lines: &LineOptions,
) -> Result<IdImage, ZError> {
    let frame = Frame::new(scene, camera, opts)?;
    let (w, h) = (frame.width, frame.height);
    let mut edges = Vec::new();
    prepare(scene, &frame, Culling::of(opts), Collect::Edges(&mut edges));
    let zb = if lines.hidden_line {
        let mut prep = Default::default();
        prepare(
            scene,
            &frame,
            Culling::of(opts),
            Collect::Triangles(&mut prep),
        );
        Some(zbuffer(&prep, w, h, opts.depth))
    } else {
        None
    };
    let mut out = IdImage::new(w, h);
    let mut line_depth = vec![f64::INFINITY; w as usize * h as usize];
    for &(a, b, face) in &edges {
        let Some((a, b)) = clip_to_picture(a, b, w, h) else {
            continue;
        };
        let mut plot = |x: i64, y: i64| {
            if x < 0 || y < 0 || x >= w as i64 || y >= h as i64 {
                return;
            }
            let i = y as usize * w as usize + x as usize;
            let d = depth_along(a, b, x as f64 + 0.5, y as f64 + 0.5);
            if let Some(zb) = &zb {
                let visible = zb.ids[i] == face
                    || zb.ids[i] == NO_FACE
                    || d <= zb.depths[i] + lines.depth_bias;
                if !visible {
                    return;
                }
            }
            if d <= line_depth[i] {
                line_depth[i] = d;
                out.ids[i] = face;
            }
        };
        match lines.algorithm {
            LineAlgorithm::Bresenham => bresenham(
                a.x.floor() as i64,
                a.y.floor() as i64,
                b.x.floor() as i64,
                b.y.floor() as i64,
                &mut plot,
            ),
            LineAlgorithm::Dda => dda(a.x, a.y, b.x, b.y, (w + h) as u64 * 2, &mut plot),
        }
    }
    Ok(out)
}

/// Window depth of the segment at the point nearest to `(x, y)` (depth is affine along
/// a projected line, so this is perspective-correct).
fn depth_along(a: ScreenVert, b: ScreenVert, x: f64, y: f64) -> f64 {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let l2 = dx * dx + dy * dy;
    let s = if l2 > 0.0 {
        (((x - a.x) * dx + (y - a.y) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    a.d + (b.d - a.d) * s
}

/// Clips a segment to the picture widened by one pixel (Liang–Barsky).
fn clip_to_picture(
    a: ScreenVert,
    b: ScreenVert,
    w: u32,
    h: u32,
) -> Option<(ScreenVert, ScreenVert)> {
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    let d = [b.x - a.x, b.y - a.y];
    let p = [a.x, a.y];
    let lim = [w as f64 + 1.0, h as f64 + 1.0];
    for k in 0..2 {
        for (q, r) in [(-d[k], p[k] + 1.0), (d[k], lim[k] - p[k])] {
            if q == 0.0 {
                if r < 0.0 {
                    return None;
                }
            } else {
                let t = r / q;
                if q < 0.0 {
                    t0 = t0.max(t);
                } else {
                    t1 = t1.min(t);
                }
            }
        }
    }
    if t0.is_nan() || t1.is_nan() || t0 > t1 {
        return None;
    }
    let at = |t: f64| ScreenVert {
        x: a.x + (b.x - a.x) * t,
        y: a.y + (b.y - a.y) * t,
        d: a.d + (b.d - a.d) * t,
    };
    Some((at(t0), at(t1)))
}

/// Draws the scene's polylines ([`Scene::lines`]) with `algorithm`, clipped at the near
/// plane and depth-tested against an f64 z-buffer of the faces: a line pixel is visible
/// when no face covers its centre or its window depth is at most the z-buffer's plus
/// `depth_bias` plus the z-buffer's depth change to the neighbouring pixels (a slope-scaled
/// offset, as OpenGL's polygon offset: the line's depth is taken at the point nearest the
/// pixel centre, up to half a pixel away, so a line drawn on a face shows, as in the vector
/// pictures). Returns the
/// index of the line drawn at each pixel ([`NO_FACE`] elsewhere; the nearest line wins).
/// This is the image-space reference for the lines `limn check` compares.
pub fn scene_lines(
    scene: &Scene,
    camera: &Camera,
    opts: &RenderOptions,
    algorithm: LineAlgorithm,
    depth_bias: f64,
) -> Result<IdImage, ZError> {
    let frame = Frame::new(scene, camera, opts)?;
    let (w, h) = (frame.width, frame.height);
    let mut prep = Default::default();
    prepare(
        scene,
        &frame,
        Culling::of(opts),
        Collect::Triangles(&mut prep),
    );
    let zb = zbuffer(&prep, w, h, crate::DepthFormat::F64);
    let mut out = IdImage::new(w, h);
    let mut line_depth = vec![f64::INFINITY; w as usize * h as usize];
    let fwd = camera.forward();
    let dist = |p: glam::DVec3| (p - camera.eye).dot(fwd);
    for (li, line) in scene.lines.iter().enumerate() {
        for seg in line.points.windows(2) {
            // Clip at the near plane (world space, along the view axis).
            let (mut a, mut b) = (seg[0], seg[1]);
            let (da, db) = (dist(a) - frame.near, dist(b) - frame.near);
            if da < 0.0 && db < 0.0 {
                continue;
            }
            if da < 0.0 {
                a = a + (b - a) * (da / (da - db));
            } else if db < 0.0 {
                b = a + (b - a) * (da / (da - db));
            }
            let (sa, sb) = (frame.project(frame.clip(a)), frame.project(frame.clip(b)));
            let Some((sa, sb)) = clip_to_picture(sa, sb, w, h) else {
                continue;
            };
            let mut plot = |x: i64, y: i64| {
                if x < 0 || y < 0 || x >= w as i64 || y >= h as i64 {
                    return;
                }
                let i = y as usize * w as usize + x as usize;
                let d = depth_along(sa, sb, x as f64 + 0.5, y as f64 + 0.5);
                let slope = |j: Option<usize>| {
                    j.filter(|&j| j < zb.depths.len() && zb.ids[j] != NO_FACE)
                        .map_or(0.0, |j| (zb.depths[j] - zb.depths[i]).abs())
                };
                let (xu, yu, wu) = (x as usize, y as usize, w as usize);
                let offset = [
                    (xu > 0).then(|| i - 1),
                    (xu + 1 < wu).then_some(i + 1),
                    (yu > 0).then(|| i - wu),
                    Some(i + wu),
                ]
                .into_iter()
                .map(slope)
                .fold(0.0, f64::max);
                let visible = zb.ids[i] == NO_FACE || d <= zb.depths[i] + depth_bias + offset;
                if visible && d <= line_depth[i] {
                    line_depth[i] = d;
                    out.ids[i] = li as u32;
                }
            };
            match algorithm {
                LineAlgorithm::Bresenham => bresenham(
                    sa.x.floor() as i64,
                    sa.y.floor() as i64,
                    sb.x.floor() as i64,
                    sb.y.floor() as i64,
                    &mut plot,
                ),
                LineAlgorithm::Dda => dda(sa.x, sa.y, sb.x, sb.y, (w + h) as u64 * 2, &mut plot),
            }
        }
    }
    Ok(out)
}
