//! PNG, rasterised with tiny-skia.
//!
//! The image is W × H pixels, y down, RGBA 8 bits per channel; pixels stay transparent
//! where nothing is painted unless the picture has a background. Paths are filled with the
//! non-zero rule and anti-aliased (unless [`PngOptions::anti_alias`] is off); colours are
//! 8-bit `round(c · 255)` and blending is tiny-skia's source-over on premultiplied values,
//! with no gamma conversion.
//!
//! **Seams**: a run of fragments of one face (see the module docs) is filled as one path,
//! so the rasteriser computes coverage of their union and the cuts between fragments of a
//! face leave no anti-aliasing seam. Edges between *different* faces keep the usual
//! coverage-based blending, as in any anti-aliased vector renderer.
//!
//! **Gouraud** fragments are interpolated per pixel: the run's coverage is rasterised into
//! a mask (anti-aliased like any fill), and each covered pixel gets the colour
//! interpolated linearly at its centre in the fan triangle that contains the centre; pixels
//! on the rim, whose centre lies in no triangle, take the colour of the nearest triangle's
//! barycentric coordinates clamped to it. Opacity is applied on top, source-over.
//!
//! **Textured** fragments are filled the same way (coverage from the run's mask), each
//! pixel's colour being the fill (a smoothly lit one's vertex colours interpolated as
//! above) times the texture sampled at the texture coordinates of
//! the pixel's centre under the fragment's projective map (perspective-correct, bilinear,
//! repeating). With supersampling, each sample is textured and the samples averaged.
//! A texture's alpha, where drawn ([`limn_scene::TextureAlpha`]), multiplies the
//! opacity at each sample: a cut-out's sample shows its colour wholly when the texel
//! holding it shows, else nothing; a blended texture's alpha is sampled bilinearly on
//! premultiplied texels.

use std::borrow::Cow;
use std::cell::RefCell;
use std::io::Write;

use tiny_skia::{
    Color, FillRule, LineCap, LineJoin, Mask, Paint, Path, PathBuilder, Pixmap, Stroke, Transform,
};

use super::marks::{circle_beziers, glyph_rects, paint_mark, scaled, MarkSink};
use super::number::{channel_u8, rgb_u8};
use super::runs::{check, reversals, walk_with_marks, Frag, Runs};
use super::{wide_color, Label, PaintError, PaintStats, Painter, Picture};

/// Options for [`PngPainter`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PngOptions {
    /// Anti-alias fills and outlines. Default on.
    pub anti_alias: bool,
    /// The largest `W · H` accepted; larger pictures fail with [`PaintError::Size`].
    /// Default 2^28 (a gigabyte of RGBA).
    pub max_pixels: u64,
    /// With anti-aliasing on: render at this many samples per pixel side without
    /// anti-aliasing and average down. Polygons that share an edge then cover every sample
    /// exactly once, so meshes show no hairline seams (which per-path anti-aliasing
    /// leaves where the background shows through both edge pixels). Reduced
    /// automatically so the supersampled buffer stays within 2^25 pixels; 1 = plain
    /// per-path anti-aliasing. Default 4.
    pub supersample: u32,
}

impl Default for PngOptions {
    fn default() -> Self {
        PngOptions {
            anti_alias: true,
            max_pixels: 1 << 28,
            supersample: 4,
        }
    }
}

/// Rasterises to PNG.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct PngPainter {
    /// Rasterisation options.
    pub options: PngOptions,
}

impl PngPainter {
    /// A painter with the given options.
    pub fn new(options: PngOptions) -> Self {
        PngPainter { options }
    }

    /// Rasterises `picture` without encoding it.
    pub fn render(&self, picture: &Picture) -> Result<(Pixmap, PaintStats), PaintError> {
        let px = u64::from(picture.width) * u64::from(picture.height);
        let mut s = self.options.supersample.max(1);
        while s > 1 && px * u64::from(s) * u64::from(s) > 1 << 25 {
            s -= 1;
        }
        if !self.options.anti_alias || s == 1 || px > self.options.max_pixels || px == 0 {
            return self.render_direct(picture, 1);
        }
        let inner = PngPainter::new(PngOptions {
            anti_alias: false,
            max_pixels: u64::MAX,
            supersample: 1,
        });
        let (pixmap, stats) = inner.render_direct(picture, s)?;
        let small =
            downsample(&pixmap, s, picture.width, picture.height).ok_or(PaintError::Size {
                width: picture.width,
                height: picture.height,
                reason: "the pixel buffer cannot be allocated",
            })?;
        Ok((small, stats))
    }

    /// Rasterises the picture `scale` times larger than its own size (its fragments and
    /// marks scaled as they are drawn: a copy of a large picture scaled was as large as
    /// the picture).
    fn render_direct(
        &self,
        picture: &Picture,
        scale: u32,
    ) -> Result<(Pixmap, PaintStats), PaintError> {
        let checked = check(picture)?;
        let checked = if scale == 1 {
            checked
        } else {
            checked.scaled(picture, scale)
        };
        let k = f64::from(scale);
        let (width, height) = (picture.width * scale, picture.height * scale);
        if u64::from(width) * u64::from(height) > self.options.max_pixels {
            return Err(PaintError::Size {
                width,
                height,
                reason: "more pixels than PNG output allows (268,435,456 by default)",
            });
        }
        let mut pixmap = Pixmap::new(width, height).ok_or(PaintError::Size {
            width,
            height,
            reason: "the pixel buffer cannot be allocated",
        })?;
        if let Some(bg) = picture.background {
            let [r, g, b] = rgb_u8([bg[0], bg[1], bg[2]]);
            pixmap.fill(Color::from_rgba8(r, g, b, channel_u8(bg[3])));
        }
        let aa = self.options.anti_alias;
        let outline = checked.outline.map(|o| {
            let [r, g, b] = rgb_u8([o.color[0], o.color[1], o.color[2]]);
            let mut paint = Paint::default();
            paint.set_color_rgba8(r, g, b, channel_u8(o.color[3]));
            paint.anti_alias = aa;
            let stroke = Stroke {
                width: o.width as f32,
                line_cap: LineCap::Round,
                line_join: LineJoin::Round,
                ..Stroke::default()
            };
            (paint, stroke)
        });

        let stats = RefCell::new(PaintStats::default());
        let pixmap = RefCell::new(pixmap);
        let mut builder = Some(PathBuilder::new());
        let on_run = |run: &[Frag<'_>], style: &Style| {
            let mut pixmap = pixmap.borrow_mut();
            let mut stats = stats.borrow_mut();
            let mut pb = builder.take().unwrap_or_default();
            for (f, reverse) in run.iter().zip(reversals(run)) {
                for (k, p) in f.oriented(reverse).enumerate() {
                    if k == 0 {
                        pb.move_to(p[0] as f32, p[1] as f32);
                    } else {
                        pb.line_to(p[0] as f32, p[1] as f32);
                    }
                }
                pb.close();
            }
            stats.paths += 1;
            if let Some(path) = pb.finish() {
                match *style {
                    Style::Flat([r, g, b], a) => {
                        let mut paint = Paint::default();
                        paint.set_color_rgba8(r, g, b, a);
                        paint.anti_alias = aa;
                        pixmap.fill_path(
                            &path,
                            &paint,
                            FillRule::Winding,
                            Transform::identity(),
                            None,
                        );
                    }
                    Style::Gouraud(a) => gouraud(&mut pixmap, run, &path, a, aa),
                    Style::Textured(_, a) => {
                        textured(&mut pixmap, run, &path, a, aa, &picture.textures, k)
                    }
                }
                builder = Some(path.clear());
            }
            if let Some((paint, stroke)) = &outline {
                if run.iter().any(Frag::has_outline) {
                    let mut pb = builder.take().unwrap_or_default();
                    for f in run {
                        let n = f.points.len();
                        f.polylines(|start, edges, closed| {
                            let last = if closed { edges - 1 } else { edges };
                            for k in 0..=last {
                                let p = f.points[(start + k) % n];
                                if k == 0 {
                                    pb.move_to(p[0] as f32, p[1] as f32);
                                } else {
                                    pb.line_to(p[0] as f32, p[1] as f32);
                                }
                            }
                            if closed {
                                pb.close();
                            }
                        });
                    }
                    if let Some(path) = pb.finish() {
                        pixmap.stroke_path(&path, paint, stroke, Transform::identity(), None);
                        builder = Some(path.clear());
                    }
                    stats.strokes += 1;
                }
            }
            Ok(())
        };
        let on_mark = |m: &super::Mark| {
            let mut pixmap = pixmap.borrow_mut();
            let mut sink = PngMarks {
                pixmap: &mut pixmap,
                aa,
            };
            let m = if scale == 1 {
                Cow::Borrowed(m)
            } else {
                Cow::Owned(scaled(m, k))
            };
            paint_mark(&m, &checked.guard, &mut sink, &mut stats.borrow_mut())
        };
        let counts = walk_with_marks(
            picture,
            &checked.guard,
            Runs::Consecutive,
            style_key,
            on_run,
            on_mark,
        )?;
        let mut stats = stats.into_inner();
        stats.skipped += counts.skipped;
        stats.clipped += counts.clipped;
        Ok((pixmap.into_inner(), stats))
    }
}

/// Averages `s`×`s` blocks of premultiplied RGBA (which keeps every channel at most its
/// alpha) into a `w`×`h` pixmap.
fn downsample(big: &Pixmap, s: u32, w: u32, h: u32) -> Option<Pixmap> {
    let src = big.data();
    let bw = big.width() as usize;
    let (s, w, h) = (s as usize, w as usize, h as usize);
    let n = (s * s) as u32;
    let mut out = vec![0u8; w * h * 4];
    for y in 0..h {
        for x in 0..w {
            let mut acc = [0u32; 4];
            for dy in 0..s {
                let row = (y * s + dy) * bw;
                for dx in 0..s {
                    let i = (row + x * s + dx) * 4;
                    for (a, v) in acc.iter_mut().zip(&src[i..i + 4]) {
                        *a += u32::from(*v);
                    }
                }
            }
            let o = (y * w + x) * 4;
            for (d, a) in out[o..o + 4].iter_mut().zip(acc) {
                *d = ((a + n / 2) / n) as u8;
            }
        }
    }
    Pixmap::from_vec(out, tiny_skia::IntSize::from_wh(w as u32, h as u32)?)
}

impl Painter for PngPainter {
    fn paint(&self, picture: &Picture, out: &mut dyn Write) -> Result<PaintStats, PaintError> {
        let (pixmap, mut stats) = self.render(picture)?;
        let png = pixmap
            .encode_png()
            .map_err(|e| PaintError::Png(e.to_string()))?;
        out.write_all(&png)?;
        out.flush()?;
        stats.bytes = png.len() as u64;
        Ok(stats)
    }
}

/// What makes two fragments paint alike in PNG.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Style {
    Flat([u8; 3], u8),
    Gouraud(u8),
    /// Texture index and opacity.
    Textured(u32, u8),
}

fn style_key(f: &Frag<'_>) -> Style {
    let a = channel_u8(f.alpha());
    if let Some(t) = &f.src.texture {
        return Style::Textured(t.texture, a);
    }
    match f.colors {
        Some(_) => Style::Gouraud(a),
        None => Style::Flat(rgb_u8(f.flat_rgb()), a),
    }
}

/// A fan triangle prepared for barycentric interpolation.
struct Tri {
    p: [[f64; 2]; 3],
    c: [[f64; 3]; 3],
    inv_det: f64,
}

/// Fills `path` (the run's union) with colours interpolated per pixel.
fn gouraud(pixmap: &mut Pixmap, run: &[Frag<'_>], path: &Path, alpha: u8, aa: bool) {
    let (w, h) = (pixmap.width(), pixmap.height());
    let r = path.bounds();
    let x0 = (r.left().floor().max(0.0) as u32).min(w);
    let y0 = (r.top().floor().max(0.0) as u32).min(h);
    let x1 = (r.right().ceil().max(0.0) as u32).min(w);
    let y1 = (r.bottom().ceil().max(0.0) as u32).min(h);
    if x0 >= x1 || y0 >= y1 {
        return;
    }
    let (bw, bh) = ((x1 - x0) as usize, (y1 - y0) as usize);
    let Some(mut mask) = Mask::new(bw as u32, bh as u32) else {
        return;
    };
    let shift = Transform::from_translate(-(x0 as f32), -(y0 as f32));
    mask.fill_path(path, FillRule::Winding, aa, shift);

    let mut tris = Vec::new();
    let mut mean = [0.0; 3];
    let mut count = 0.0_f64;
    for f in run {
        let Some(colors) = &f.colors else { continue };
        let rgb = |i: usize| {
            let c = wide_color(colors[i]);
            [c[0], c[1], c[2]].map(|v| v.clamp(0.0, 1.0))
        };
        for i in 0..f.points.len() {
            let c = rgb(i);
            for k in 0..3 {
                mean[k] += c[k];
            }
            count += 1.0;
        }
        for i in 1..f.points.len() - 1 {
            let p = [f.points[0], f.points[i], f.points[i + 1]];
            let det = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1])
                - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
            if det != 0.0 && det.is_finite() {
                tris.push(Tri {
                    p,
                    c: [rgb(0), rgb(i), rgb(i + 1)],
                    inv_det: 1.0 / det,
                });
            }
        }
    }
    let mean = mean.map(|v| v / count.max(1.0));
    // Pixel ranges each triangle can colour: its bounds grown by a pixel for the rim.
    let ranges: Vec<[u32; 4]> = tris
        .iter()
        .map(|t| {
            let lo = |k: usize| t.p.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min);
            let hi = |k: usize| t.p.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max);
            let clamp = |v: f64, a: u32, b: u32| v.max(f64::from(a)).min(f64::from(b)) as u32;
            [
                clamp(lo(0).floor() - 1.0, x0, x1),
                clamp(hi(0).ceil() + 1.0, x0, x1),
                clamp(lo(1).floor() - 1.0, y0, y1),
                clamp(hi(1).ceil() + 1.0, y0, y1),
            ]
        })
        .collect();

    // One row at a time, so memory stays proportional to the run's width.
    let alpha = f64::from(alpha) / 255.0;
    let stride = w as usize * 4;
    let coverage = mask.data();
    let data = pixmap.data_mut();
    let mut color = vec![mean; bw];
    let mut best = vec![f64::NEG_INFINITY; bw];
    for j in y0..y1 {
        color.fill(mean);
        best.fill(f64::NEG_INFINITY);
        let py = f64::from(j) + 0.5;
        for (t, &[tx0, tx1, ty0, ty1]) in tris.iter().zip(&ranges) {
            if j < ty0 || j >= ty1 {
                continue;
            }
            let [a, b, c] = t.p;
            for i in tx0..tx1 {
                let px = f64::from(i) + 0.5;
                let l1 = ((px - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (py - a[1])) * t.inv_det;
                let l2 = ((b[0] - a[0]) * (py - a[1]) - (px - a[0]) * (b[1] - a[1])) * t.inv_det;
                let l0 = 1.0 - l1 - l2;
                let score = l0.min(l1).min(l2);
                let idx = (i - x0) as usize;
                if score > best[idx] {
                    best[idx] = score;
                    let l = [l0.max(0.0), l1.max(0.0), l2.max(0.0)];
                    let sum = l[0] + l[1] + l[2];
                    color[idx] = [0, 1, 2]
                        .map(|k| (l[0] * t.c[0][k] + l[1] * t.c[1][k] + l[2] * t.c[2][k]) / sum);
                }
            }
        }
        let row = (j - y0) as usize * bw;
        for (i, c) in color.iter().enumerate() {
            let m = coverage[row + i];
            if m == 0 {
                continue;
            }
            let a = alpha * f64::from(m) / 255.0;
            let at = j as usize * stride + (x0 as usize + i) * 4;
            let px = &mut data[at..at + 4];
            let out_a = a * 255.0 + f64::from(px[3]) * (1.0 - a);
            let out_a8 = out_a.round().clamp(0.0, 255.0) as u8;
            for k in 0..3 {
                let v = c[k] * a * 255.0 + f64::from(px[k]) * (1.0 - a);
                px[k] = (v.round().clamp(0.0, 255.0) as u8).min(out_a8);
            }
            px[3] = out_a8;
        }
    }
}

/// Fills `path` (the run's union) with each fragment's fill (or its vertex colours
/// interpolated in its fan triangle) times its texture, sampled
/// per pixel centre through the fragment's map; a pixel whose centre lies in no fragment
/// (the anti-aliased rim) takes the fragment whose fan triangle is nearest.
fn textured(
    pixmap: &mut Pixmap,
    run: &[Frag<'_>],
    path: &Path,
    alpha: u8,
    aa: bool,
    textures: &[std::sync::Arc<limn_scene::Texture>],
    scale: f64,
) {
    // Each fragment's map for the page as drawn (`scale` times the picture's).
    let maps: Vec<Option<super::TextureMap>> = run
        .iter()
        .map(|f| {
            f.src
                .texture
                .as_deref()
                .map(|m| if scale == 1.0 { *m } else { m.scaled(scale) })
        })
        .collect();
    let (w, h) = (pixmap.width(), pixmap.height());
    let r = path.bounds();
    let x0 = (r.left().floor().max(0.0) as u32).min(w);
    let y0 = (r.top().floor().max(0.0) as u32).min(h);
    let x1 = (r.right().ceil().max(0.0) as u32).min(w);
    let y1 = (r.bottom().ceil().max(0.0) as u32).min(h);
    if x0 >= x1 || y0 >= y1 {
        return;
    }
    let (bw, bh) = ((x1 - x0) as usize, (y1 - y0) as usize);
    let Some(mut mask) = Mask::new(bw as u32, bh as u32) else {
        return;
    };
    let shift = Transform::from_translate(-(x0 as f32), -(y0 as f32));
    mask.fill_path(path, FillRule::Winding, aa, shift);
    // Fan triangles of every fragment, each with its fragment's index and its second
    // corner's.
    let mut tris: Vec<([[f64; 2]; 3], f64, usize, usize)> = Vec::new();
    for (k, f) in run.iter().enumerate() {
        for i in 1..f.points.len() - 1 {
            let p = [f.points[0], f.points[i], f.points[i + 1]];
            let det = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1])
                - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
            if det != 0.0 && det.is_finite() {
                tris.push((p, 1.0 / det, k, i));
            }
        }
    }
    let alpha = f64::from(alpha) / 255.0;
    let stride = w as usize * 4;
    let coverage = mask.data();
    let data = pixmap.data_mut();
    for j in y0..y1 {
        let py = f64::from(j) + 0.5;
        for i in x0..x1 {
            let m = coverage[(j - y0) as usize * bw + (i - x0) as usize];
            if m == 0 {
                continue;
            }
            let px = f64::from(i) + 0.5;
            // The fragment whose fan triangle holds the centre (or comes nearest).
            let mut best = (f64::NEG_INFINITY, 0usize, 1usize, [1.0, 0.0, 0.0]);
            for (t, inv_det, k, corner) in &tris {
                let [a, b, c] = *t;
                let l1 = ((px - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (py - a[1])) * inv_det;
                let l2 = ((b[0] - a[0]) * (py - a[1]) - (px - a[0]) * (b[1] - a[1])) * inv_det;
                let score = (1.0 - l1 - l2).min(l1).min(l2);
                if score > best.0 {
                    best = (score, *k, *corner, [1.0 - l1 - l2, l1, l2]);
                }
                if score >= 0.0 {
                    break;
                }
            }
            let f = &run[best.1];
            // The texture's alpha (1 unless drawn) multiplies the opacity.
            let (c, ta) = crate::texture_page::textured_colour(
                f.src.fill,
                f.colors.as_deref(),
                best.2,
                best.3,
                maps[best.1].as_ref(),
                textures,
                [px, py],
            );
            if ta <= 0.0 {
                continue;
            }
            let a = alpha * f64::from(m) / 255.0 * ta;
            let at = j as usize * stride + i as usize * 4;
            let px = &mut data[at..at + 4];
            let out_a = a * 255.0 + f64::from(px[3]) * (1.0 - a);
            let out_a8 = out_a.round().clamp(0.0, 255.0) as u8;
            for k in 0..3 {
                let v = c[k] * a * 255.0 + f64::from(px[k]) * (1.0 - a);
                px[k] = (v.round().clamp(0.0, 255.0) as u8).min(out_a8);
            }
            px[3] = out_a8;
        }
    }
}

/// Marks rasterised with tiny-skia.
struct PngMarks<'a> {
    pixmap: &'a mut Pixmap,
    aa: bool,
}

impl PngMarks<'_> {
    fn paint(&self, color: [f64; 4]) -> Paint<'static> {
        let [r, g, b] = rgb_u8([color[0], color[1], color[2]]);
        let mut paint = Paint::default();
        paint.set_color_rgba8(r, g, b, channel_u8(color[3]));
        paint.anti_alias = self.aa;
        paint
    }
}

impl MarkSink for PngMarks<'_> {
    fn polylines(
        &mut self,
        lines: &[Vec<[f64; 2]>],
        closed: bool,
        color: [f64; 4],
        width: f64,
        dash: &[f64],
        offset: f64,
    ) -> Result<(), PaintError> {
        let mut pb = PathBuilder::new();
        for line in lines {
            for (k, p) in line.iter().enumerate() {
                if k == 0 {
                    pb.move_to(p[0] as f32, p[1] as f32);
                } else {
                    pb.line_to(p[0] as f32, p[1] as f32);
                }
            }
            if closed {
                pb.close();
            }
        }
        let Some(path) = pb.finish() else {
            return Ok(());
        };
        let stroke = Stroke {
            width: width as f32,
            line_cap: LineCap::Butt,
            line_join: LineJoin::Round,
            dash: (!dash.is_empty())
                .then(|| {
                    tiny_skia::StrokeDash::new(
                        dash.iter().map(|&d| d as f32).collect(),
                        offset as f32,
                    )
                })
                .flatten(),
            ..Stroke::default()
        };
        let paint = self.paint(color);
        self.pixmap
            .stroke_path(&path, &paint, &stroke, Transform::identity(), None);
        Ok(())
    }

    fn circle(
        &mut self,
        c: [f64; 2],
        r: f64,
        color: [f64; 4],
        stroke: Option<f64>,
    ) -> Result<(), PaintError> {
        let mut pb = PathBuilder::new();
        let (start, quarters) = circle_beziers(c, r);
        pb.move_to(start[0] as f32, start[1] as f32);
        for [a, b, e] in quarters {
            pb.cubic_to(
                a[0] as f32,
                a[1] as f32,
                b[0] as f32,
                b[1] as f32,
                e[0] as f32,
                e[1] as f32,
            );
        }
        pb.close();
        let Some(path) = pb.finish() else {
            return Ok(());
        };
        let paint = self.paint(color);
        match stroke {
            None => self.pixmap.fill_path(
                &path,
                &paint,
                FillRule::Winding,
                Transform::identity(),
                None,
            ),
            Some(w) => {
                let s = Stroke {
                    width: w as f32,
                    ..Stroke::default()
                };
                self.pixmap
                    .stroke_path(&path, &paint, &s, Transform::identity(), None)
            }
        }
        Ok(())
    }

    fn triangle(&mut self, points: [[f64; 2]; 3], color: [f64; 4]) -> Result<(), PaintError> {
        let mut pb = PathBuilder::new();
        pb.move_to(points[0][0] as f32, points[0][1] as f32);
        pb.line_to(points[1][0] as f32, points[1][1] as f32);
        pb.line_to(points[2][0] as f32, points[2][1] as f32);
        pb.close();
        if let Some(path) = pb.finish() {
            let paint = self.paint(color);
            self.pixmap.fill_path(
                &path,
                &paint,
                FillRule::Winding,
                Transform::identity(),
                None,
            );
        }
        Ok(())
    }

    fn text(&mut self, origin: [f64; 2], label: &Label) -> Result<bool, PaintError> {
        let mut pb = PathBuilder::new();
        for [x, y, w, h] in glyph_rects(origin, label) {
            if let Some(r) = tiny_skia::Rect::from_xywh(x as f32, y as f32, w as f32, h as f32) {
                pb.push_rect(r);
            }
        }
        if let Some(path) = pb.finish() {
            let paint = self.paint(label.color);
            self.pixmap.fill_path(
                &path,
                &paint,
                FillRule::Winding,
                Transform::identity(),
                None,
            );
        }
        Ok(false)
    }
}
