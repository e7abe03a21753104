//! Warnock's area subdivision.
//!
//! An *area* is a rectangle of pixels; what matters of it is the set of its pixel
//! centres, so triangles are classified against the rectangle spanned by its corner
//! centres with the same exact edge tests the z-buffer uses:
//!
//! * **disjoint**: one edge rejects all four corner centres, or the bounding boxes do
//!   not meet; dropped;
//! * **surrounding**: every edge accepts all four corner centres, so every centre of the
//!   area is covered;
//! * **contained**: the triangle's bounding box lies inside the area;
//! * **intersecting**: anything else.
//!
//! The area is then resolved when (1) no triangle is left: background; (2) a single
//! contained or intersecting triangle is left: it is scan-converted inside the area;
//! (3) a single surrounding triangle is left, or (4) a surrounding triangle is in front
//! of every other triangle's plane at the four corners (compared after quantising to
//! the depth format, so it also wins every pixel between them): the area takes it.
//! Triangles hidden that way behind a surrounding triangle are dropped before
//! subdividing. Otherwise the area is split in four, down to single pixels, where the
//! centre is resolved by depth exactly as in the z-buffer (nearest stored depth, ties to
//! the later triangle).

use crate::image::NO_FACE;
use crate::setup::Prepared;
use crate::span::TriSetup;
use crate::DepthFormat;

/// Ids and depths of a Warnock rendering.
pub(crate) struct Output {
    pub ids: Vec<u32>,
    pub depths: Vec<f64>,
    /// Number of areas examined.
    pub areas: u64,
    /// Bytes of triangle setups and the top-level list.
    pub working_bytes: usize,
}

struct Ctx<'a> {
    tris: Vec<(u32, TriSetup)>,
    prep: &'a Prepared,
    width: u32,
    format: DepthFormat,
    out: Output,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Class {
    Surrounding,
    Contained,
    Intersecting,
}

/// Renders by recursive subdivision.
pub(crate) fn warnock(prep: &Prepared, width: u32, height: u32, format: DepthFormat) -> Output {
    let tris: Vec<(u32, TriSetup)> = prep
        .tris
        .iter()
        .enumerate()
        .filter_map(|(t, tri)| {
            let [a, b, c] = tri.map(|v| prep.verts[v as usize]);
            TriSetup::new(a, b, c, width, height).map(|s| (t as u32, s))
        })
        .collect();
    let n = width as usize * height as usize;
    let mut ctx = Ctx {
        tris,
        prep,
        width,
        format,
        out: Output {
            ids: vec![NO_FACE; n],
            depths: vec![f64::INFINITY; n],
            areas: 0,
            working_bytes: 0,
        },
    };
    let all: Vec<u32> = (0..ctx.tris.len() as u32).collect();
    ctx.out.working_bytes =
        ctx.tris.capacity() * std::mem::size_of::<(u32, TriSetup)>() + all.capacity() * 4;
    ctx.area(0, 0, width, height, &all);
    ctx.out
}

impl Ctx<'_> {
    fn area(&mut self, x0: u32, y0: u32, x1: u32, y1: u32, list: &[u32]) {
        if x0 >= x1 || y0 >= y1 {
            return;
        }
        self.out.areas += 1;
        let (cx0, cy0) = (x0 as f64 + 0.5, y0 as f64 + 0.5);
        let (cx1, cy1) = (x1 as f64 - 0.5, y1 as f64 - 0.5);
        let corners = [(cx0, cy0), (cx1, cy0), (cx0, cy1), (cx1, cy1)];
        let mut live: Vec<(u32, Class)> = Vec::new();
        for &k in list {
            let s = &self.tris[k as usize].1;
            let (bx0, by0, bx1, by1) = s.bbox();
            if bx1 < cx0 || bx0 > cx1 || by1 < cy0 || by0 > cy1 {
                continue;
            }
            let class = match s.classify_corners(corners) {
                Some(false) => continue,
                Some(true) => Class::Surrounding,
                None if bx0 >= x0 as f64
                    && bx1 <= x1 as f64
                    && by0 >= y0 as f64
                    && by1 <= y1 as f64 =>
                {
                    Class::Contained
                }
                None => Class::Intersecting,
            };
            live.push((k, class));
        }
        if live.is_empty() {
            return; // case 1: background (already there)
        }
        if x1 - x0 == 1 && y1 - y0 == 1 {
            self.resolve_pixel(x0, y0, &live);
            return;
        }
        // Drop triangles hidden behind a surrounding one; keep the list order.
        let surrounding: Vec<u32> = live
            .iter()
            .filter(|(_, c)| *c == Class::Surrounding)
            .map(|(k, _)| *k)
            .collect();
        if !surrounding.is_empty() {
            live.retain(|&(k, _)| {
                !surrounding
                    .iter()
                    .any(|&s| s != k && self.hides(s, k, &corners))
            });
        }
        if live.len() == 1 {
            // Case 3 (surrounding), case 4 (a surrounding triangle hid all others) or
            // case 2 (one contained or intersecting triangle): scan-convert it here.
            self.paint(live[0].0, x0, y0, x1, y1);
            return;
        }
        let keep: Vec<u32> = live.iter().map(|(k, _)| *k).collect();
        let (mx, my) = (x0 + (x1 - x0) / 2, y0 + (y1 - y0) / 2);
        self.area(x0, y0, mx, my, &keep);
        self.area(mx, y0, x1, my, &keep);
        self.area(x0, my, mx, y1, &keep);
        self.area(mx, my, x1, y1, &keep);
    }

    /// Whether surrounding triangle `s` wins every pixel of the area against `t`: its
    /// largest quantised corner depth is below `t`'s smallest (depths clamped as the
    /// rasteriser clamps them), or equal when `s` is the later triangle.
    fn hides(&self, s: u32, t: u32, corners: &[(f64, f64); 4]) -> bool {
        let ss = &self.tris[s as usize].1;
        let st = &self.tris[t as usize].1;
        let smax = corners
            .iter()
            .map(|&(x, y)| ss.plane_depth(x, y))
            .fold(f64::NEG_INFINITY, f64::max)
            .clamp(ss.dmin, ss.dmax);
        let tmin = corners
            .iter()
            .map(|&(x, y)| st.plane_depth(x, y))
            .fold(f64::INFINITY, f64::min)
            .clamp(st.dmin, st.dmax);
        let (qs, qt) = (self.format.round_trip(smax), self.format.round_trip(tmin));
        // The margin covers the rounding of depth stepped incrementally along a row (one
        // rounding per pixel); exact ties are never decided here but per pixel.
        let margin = (self.width as f64 + 4.0) * f64::EPSILON * (qs.abs() + qt.abs());
        qs + margin < qt
    }

    fn paint(&mut self, k: u32, x0: u32, y0: u32, x1: u32, y1: u32) {
        let (t, s) = self.tris[k as usize];
        let face = self.prep.faces[t as usize];
        for row in y0..y1 {
            let base = row as usize * self.width as usize;
            let (ids, depths) = (&mut self.out.ids, &mut self.out.depths);
            let format = self.format;
            s.for_each_in_row(row, x0, x1, |x, _| {
                let d = s.depth_at(x as f64 + 0.5, row as f64 + 0.5);
                ids[base + x as usize] = face;
                depths[base + x as usize] = format.round_trip(d);
            });
        }
    }

    fn resolve_pixel(&mut self, x: u32, y: u32, live: &[(u32, Class)]) {
        let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
        let mut best: Option<(f64, u32)> = None;
        for &(k, _) in live {
            let (t, s) = &self.tris[k as usize];
            if !s.covers(px, py) {
                continue;
            }
            let d = self.format.round_trip(s.depth_at(px, py));
            if best.is_none_or(|(bd, bt)| d < bd || (d == bd && *t > bt)) {
                best = Some((d, *t));
            }
        }
        if let Some((d, t)) = best {
            let i = y as usize * self.width as usize + x as usize;
            self.out.ids[i] = self.prep.faces[t as usize];
            self.out.depths[i] = d;
        }
    }
}
