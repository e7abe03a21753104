//! Opaque textured faces drawn from one image of the page.
//!
//! Drawn under its own map, every textured triangle of a mesh costs a vector viewer a
//! clip of its own (a 3,600-face truck: 14,000 clips, and its lit colours as a second,
//! multiplied layer whose pieces leave hairlines in rsvg), and its file holds a matrix
//! and a clip per triangle. [`draw_from_page_image`] instead samples what every opaque
//! textured fragment shows — its fill or its lit vertex colours times its texture, as
//! the PNG painter samples them — at `samples` points per page unit, the topmost
//! fragment's colour at each point, into one image of the page. Each such fragment is
//! then the image under one shared map, white and unlit; the writers draw consecutive
//! ones as one run: the union of their outlines as one clip, the image placed once
//! inside it. Boundaries are unchanged (the clip is the fragments' own outline, exact as
//! every outline is); the colours inside are the image's, interpolated by the viewer
//! between samples.
//!
//! A point in no fragment takes the colour of the nearest fan triangle near it (the
//! anti-aliased rim of a clip reads there); points far from every fragment are never
//! shown and stay transparent.
//!
//! A face whose texture blends with what is behind it, or a translucent textured face,
//! cannot share the page image (what lies beneath it must show through, and where faces
//! overlap each needs its own colour): its consecutive fragments are drawn from an image
//! of their own, sampled on the same grid over their box, with the texture's alpha; the
//! face's opacity is applied once to it. Cut-outs keep their own maps: their boundary
//! follows their texels.

use std::sync::Arc;

use limn_scene::{Texture, TextureAlpha};
use rayon::prelude::*;

use crate::runs::{is_valid, Frag};
use crate::texture_pieces::{affine_pieces, AffinePiece};
use crate::{narrow_color, PageImage, PaintFragment, Picture, TextureMap, VertexColor};

/// Samples per page unit by default: twice the page's pixels each way.
pub const DEFAULT_TEXTURE_SAMPLES: f64 = 2.0;

/// The most samples the page image holds; a larger page is sampled more coarsely.
const MAX_SAMPLES: f64 = (1u64 << 22) as f64;

/// Side of an index cell, in samples.
const CELL: usize = 16;

/// How far around a fan triangle, in samples, the image holds its colour.
const RIM: f64 = 2.0;

/// Side of a tile of the page image, in samples.
pub(crate) const TILE: u32 = 128;

/// The page image of a picture cut into tiles of [`TILE`] × [`TILE`] samples, as the
/// vector writers embed it: a run drawn from it places only the tiles it covers (a
/// viewer resamples each image it places whole, however little of it a clip shows).
/// Each tile also holds the first column and row of the tiles after it, so that tiles
/// placed side by side overlap by one sample, where both hold the same samples: no
/// seam opens between them.
#[derive(Clone)]
pub(crate) struct Tiles {
    /// The page image's index in [`Picture::textures`].
    pub texture: u32,
    image: Arc<Texture>,
    samples: f64,
    cols: u32,
    rows: u32,
}

impl Tiles {
    /// The tiles of `picture`'s page image, if it has one.
    pub fn of(picture: &Picture) -> Option<Tiles> {
        let page = picture.page_image?;
        let image = picture.textures.get(page.texture as usize)?.clone();
        Some(Tiles {
            texture: page.texture,
            samples: page.samples,
            cols: image.width().div_ceil(TILE),
            rows: image.height().div_ceil(TILE),
            image,
        })
    }

    /// How many tiles there are (ids run row by row).
    pub fn count(&self) -> usize {
        (self.cols * self.rows) as usize
    }

    /// Marks in `tiles` (one flag per tile) every tile whose samples a polygon with
    /// corners `points` reads: those its box, grown by [`RIM`] samples, meets.
    pub fn mark(&self, points: &[[f64; 2]], tiles: &mut [bool]) {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in points {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let tile = |v: f64, n: u32| -> Option<u32> {
            let t = (v * self.samples / f64::from(TILE)).floor();
            (t >= 0.0).then(|| (t as u32).min(n - 1))
        };
        let grow = RIM / self.samples;
        let (Some(x1), Some(y1)) = (tile(hi[0] + grow, self.cols), tile(hi[1] + grow, self.rows))
        else {
            return;
        };
        let x0 = tile(lo[0] - grow, self.cols).unwrap_or(0);
        let y0 = tile(lo[1] - grow, self.rows).unwrap_or(0);
        for ty in y0..=y1 {
            for tx in x0..=x1 {
                if let Some(t) = tiles.get_mut((ty * self.cols + tx) as usize) {
                    *t = true;
                }
            }
        }
    }

    /// The samples of tile `id`: its first column and row, its size, and the page
    /// rectangle it covers `[x, y, width, height]`.
    fn span(&self, id: usize) -> ([u32; 2], [u32; 2], [f64; 4]) {
        let (tx, ty) = (id as u32 % self.cols, id as u32 / self.cols);
        let (i0, j0) = (tx * TILE, ty * TILE);
        let w = (TILE + 1).min(self.image.width() - i0);
        let h = (TILE + 1).min(self.image.height() - j0);
        let s = self.samples;
        let rect = [
            f64::from(i0) / s,
            f64::from(j0) / s,
            f64::from(w) / s,
            f64::from(h) / s,
        ];
        ([i0, j0], [w, h], rect)
    }

    /// The page rectangle `[x, y, width, height]` tile `id` covers.
    pub fn rect(&self, id: usize) -> [f64; 4] {
        self.span(id).2
    }

    /// Tile `id` as a texture of its own (opaque).
    pub fn texture(&self, id: usize) -> Option<Texture> {
        let ([i0, j0], [w, h], _) = self.span(id);
        let stride = 4 * self.image.width() as usize;
        let all = self.image.rgba();
        let mut rgba = Vec::with_capacity(4 * (w * h) as usize);
        for j in j0..j0 + h {
            let at = j as usize * stride + 4 * i0 as usize;
            rgba.extend_from_slice(&all[at..at + 4 * w as usize]);
        }
        Texture::new("a tile of the page image", w, h, rgba).ok()
    }

    /// Flags (one per tile) of the tiles some fragment drawn from the page image reads.
    pub fn used(&self, picture: &Picture) -> Vec<bool> {
        let mut tiles = vec![false; self.count()];
        for f in &picture.fragments {
            if f.texture
                .as_ref()
                .is_some_and(|m| m.texture == self.texture)
                && is_valid(f)
            {
                self.mark(&f.points, &mut tiles);
            }
        }
        tiles
    }
}

/// One fan triangle of a fragment drawn from the image.
struct Tri {
    p: [[f64; 2]; 3],
    inv_det: f64,
    /// The fragment (index into the picture) and the second corner of its fan triangle.
    frag: usize,
    corner: usize,
}

/// How a textured fragment is drawn from page samples.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Drawn {
    /// From the page image: opaque, of opacity 1, its texture showing nothing behind it.
    Page(TextureMap),
    /// From an image of its own face's fragments, their alpha (and opacity) kept: a
    /// blended texture or a translucent face.
    Own(TextureMap),
}

/// How `f` is drawn from page samples: `None` for an untextured or invalid fragment, a
/// cut-out (its boundary follows its texels), or one whose vertex colours carry an
/// opacity of their own.
fn drawn(f: &PaintFragment, textures: &[Arc<Texture>]) -> Option<Drawn> {
    let map = f.texture.as_deref()?;
    let texture = textures.get(map.texture as usize)?;
    let mask = map.alpha == TextureAlpha::Mask || texture.alpha() == TextureAlpha::Mask;
    // The fill's opacity as vertex colours keep it.
    let alpha = narrow_color(f.fill)[3];
    let own_alpha = f
        .vertex_colors
        .as_ref()
        .is_some_and(|cs| cs.iter().any(|c| c[3] != alpha));
    if mask || own_alpha || !is_valid(f) {
        return None;
    }
    let opaque = !map.see_through() && texture.alpha() == TextureAlpha::Opaque && f.fill[3] >= 1.0;
    Some(if opaque {
        Drawn::Page(*map)
    } else {
        Drawn::Own(*map)
    })
}

/// The map every fragment of `run` shares when it is affine (as the page image's is):
/// the run is then drawn as one placement of its image inside the run's outline.
pub(crate) fn shared_affine_map<'r>(run: &'r [Frag<'_>]) -> Option<&'r TextureMap> {
    let map = run.first()?.src.texture.as_deref()?;
    let affine = map.screen_to_st[2] == [0.0, 0.0, 1.0];
    (affine && run.iter().all(|f| f.src.texture.as_deref() == Some(map))).then_some(map)
}

/// What a writer draws first of a textured run (`see_through`: its texture shows what
/// is behind it): the whole run under one affine map, its first fan triangle's, so that
/// the anti-aliased edges between its pieces show nearly the same texels; and whether
/// every fragment shares that one affine map (the whole is then all there is to draw).
/// No whole under a texture that shows through, unless it is all that is drawn (it
/// would show twice).
pub(crate) fn run_underlay(run: &[Frag<'_>], see_through: bool) -> (Option<AffinePiece>, bool) {
    let one_map = shared_affine_map(run).is_some();
    let whole = run
        .iter()
        .find_map(|f| f.src.texture.as_deref())
        .filter(|_| !see_through || one_map)
        .and_then(|map| {
            affine_pieces(&run[0].points, map, f64::INFINITY)
                .into_iter()
                .next()
        });
    (whole, one_map)
}

/// The colour of fragment `f` at page point `p` in its fan triangle `(0, corner,
/// corner + 1)` with barycentric weights `l` (clamped to the triangle, for the rim): its
/// fill or its vertex colours interpolated, times its texture under `map`; RGB in
/// [0, 1] and the texture's alpha.
pub(crate) fn textured_colour(
    fill: [f64; 4],
    colors: Option<&[VertexColor]>,
    corner: usize,
    l: [f64; 3],
    map: Option<&TextureMap>,
    textures: &[Arc<Texture>],
    p: [f64; 2],
) -> ([f64; 3], f64) {
    let base = match colors {
        None => fill,
        Some(cs) => {
            let l = l.map(|v| v.max(0.0));
            let sum = (l[0] + l[1] + l[2]).max(f64::MIN_POSITIVE);
            let at = [0, corner, corner + 1];
            let mut c = [0.0; 4];
            for k in 0..3 {
                c[k] = (0..3).map(|j| l[j] * f64::from(cs[at[j]][k])).sum::<f64>() / sum;
            }
            c
        }
    };
    match map.and_then(|m| Some((m, textures.get(m.texture as usize)?))) {
        Some((map, tex)) => {
            let t = tex.sample_rgba(map.st_at(p).unwrap_or([f64::NAN; 2]));
            ([0, 1, 2].map(|k| (base[k] * t[k]).clamp(0.0, 1.0)), t[3])
        }
        None => ([0, 1, 2].map(|k| base[k].clamp(0.0, 1.0)), 1.0),
    }
}

/// Draws every opaque textured fragment of `picture` from one image of the page sampled
/// at `samples` points per page unit each way (fewer on a page of more than 2²² samples;
/// see the module docs): the image is added to [`Picture::textures`] and named by
/// [`Picture::page_image`], each such fragment becomes that image under one shared map,
/// white and unlit. Without outlines, consecutive such fragments of one object are made
/// one face, so that the writers draw them as one run (its union one clip). A textured
/// face that lets what is behind it show (a blended texture, or translucent) is drawn
/// likewise from an image of its own consecutive fragments sampled on the same grid,
/// their texture's alpha in the image and their opacity kept. Cut-outs keep their own
/// maps (their boundary follows their texels). Textures no fragment reads any more are
/// left out. Returns how many fragments are drawn from page samples: 0, changing
/// nothing, when none qualifies, `samples` is not positive or the picture already has a
/// page image.
pub fn draw_from_page_image(picture: &mut Picture, samples: f64) -> usize {
    if samples.is_nan()
        || samples <= 0.0
        || picture.textures.is_empty()
        || picture.page_image.is_some()
    {
        return 0;
    }
    let how: Vec<Option<Drawn>> = picture
        .fragments
        .iter()
        .map(|f| drawn(f, &picture.textures))
        .collect();
    let maps: Vec<Option<TextureMap>> = how
        .iter()
        .map(|d| d.map(|(Drawn::Page(m) | Drawn::Own(m))| m))
        .collect();
    let count = maps.iter().filter(|m| m.is_some()).count();
    if count == 0 {
        return 0;
    }
    let (pw, ph) = (f64::from(picture.width), f64::from(picture.height));
    let s = samples.min((MAX_SAMPLES / (pw * ph)).sqrt());
    // The faces that show what is behind them: consecutive fragments of one face, each
    // run from an image of its own.
    let mut own: Vec<(usize, usize)> = Vec::new();
    for (k, d) in how.iter().enumerate() {
        if !matches!(d, Some(Drawn::Own(_))) {
            continue;
        }
        let f = &picture.fragments[k];
        match own.last_mut() {
            Some((start, end))
                if *end == k && {
                    let g = &picture.fragments[*start];
                    (g.object, g.face) == (f.object, f.face)
                } =>
            {
                *end = k + 1;
            }
            _ => own.push((k, k + 1)),
        }
    }
    let mut replaced: Vec<Option<TextureMap>> = vec![None; maps.len()];
    // Their images together hold at most MAX_SAMPLES; faces beyond keep their maps.
    let mut budget = MAX_SAMPLES;
    for (start, end) in own {
        let frags: Vec<usize> = (start..end).collect();
        let Some(region) = region_of(picture, &frags, s) else {
            continue;
        };
        let samples = f64::from(region.size[0]) * f64::from(region.size[1]);
        if samples > budget {
            continue;
        }
        budget -= samples;
        let blended = frags.iter().any(|&k| {
            let m = maps[k].as_ref();
            m.is_some_and(|m| {
                m.alpha == TextureAlpha::Blend
                    || picture.textures[m.texture as usize].alpha() == TextureAlpha::Blend
            })
        });
        let rgba = sample_region(picture, &frags, &maps, region);
        let Ok(image) = Texture::new(
            "page samples of a see-through face",
            region.size[0],
            region.size[1],
            rgba,
        ) else {
            continue;
        };
        // Blended where its samples' alpha is drawn (not where all are opaque).
        let image = if blended {
            image.with_alpha(TextureAlpha::Blend)
        } else {
            image
        };
        let mut map = region.map(image.alpha());
        picture.textures.push(Arc::new(image));
        map.texture = (picture.textures.len() - 1) as u32;
        for k in frags {
            replaced[k] = Some(map);
        }
    }
    // The page image of the opaque ones.
    let page: Vec<usize> = (0..how.len())
        .filter(|&k| matches!(how[k], Some(Drawn::Page(_))))
        .collect();
    if !page.is_empty() {
        let region = Region {
            origin: [0, 0],
            size: [
                ((pw * s).ceil() as u32).max(1),
                ((ph * s).ceil() as u32).max(1),
            ],
            s,
        };
        let rgba = sample_region(picture, &page, &maps, region);
        if let Ok(image) = Texture::new(
            "page image of the textured faces",
            region.size[0],
            region.size[1],
            rgba,
        ) {
            picture.textures.push(Arc::new(image));
            let index = (picture.textures.len() - 1) as u32;
            let mut shared = region.map(TextureAlpha::Opaque);
            shared.texture = index;
            for &k in &page {
                replaced[k] = Some(shared);
            }
            picture.page_image = Some(PageImage {
                texture: index,
                samples: s,
            });
        }
    }
    let one_run = picture.outline.is_none();
    let mut run_face: Option<(u32, u32)> = None;
    let mut drawn_count = 0;
    for (k, f) in picture.fragments.iter_mut().enumerate() {
        let Some(map) = replaced[k] else {
            run_face = None;
            continue;
        };
        drawn_count += 1;
        f.texture = Some(Box::new(map));
        f.fill = [1.0, 1.0, 1.0, f.fill[3]];
        f.vertex_colors = None;
        let paged = matches!(how[k], Some(Drawn::Page(_)));
        if one_run && paged {
            match run_face {
                Some((object, face)) if object == f.object => f.face = face,
                _ => run_face = Some((f.object, f.face)),
            }
        } else {
            run_face = None;
        }
    }
    drop_unused_textures(picture);
    drawn_count
}

/// The samples around the fragments `frags` (indices) on the grid of `s` samples per
/// page unit, grown by [`RIM`] and kept within the page: `None` when they lie off it.
fn region_of(picture: &Picture, frags: &[usize], s: f64) -> Option<Region> {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for &k in frags {
        for p in &picture.fragments[k].points {
            for a in 0..2 {
                lo[a] = lo[a].min(p[a]);
                hi[a] = hi[a].max(p[a]);
            }
        }
    }
    let page = [f64::from(picture.width) * s, f64::from(picture.height) * s];
    let mut origin = [0i64; 2];
    let mut size = [0u32; 2];
    for a in 0..2 {
        let from = (lo[a] * s - RIM).floor().max(0.0);
        let to = (hi[a] * s + RIM).ceil().min(page[a].ceil());
        if to <= from {
            return None;
        }
        origin[a] = from as i64;
        size[a] = (to - from) as u32;
    }
    Some(Region { origin, size, s })
}

/// Leaves out of [`Picture::textures`] those no fragment reads any more (the faces'
/// own textures, now sampled into the page image), renumbering the maps of the rest.
fn drop_unused_textures(picture: &mut Picture) {
    let mut used = vec![false; picture.textures.len()];
    for f in &picture.fragments {
        if let Some(m) = &f.texture {
            match used.get_mut(m.texture as usize) {
                Some(u) => *u = true,
                // A map naming no texture: the writers refuse the picture as it is.
                None => return,
            }
        }
    }
    let mut renumbered = vec![0u32; used.len()];
    let mut next = 0u32;
    for (k, &u) in used.iter().enumerate() {
        renumbered[k] = next;
        next += u32::from(u);
    }
    let mut k = 0;
    picture.textures.retain(|_| {
        k += 1;
        used[k - 1]
    });
    for f in &mut picture.fragments {
        if let Some(m) = f.texture.as_deref_mut() {
            m.texture = renumbered[m.texture as usize];
        }
    }
    if let Some(p) = &mut picture.page_image {
        p.texture = renumbered[p.texture as usize];
    }
}

/// A rectangle of the page's sample grid (`s` samples per page unit): its first
/// column and row and its size, in samples.
#[derive(Debug, Clone, Copy)]
struct Region {
    origin: [i64; 2],
    size: [u32; 2],
    s: f64,
}

impl Region {
    /// Page point `p` in the region's samples (sample `(i, j)` is centred at
    /// `(i + ½, j + ½)`).
    fn at(&self, p: [f64; 2]) -> [f64; 2] {
        [
            p[0] * self.s - self.origin[0] as f64,
            p[1] * self.s - self.origin[1] as f64,
        ]
    }

    /// The map from the page to the region's image as a texture (its unit square).
    fn map(&self, alpha: TextureAlpha) -> TextureMap {
        let (w, h) = (f64::from(self.size[0]), f64::from(self.size[1]));
        TextureMap {
            texture: 0,
            screen_to_st: [
                [self.s / w, 0.0, -(self.origin[0] as f64) / w],
                [0.0, self.s / h, -(self.origin[1] as f64) / h],
                [0.0, 0.0, 1.0],
            ],
            alpha,
        }
    }
}

/// The image (RGBA rows) of `region`: each sample the colour (and the texture's alpha)
/// of the last fragment of `frags` (indices in paint order, each with its map in
/// `maps`) whose fan triangle holds it, or of the fan triangle nearest it within [`RIM`]
/// samples; transparent black elsewhere.
fn sample_region(
    picture: &Picture,
    frags: &[usize],
    maps: &[Option<TextureMap>],
    region: Region,
) -> Vec<u8> {
    let [w, h] = region.size;
    let mut tris = Vec::new();
    for &k in frags {
        let p: Vec<[f64; 2]> = picture.fragments[k]
            .points
            .iter()
            .map(|&q| region.at(q))
            .collect();
        for i in 1..p.len() - 1 {
            let t = [p[0], p[i], p[i + 1]];
            let det = (t[1][0] - t[0][0]) * (t[2][1] - t[0][1])
                - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1]);
            if det != 0.0 && det.is_finite() {
                tris.push(Tri {
                    p: t,
                    inv_det: 1.0 / det,
                    frag: k,
                    corner: i,
                });
            }
        }
    }
    // Cells of CELL × CELL samples, each listing (in paint order) the triangles whose
    // box grown by the rim meets it.
    let (cw, ch) = ((w as usize).div_ceil(CELL), (h as usize).div_ceil(CELL));
    let mut cells: Vec<Vec<u32>> = vec![Vec::new(); cw * ch];
    let cell = |v: f64, n: usize| -> usize {
        // Clamped to the grid (NaN-free: corners are finite).
        (v / CELL as f64).floor().clamp(0.0, n as f64 - 1.0) as usize
    };
    for (n, t) in tris.iter().enumerate() {
        let lo = |k: usize| t.p.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min) - RIM;
        let hi = |k: usize| t.p.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max) + RIM;
        if hi(0) < 0.0 || hi(1) < 0.0 || lo(0) > f64::from(w) || lo(1) > f64::from(h) {
            continue;
        }
        for cy in cell(lo(1), ch)..=cell(hi(1), ch) {
            for cx in cell(lo(0), cw)..=cell(hi(0), cw) {
                cells[cy * cw + cx].push(n as u32);
            }
        }
    }
    let textures = &picture.textures;
    let mut rgba = vec![0u8; 4 * w as usize * h as usize];
    rgba.par_chunks_mut(4 * w as usize)
        .enumerate()
        .for_each(|(j, row)| {
            let y = j as f64 + 0.5;
            let cy = j / CELL;
            for i in 0..w as usize {
                let x = i as f64 + 0.5;
                let list = &cells[cy * cw + i / CELL];
                // The last triangle holding the point, else the nearest one.
                let mut best: Option<(f64, &Tri, [f64; 3])> = None;
                for &n in list.iter().rev() {
                    let t = &tris[n as usize];
                    let [a, b, c] = t.p;
                    let l1 = ((x - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (y - a[1])) * t.inv_det;
                    let l2 = ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) * t.inv_det;
                    let l = [1.0 - l1 - l2, l1, l2];
                    let score = l[0].min(l[1]).min(l[2]);
                    if best.is_none_or(|(s0, _, _)| score > s0) {
                        best = Some((score, t, l));
                    }
                    if score >= 0.0 {
                        break;
                    }
                }
                let Some((_, t, l)) = best else { continue };
                let f = &picture.fragments[t.frag];
                let page = [
                    (x + region.origin[0] as f64) / region.s,
                    (y + region.origin[1] as f64) / region.s,
                ];
                let (c, a) = textured_colour(
                    f.fill,
                    f.vertex_colors.as_deref(),
                    t.corner,
                    l,
                    maps[t.frag].as_ref(),
                    textures,
                    page,
                );
                let px = &mut row[4 * i..4 * i + 4];
                for k in 0..3 {
                    px[k] = (c[k] * 255.0).round() as u8;
                }
                px[3] = (a.clamp(0.0, 1.0) * 255.0).round() as u8;
            }
        });
    rgba
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 4 × 4 texture whose texel (i, j) is (60·i, 60·j, 100).
    fn texture() -> Arc<Texture> {
        let rgba = (0..16u32)
            .flat_map(|k| [(60 * (k % 4)) as u8, (60 * (k / 4)) as u8, 100, 255])
            .collect();
        Arc::new(Texture::new("t", 4, 4, rgba).unwrap())
    }

    /// A picture of two textured squares, the second over the first, and a flat one.
    fn picture() -> Picture {
        let mut p = Picture::new(40, 30);
        p.textures.push(texture());
        let map = TextureMap {
            texture: 0,
            screen_to_st: [[0.05, 0.0, 0.0], [0.0, 0.05, 0.0], [0.0, 0.0, 1.0]],
            alpha: TextureAlpha::Opaque,
        };
        let square =
            |x: f64, y: f64| vec![[x, y], [x + 20.0, y], [x + 20.0, y + 20.0], [x, y + 20.0]];
        let mut a = PaintFragment::new(square(0.0, 0.0), [1.0, 0.5, 1.0, 1.0]);
        a.texture = Some(Box::new(map));
        a.face = 1;
        let mut b = PaintFragment::new(square(10.0, 5.0), [1.0; 4]);
        b.texture = Some(Box::new(map));
        b.vertex_colors = Some(vec![[0.5, 0.5, 0.5, 1.0]; 4]);
        b.face = 2;
        let mut c = PaintFragment::new(square(20.0, 10.0), [0.2, 0.3, 0.4, 1.0]);
        c.face = 3;
        p.fragments = vec![a, b, c];
        p
    }

    #[test]
    fn each_sample_is_the_topmost_fragments_colour() {
        let before = picture();
        let mut after = picture();
        assert_eq!(draw_from_page_image(&mut after, 2.0), 2);
        let page = after.page_image.unwrap();
        // The faces' own texture is left out; the page image takes its place.
        assert_eq!(
            (after.textures.len(), page.texture, page.samples),
            (1, 0, 2.0)
        );
        let image = after.textures[0].clone();
        assert_eq!((image.width(), image.height()), (80, 60));
        let shared = *after.fragments[0].texture.as_deref().unwrap();
        assert_eq!(after.fragments[1].texture.as_deref(), Some(&shared));
        assert_eq!(after.fragments[2].texture, None);
        // One run: the second square takes the first's face; the flat one keeps its own.
        assert_eq!(
            after.fragments.iter().map(|f| f.face).collect::<Vec<_>>(),
            [1, 1, 3]
        );
        assert_eq!(after.fragments[1].vertex_colors, None);
        let tex = &before.textures;
        // Sample centres: in the first square only, in both (the second wins).
        for (p, top) in [([5.25, 3.25], 0), ([15.25, 10.25], 1), ([28.75, 22.75], 1)] {
            let f = &before.fragments[top];
            let want = textured_colour(
                f.fill,
                f.vertex_colors.as_deref(),
                1,
                [1.0, 0.0, 0.0],
                f.texture.as_deref(),
                tex,
                p,
            )
            .0;
            // The image's own texel there, read at its centre.
            let got = image.sample(shared.st_at(p).unwrap());
            for k in 0..3 {
                assert!(
                    (want[k] - got[k]).abs() <= 0.5 / 255.0 + 1e-12,
                    "{p:?}: {want:?} {got:?}"
                );
            }
        }
    }

    #[test]
    fn see_through_faces_get_images_of_their_own_cut_outs_keep_their_maps() {
        // A translucent face and a blended one: each from an image of its own (its
        // opacity kept, the texture's alpha in the image), no page image.
        let before = picture();
        let mut p = picture();
        p.fragments[0].fill[3] = 0.5;
        // The second square's texture half transparent, blended.
        let rgba = texture()
            .rgba()
            .chunks_exact(4)
            .flat_map(|c| [c[0], c[1], c[2], 128])
            .collect();
        let half = Texture::new("half", 4, 4, rgba)
            .unwrap()
            .with_alpha(TextureAlpha::Blend);
        p.textures.push(Arc::new(half));
        if let Some(m) = p.fragments[1].texture.as_deref_mut() {
            m.alpha = TextureAlpha::Blend;
            m.texture = 1;
        }
        assert_eq!(draw_from_page_image(&mut p, 2.0), 2);
        assert_eq!((p.page_image, p.textures.len()), (None, 2));
        let [a, b] = [0, 1].map(|k| *p.fragments[k].texture.as_deref().unwrap());
        assert_eq!(
            (a.alpha, b.alpha),
            (TextureAlpha::Opaque, TextureAlpha::Blend)
        );
        assert_eq!(p.textures[b.texture as usize].alpha(), TextureAlpha::Blend);
        assert_eq!(p.fragments[0].fill, [1.0, 1.0, 1.0, 0.5]);
        assert_eq!(p.fragments[1].vertex_colors, None);
        // Each image covers its face (grown by the rim), on the page's sample grid:
        // the first square's 40 × 40 samples and the rim, within the page.
        let image = &p.textures[a.texture as usize];
        assert_eq!((image.width(), image.height()), (42, 42));
        // Its samples are the face's colours.
        let q = [7.25, 9.75];
        let f = &before.fragments[0];
        let want = textured_colour(
            f.fill,
            None,
            1,
            [1.0, 0.0, 0.0],
            f.texture.as_deref(),
            &before.textures,
            q,
        )
        .0;
        let got = image.sample(a.st_at(q).unwrap());
        for k in 0..3 {
            assert!(
                (want[k] - got[k]).abs() <= 0.5 / 255.0 + 1e-12,
                "{want:?} {got:?}"
            );
        }
        // A cut-out keeps its map and its texture.
        let mut p = picture();
        if let Some(m) = p.fragments[1].texture.as_deref_mut() {
            m.alpha = TextureAlpha::Mask;
        }
        assert_eq!(draw_from_page_image(&mut p, 2.0), 1);
        assert_eq!(
            p.fragments[1].texture.as_deref().unwrap().screen_to_st,
            before.fragments[1].texture.as_deref().unwrap().screen_to_st
        );
        assert_eq!(p.textures.len(), 2);
        let mut p = picture();
        p.outline = Some(crate::Outline {
            width: 1.0,
            color: [0.0, 0.0, 0.0, 1.0],
        });
        assert_eq!(draw_from_page_image(&mut p, 2.0), 2);
        assert_eq!(
            p.fragments.iter().map(|f| f.face).collect::<Vec<_>>(),
            [1, 2, 3]
        );
        assert_eq!(draw_from_page_image(&mut picture(), 0.0), 0);
    }

    #[test]
    fn a_large_page_is_sampled_more_coarsely() {
        let mut p = picture();
        p.width = 4000;
        p.height = 3000;
        assert_eq!(draw_from_page_image(&mut p, 2.0), 2);
        let image = &p.textures[0];
        let samples = f64::from(image.width()) * f64::from(image.height());
        assert!(samples <= MAX_SAMPLES + 8000.0, "{samples}");
        assert!(p.page_image.unwrap().samples < 1.0);
    }
}
