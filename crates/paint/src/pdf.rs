//! PDF, one page, through `pdf-writer`.
//!
//! The page is W × H points with `MediaBox [0 0 W H]`; a pixel point (x, y) is written as
//! (x, H − y), so the picture is upright with PDF's origin at the bottom left. The document
//! structure (catalog, page tree, resources, shadings, cross-reference table) is written by
//! `pdf-writer`; the content stream is written with the same number formatter as SVG and
//! EPS, so the three formats carry identical coordinates. Nothing time- or
//! machine-dependent is written: equal pictures give equal files.
//!
//! - Flat fragments: `r g b rg`, the subpaths of the run, `f` (non-zero rule).
//! - Opacity: an `ExtGState` per distinct value, named `/a` + thousandths (`/a500` sets
//!   `/ca 0.5`); the outline's opacity likewise as `/s` + thousandths (`/CA`).
//! - Gouraud fragments (with vertex colours): each run becomes one type-4 free-form
//!   triangle-mesh shading (`/Sh0 sh`, `/Sh1 sh`, …) holding every fragment
//!   fan-triangulated from its first corner; coordinates are 32-bit over the run's bounding
//!   box rounded outwards to whole points, colours 16-bit per channel. Translucent
//!   runs of one object and opacity are put into layers of runs shown disjoint (see
//!   `layers.rs`; runs disjoint from them painted first; not with outlines); a layer
//!   is one shading, filling its fragments' path opaque inside a
//!   transparency group (a form XObject `/FmN` with `/Group << /S /Transparency >>`)
//!   drawn with the opacity (`/a500 gs /Fm0 Do`): poppler paints a shading with `sh`
//!   opaque whatever the fill opacity, and ghostscript blends the shared edges of a
//!   mesh's triangles twice; a group is blended once.
//! - Textured fragments: each texture is one image XObject `/ImK` (RGB, 8 bits,
//!   Flate-compressed, `/Interpolate true`; a blended texture's with an `/SMask` of its
//!   alpha; a cut-out's repetitions clipped to its shown texels, see `texture_mask.rs`,
//!   the fill multiplied inside that clip). A fragment is drawn inside `q … Q` as
//!   affine triangles within [`crate::MAX_PERSPECTIVE_ERROR`] pixels of the exact
//!   projective map, each clipped to its triangle with the image placed by `cm` (once
//!   per repetition of the texture the triangle reaches; a triangle reaching more than
//!   1024 is filled with the mean colour and counted as approximated). Under them the
//!   whole run (fragments and seam flaps as one clip) is drawn first under one affine
//!   map, so the anti-aliased edges between triangles show nearly the same texels. A fill other than white is then
//!   painted over the fragment with the blend mode `Multiply` (`/Mul gs`): fill times
//!   texture, exact for opaque fragments; a translucent one blends twice and is counted
//!   as approximated. Smoothly lit textured fragments (vertex colours) instead wait,
//!   consecutive opaque runs together, and their triangle mesh goes over their textures
//!   in one transparency group drawn with `/Mul gs` (inside the group the fills cover
//!   each other as untextured layers do, so each pixel is multiplied once). A run
//!   whose fragments all share one affine map is drawn whole only, clipped to the
//!   union of its fragments.
//! - The page image ([`crate::draw_from_page_image`], [`Picture::page_image`]): not
//!   written itself; each of its tiles some fragment reads is an image XObject after
//!   the textures', and a run drawn from it is `q`, its union as the clip, a
//!   `q w 0 0 h x y cm /ImN Do Q` per tile its fragments read, `Q`.
//! - Outlines: `w`, round caps and joins and the stroke colour are set once; each run's
//!   original edges are one path stroked with `S` right after the run's fill.
//! - Marks: each inside `q … Q`, so they leave the fragments' state alone. Line pieces are
//!   stroked with butt caps (`0 J`), round joins and their dash (`[…] phase d`); markers
//!   are stroked or filled paths (circles as four Bézier curves); labels are `BT … Tj ET`
//!   in the base-14 font Helvetica (`/F1`, WinAnsiEncoding, not embedded), printable
//!   ASCII only (any other character is written as `?` and counted as approximated).

use std::cell::RefCell;
use std::collections::BTreeSet;
use std::io::Write;

use pdf_writer::writers::Catalog;
use pdf_writer::{Name, Rect, Ref};

use super::layers::Layers;
use super::marks::{ascii_text, circle_beziers, paint_mark, MarkSink};
use super::merge;
use super::number::{alpha_milli, channel_fixed, push_fixed, push_num, push_uint};
use super::pdf_objects::ObjectWriter;
use super::runs::{check, reversals, walk_with_marks, Frag};
use super::texture_page::{run_underlay, Tiles};
use super::texture_pieces::{pieces_over, push_flipped_outline};
use super::{
    pdf_texture, svg_texture, texture_images, texture_mask, Label, PaintError, PaintStats, Painter,
    Picture,
};

/// Options for [`PdfPainter`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PdfOptions {
    /// Maximal decimals for coordinates and the outline width. Default 2; at most 9.
    pub decimals: u8,
    /// Maximal decimals for colour components in [0, 1]. Default 4; at most 9.
    pub color_decimals: u8,
}

impl Default for PdfOptions {
    fn default() -> Self {
        PdfOptions {
            decimals: 2,
            color_decimals: 4,
        }
    }
}

/// Writes a one-page PDF.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct PdfPainter {
    /// How numbers are written.
    pub options: PdfOptions,
}

impl PdfPainter {
    /// A painter with the given options.
    pub fn new(options: PdfOptions) -> Self {
        PdfPainter { options }
    }
}

/// What makes two fragments paint alike in PDF.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Style {
    Flat([u32; 3], u16),
    Gouraud(u16),
    /// Texture index, fill (`None`: the vertex colours, smooth) and opacity.
    Textured(u32, Option<[u32; 3]>, u16),
}

/// A type-4 shading, written as soon as it is made (a million-face picture's 487,092
/// meshes, held until the end, were about 100 MB): its object, and the form of its
/// transparency group when it is painted in one (`/FmN Do`) rather than with `sh`.
struct Mesh {
    shading: Ref,
    form: Option<Ref>,
}

/// The content stream and the resources it uses, and the document it goes into (the
/// shadings are written to it as they are made).
struct Content<'w> {
    pdf: ObjectWriter<'w>,
    /// The next object id (1 to 4 are the catalog, the page tree, the page and the
    /// content stream).
    next: i32,
    /// The first error writing a shading (the rest are not written).
    failed: Option<std::io::Error>,
    /// The page's width (a group's bounding box).
    width: f64,
    buf: Vec<u8>,
    d: u8,
    cd: u8,
    height: f64,
    fill_alphas: BTreeSet<u16>,
    stroke_alphas: BTreeSet<u16>,
    meshes: Vec<Mesh>,
    alpha: u16,
    rgb: Option<[u32; 3]>,
    /// Seam stroke width (0 = none).
    seams: f64,
    /// Whether a flat run is written as the union of its fragments
    /// ([`Picture::merge_pieces`]).
    merge: bool,
    /// Current stroke colour and line width, and the outline's, to restore.
    stroke: Option<([u32; 3], u64)>,
    outline_stroke: Option<([u32; 3], u64)>,
    /// Whether a label uses the font `/F1`.
    font: bool,
    /// The textures (padded RGB rows, width, height) as image XObjects `/Im0`, …,
    /// then the tiles of the page image drawn (the page image itself empty: not
    /// written).
    images: Vec<(Vec<u8>, u32, u32)>,
    /// The page image in tiles, if the picture has one, and per tile the index in
    /// `images` of its XObject (tiles no fragment reads have none).
    page_tiles: Option<(Tiles, Vec<Option<usize>>)>,
    /// Per texture: a blended one's padded alpha rows, its image's soft mask.
    image_alphas: Vec<Option<Vec<u8>>>,
    /// Per texture: a cut-out's shown texels, the clip of each repetition.
    image_masks: Vec<Option<Vec<[f64; 4]>>>,
    /// Whether `/Mul` (blend mode Multiply) is used.
    multiply: bool,
}

impl Content<'_> {
    fn point(&mut self, p: [f64; 2]) {
        push_num(&mut self.buf, p[0], self.d);
        self.buf.push(b' ');
        push_num(&mut self.buf, self.height - p[1], self.d);
    }

    fn color(&mut self, c: [u32; 3], op: &[u8]) {
        for q in c {
            push_fixed(&mut self.buf, q, self.cd);
            self.buf.push(b' ');
        }
        self.buf.extend_from_slice(op);
    }

    fn fill_alpha(&mut self, milli: u16) {
        if milli != self.alpha {
            self.buf.extend_from_slice(b"/a");
            push_uint(&mut self.buf, milli.into());
            self.buf.extend_from_slice(b" gs\n");
            self.fill_alphas.insert(milli);
            self.alpha = milli;
        }
    }

    fn quantise(&self, c: [f64; 3]) -> [u32; 3] {
        c.map(|v| channel_fixed(v, self.cd))
    }

    fn flat_run(&mut self, run: &[Frag<'_>], rgb: [u32; 3]) {
        let height = self.height;
        let stroked = self.seams > 0.0 && self.alpha >= 1000;
        let merged = merge::run_shapes(run, self.d, self.merge, |p| [p[0], height - p[1]])
            .filter(|shapes| !(shapes.is_empty() && stroked));
        if merged.as_ref().is_some_and(Vec::is_empty) {
            // Fills no point.
            return;
        }
        if self.rgb != Some(rgb) {
            self.color(rgb, b"rg\n");
            self.rgb = Some(rgb);
        }
        match merged {
            Some(shapes) => {
                for shape in &shapes {
                    merge::push_moveto_lineto(&mut self.buf, shape, self.d);
                }
            }
            None => {
                for (f, reverse) in run.iter().zip(reversals(run)) {
                    for (k, p) in f.oriented(reverse).enumerate() {
                        self.point(p);
                        self.buf
                            .extend_from_slice(if k == 0 { b" m " } else { b" l " });
                    }
                    self.buf.extend_from_slice(b"h\n");
                }
            }
        }
        if self.seams > 0.0 && self.alpha >= 1000 {
            self.set_stroke(rgb, self.seams);
            self.buf.extend_from_slice(b"B\n");
        } else {
            self.buf.extend_from_slice(b"f\n");
        }
    }

    /// A run of textured fragments with texture `k` and fill `rgb` (`None`: their
    /// vertex colours; see the module docs), inside `q … Q`; returns how many fragments
    /// are approximated.
    fn textured_run(
        &mut self,
        run: &[Frag<'_>],
        k: u32,
        rgb: Option<[u32; 3]>,
        mean: [f64; 3],
    ) -> usize {
        let fill = run[0].flat_rgb();
        let size = (self.images[k as usize].1, self.images[k as usize].2);
        let flat = self.quantise([0, 1, 2].map(|i| fill[i] * mean[i]));
        let polys: Vec<Vec<[f64; 2]>> = run
            .iter()
            .zip(reversals(run))
            .map(|(f, reverse)| f.oriented(reverse).collect())
            .collect();
        // Fills `polys` with the mean colour (too many repetitions of the texture).
        let mean_fill = |c: &mut Content<'_>, polys: &[Vec<[f64; 2]>]| {
            c.color(flat, b"rg\n");
            for poly in polys {
                for (i, &q) in poly.iter().enumerate() {
                    c.point(q);
                    c.buf
                        .extend_from_slice(if i == 0 { b" m " } else { b" l " });
                }
                c.buf.extend_from_slice(b"h ");
            }
            c.buf.extend_from_slice(b"f\n");
        };
        let mut approximated = 0;
        let see_through = svg_texture::see_through(run);
        if see_through && run.iter().any(|f| f.colors.is_some()) {
            // Smoothly lit: its mean lit colour multiplies the texture (a lit mesh
            // multiplied over it would colour its transparent parts).
            approximated += run.len();
        }
        let white = self.quantise([1.0; 3]);
        // A cut-out's fill multiplies each repetition inside its clip (its shown texels).
        let mask = self.image_masks[k as usize].take();
        let multiply_inside = match rgb {
            Some(rgb) if mask.is_some() && rgb != white => {
                let mut m = Vec::new();
                std::mem::swap(&mut m, &mut self.buf);
                self.color(rgb, b"rg /Mul gs 0 0 1 1 re f");
                std::mem::swap(&mut m, &mut self.buf);
                self.multiply = true;
                Some(m)
            }
            _ => None,
        };
        self.buf.extend_from_slice(b"q\n");
        // Under the pieces, the whole run (fragments and seam flaps: one clip).
        let (whole, one_map) = run_underlay(run, see_through);
        // Fragments drawn from the page image share one affine map (see
        // `texture_page.rs`): the whole run is all there is to draw, its outline their
        // union (the edges between them are then not in the clip).
        // The page image (see `texture_page.rs`) is drawn from its tiles, never under a
        // map of its own.
        let paged = self
            .page_tiles
            .as_ref()
            .is_some_and(|(t, _)| t.texture == k);
        let shared = (paged || whole.is_some()) && one_map;
        if paged || whole.is_some() {
            let height = self.height;
            let mut outline = Vec::new();
            match (shared && self.merge)
                .then(|| merge::union(run, self.d, |p| [p[0], height - p[1]]))
                .flatten()
            {
                Some(shapes) => shapes
                    .iter()
                    .for_each(|shape| merge::push_moveto_lineto(&mut outline, shape, self.d)),
                None => push_flipped_outline(&mut outline, &polys, height, self.d),
            }
            match (&self.page_tiles, &whole) {
                (Some((tiles, images)), _) if paged => {
                    write_tiled(&mut self.buf, &outline, run, tiles, images, height, self.d);
                }
                (_, Some(whole))
                    if !pdf_texture::write_clipped(
                        &mut self.buf,
                        &outline,
                        whole,
                        k,
                        size,
                        mask.as_deref(),
                        multiply_inside.as_deref(),
                        self.height,
                        self.d,
                    ) =>
                {
                    mean_fill(self, &polys);
                }
                _ => {}
            }
        }
        for f in run.iter().filter(|_| !shared && !paged) {
            let Some(map) = &f.src.texture else { continue };
            let mut flat = false;
            for p in pieces_over(&f.points, map, whole.as_ref(), run.len() == 1) {
                let tri = [p.points.clone()];
                let mut outline = Vec::new();
                push_flipped_outline(&mut outline, &tri, self.height, self.d);
                if !pdf_texture::write_clipped(
                    &mut self.buf,
                    &outline,
                    &p,
                    k,
                    size,
                    mask.as_deref(),
                    multiply_inside.as_deref(),
                    self.height,
                    self.d,
                ) {
                    flat = true;
                    mean_fill(self, &tri);
                }
            }
            approximated += usize::from(flat);
        }
        self.image_masks[k as usize] = mask;
        let Some(rgb) = rgb else {
            // Smoothly lit: the caller multiplies the lit colours over the texture
            // (`lit_layer`).
            self.buf.extend_from_slice(b"Q\n");
            return approximated;
        };
        if rgb != white && multiply_inside.is_none() {
            if see_through {
                // A blended texture: the fill is multiplied over what shows through
                // its transparent parts too.
                approximated += run.len();
            }
            self.buf.extend_from_slice(b"/Mul gs ");
            self.multiply = true;
            self.color(rgb, b"rg\n");
            for poly in &polys {
                for (i, &q) in poly.iter().enumerate() {
                    self.point(q);
                    self.buf
                        .extend_from_slice(if i == 0 { b" m " } else { b" l " });
                }
                self.buf.extend_from_slice(b"h ");
            }
            self.buf.extend_from_slice(b"f\n");
            if self.alpha < 1000 {
                approximated += run.len();
            }
        }
        self.buf.extend_from_slice(b"Q\n");
        // Q restored the colour set before the run.
        approximated
    }

    /// The lit colours of smoothly lit textured runs (`frags`, painted just before with
    /// their textures) as one triangle mesh in a transparency group, multiplied over
    /// the textures (`/Mul gs`): inside the group the fills are composited as an
    /// untextured smooth layer is, so each pixel is multiplied once.
    fn lit_layer(&mut self, frags: &[Frag<'_>]) {
        if frags.is_empty() {
            return;
        }
        self.multiply = true;
        self.buf.extend_from_slice(b"q /Mul gs ");
        self.gouraud_run(frags, true);
        self.buf.extend_from_slice(b"Q\n");
    }

    /// Sets the stroke colour and line width, writing only what changes.
    fn set_stroke(&mut self, rgb: [u32; 3], width: f64) {
        let (old_rgb, old_w) = self.stroke.unzip();
        if old_w != Some(width.to_bits()) {
            push_num(&mut self.buf, width, self.d);
            self.buf.extend_from_slice(b" w\n");
        }
        if old_rgb != Some(rgb) {
            self.color(rgb, b"RG\n");
        }
        self.stroke = Some((rgb, width.to_bits()));
    }

    /// Paints the run as one type-4 shading: with `sh`, or inside a transparency group
    /// when `group`.
    fn gouraud_run(&mut self, run: &[Frag<'_>], group: bool) {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for f in run {
            for p in f.points.iter() {
                let q = [p[0], self.height - p[1]];
                for k in 0..2 {
                    lo[k] = lo[k].min(q[k]);
                    hi[k] = hi[k].max(q[k]);
                }
            }
        }
        for k in 0..2 {
            lo[k] = lo[k].floor();
            hi[k] = hi[k].ceil().max(lo[k] + 1.0);
        }
        let mut data = Vec::new();
        let coord = |v: f64, k: usize| -> u32 {
            ((v - lo[k]) / (hi[k] - lo[k]) * f64::from(u32::MAX)).round() as u32
        };
        for f in run {
            let Some(colors) = &f.colors else { continue };
            for i in 1..f.points.len() - 1 {
                for v in [0, i, i + 1] {
                    let p = f.points[v];
                    data.push(0);
                    data.extend_from_slice(&coord(p[0], 0).to_be_bytes());
                    data.extend_from_slice(&coord(self.height - p[1], 1).to_be_bytes());
                    for c in &colors[v][..3] {
                        let q = (f64::from(*c).clamp(0.0, 1.0) * 65535.0).round() as u16;
                        data.extend_from_slice(&q.to_be_bytes());
                    }
                }
            }
        }
        let (name, op): (&[u8], &[u8]) = if group {
            (b"/Fm", b" Do\n")
        } else {
            (b"/Sh", b" sh\n")
        };
        let index = self.meshes.len();
        self.buf.extend_from_slice(name);
        push_uint(&mut self.buf, index as u64);
        self.buf.extend_from_slice(op);
        // In a group, the shading fills the fragments' path: viewers that paint a mesh
        // without anti-aliasing (poppler, ghostscript) then give its edges the path's
        // partial coverage, and two layers meeting along an edge do not both paint
        // its pixels in full.
        let group = group.then(|| {
            let main = std::mem::take(&mut self.buf);
            for f in run {
                // Every subpath turning one way: the non-zero rule fills their union
                // (overlapping seam flaps included).
                for (k, p) in f.oriented(f.area2() < 0.0).enumerate() {
                    self.point(p);
                    self.buf
                        .extend_from_slice(if k == 0 { b" m " } else { b" l " });
                }
                self.buf.extend_from_slice(b"h\n");
            }
            std::mem::replace(&mut self.buf, main)
        });
        let shading = self.alloc();
        let form = group.as_ref().map(|_| (self.alloc(), self.alloc()));
        self.meshes.push(Mesh {
            shading,
            form: form.map(|f| f.0),
        });
        if self.failed.is_none() {
            let decode = [lo[0], hi[0], lo[1], hi[1]];
            if let Err(e) = self.write_mesh(shading, &data, decode, form.zip(group)) {
                self.failed = Some(e);
            }
        }
    }

    /// A new object id.
    fn alloc(&mut self) -> Ref {
        let r = Ref::new(self.next);
        self.next += 1;
        r
    }

    /// Writes a type-4 shading (`data`, its Decode array's x0 x1 y0 y1) as object
    /// `shading`, and when painted in a group, the group's form and pattern objects and
    /// the path the group fills.
    fn write_mesh(
        &mut self,
        shading: Ref,
        data: &[u8],
        decode: [f64; 4],
        group: Option<((Ref, Ref), Vec<u8>)>,
    ) -> std::io::Result<()> {
        if let Some(((form, pattern), path)) = group {
            // The form fills its path with its shading, opaque: a group starts with
            // opacity 1.
            let mut content = b"/Pattern cs /P scn\n".to_vec();
            content.extend_from_slice(&path);
            content.extend_from_slice(b"f\n");
            let mut f = self.pdf.object(form)?.form_xobject(form, &content);
            f.bbox(Rect::new(0.0, 0.0, self.width as f32, self.height as f32));
            f.group().transparency();
            f.resources().patterns().pair(Name(b"P"), pattern);
            drop(f);
            self.pdf
                .object(pattern)?
                .shading_pattern(pattern)
                .shading_ref(shading);
        }
        let mut s = self.pdf.object(shading)?.stream_shading(shading, data);
        // `StreamShadingType` is not exported by pdf-writer 0.14: write the number.
        s.pair(Name(b"ShadingType"), 4);
        s.color_space().device_rgb();
        s.bits_per_coordinate(32);
        s.bits_per_component(16);
        s.bits_per_flag(8);
        let [x0, x1, y0, y1] = decode.map(|v| v as f32);
        s.decode([x0, x1, y0, y1, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0]);
        Ok(())
    }

    fn outline(&mut self, run: &[Frag<'_>]) {
        if let Some((rgb, w)) = self.outline_stroke {
            self.set_stroke(rgb, f64::from_bits(w));
        }
        for f in run {
            let n = f.points.len();
            f.polylines(|start, edges, closed| {
                let last = if closed { edges - 1 } else { edges };
                for k in 0..=last {
                    self.point(f.points[(start + k) % n]);
                    self.buf
                        .extend_from_slice(if k == 0 { b" m " } else { b" l " });
                }
                if closed {
                    self.buf.extend_from_slice(b"h ");
                }
            });
        }
        self.buf.extend_from_slice(b"S\n");
    }
}

impl Painter for PdfPainter {
    fn paint<'p>(
        &self,
        picture: &'p Picture,
        out: &mut dyn Write,
    ) -> Result<PaintStats, PaintError> {
        let checked = check(picture)?;
        let (w, h) = (f64::from(picture.width), f64::from(picture.height));
        let tiles = Tiles::of(picture);
        let mut c = Content {
            pdf: ObjectWriter::new(out)?,
            next: 5,
            failed: None,
            width: w,
            // About 18 bytes per corner and 32 per fill: one allocation in the usual case.
            buf: Vec::with_capacity(
                picture
                    .fragments
                    .iter()
                    .map(|f| 18 * f.points.len() + 32)
                    .sum::<usize>()
                    + 256,
            ),
            d: self.options.decimals,
            cd: self.options.color_decimals,
            height: h,
            fill_alphas: BTreeSet::new(),
            stroke_alphas: BTreeSet::new(),
            meshes: Vec::new(),
            alpha: 1000,
            rgb: None,
            // Seam strokes must be opaque: not with a translucent outline's stroke state.
            seams: match checked.outline {
                Some(o) if alpha_milli(o.color[3]) < 1000 => 0.0,
                _ if picture.seams.is_finite() && picture.seams > 0.0 => picture.seams,
                _ => 0.0,
            },
            merge: picture.merge_pieces,
            stroke: None,
            outline_stroke: None,
            font: false,
            images: picture
                .textures
                .iter()
                .enumerate()
                .map(|(k, t)| match &tiles {
                    // The page image is written in tiles.
                    Some(tiles) if tiles.texture as usize == k => (Vec::new(), 0, 0),
                    _ => texture_images::rgb_rows(t),
                })
                .collect(),
            page_tiles: None,
            image_alphas: picture
                .textures
                .iter()
                .map(|t| texture_images::alpha_rows(t))
                .collect(),
            image_masks: picture
                .textures
                .iter()
                .map(|t| texture_mask::shown_rects_y_up(t))
                .collect(),
            multiply: false,
        };
        if let Some(tiles) = tiles {
            // Each tile some fragment reads, an opaque image after the textures.
            let mut images = vec![None; tiles.count()];
            for (id, used) in tiles.used(picture).into_iter().enumerate() {
                let Some(t) = tiles.texture(id).filter(|_| used) else {
                    continue;
                };
                let (rgb, iw, ih) = texture_images::plain_rgb_rows(&t);
                images[id] = Some(c.images.len());
                c.images.push((rgb, iw, ih));
                c.image_alphas.push(None);
                c.image_masks.push(None);
            }
            c.page_tiles = Some((tiles, images));
        }
        let means: Vec<[f64; 3]> = picture.textures.iter().map(|t| t.mean()).collect();
        let stats = PaintStats::default();
        if c.seams > 0.0 && checked.outline.is_none() {
            c.buf.extend_from_slice(b"1 j\n");
        }

        if let Some(o) = checked.outline {
            push_num(&mut c.buf, o.width, c.d);
            c.buf.extend_from_slice(b" w 1 J 1 j\n");
            let rgb = c.quantise([o.color[0], o.color[1], o.color[2]]);
            c.color(rgb, b"RG\n");
            c.stroke = Some((rgb, o.width.to_bits()));
            c.outline_stroke = c.stroke;
            let milli = alpha_milli(o.color[3]);
            if milli < 1000 {
                c.buf.extend_from_slice(b"/s");
                push_uint(&mut c.buf, milli.into());
                c.buf.extend_from_slice(b" gs\n");
                c.stroke_alphas.insert(milli);
            }
        }
        if let Some(bg) = picture.background {
            c.fill_alpha(alpha_milli(bg[3]));
            let rgb = c.quantise([bg[0], bg[1], bg[2]]);
            c.color(rgb, b"rg\n");
            c.rgb = Some(rgb);
            c.buf.extend_from_slice(b"0 0 ");
            push_uint(&mut c.buf, picture.width.into());
            c.buf.push(b' ');
            push_uint(&mut c.buf, picture.height.into());
            c.buf.extend_from_slice(b" re f\n");
        }

        let cd = self.options.color_decimals;
        let key = |f: &Frag<'_>| {
            let a = alpha_milli(f.alpha());
            if let Some(t) = &f.src.texture {
                // A smoothly lit run whose texture shows through takes its mean lit
                // colour (see `textured_run`).
                let fill = match f.colors {
                    Some(_) if !t.see_through() => None,
                    _ => Some(f.flat_rgb().map(|v| channel_fixed(v, cd))),
                };
                return Style::Textured(t.texture, fill, a);
            }
            match f.colors {
                Some(_) => Style::Gouraud(a),
                None => Style::Flat(f.flat_rgb().map(|v| channel_fixed(v, cd)), a),
            }
        };
        let c = RefCell::new(c);
        let stats = RefCell::new(stats);
        // Translucent Gouraud runs wait to be drawn as layers (see `layers.rs`), each one
        // shading in a transparency group; other runs disjoint from them are painted
        // first.
        let layer: RefCell<Layers<'p>> = RefCell::new(Layers::new(&picture.face_outlines));
        let flush_layer = |c: &mut Content<'_>, stats: &mut PaintStats| {
            if let Some((layers, (_, a))) = layer.borrow_mut().take() {
                c.fill_alpha(a);
                for frags in &layers {
                    c.gouraud_run(frags, true);
                    stats.paths += 1;
                }
            }
        };
        // Opaque smoothly lit textured runs: textures painted as they come, their lit
        // colours waiting here for one multiplied group (`lit_layer`) before anything
        // else is painted.
        let lit: RefCell<Vec<Frag<'p>>> = RefCell::new(Vec::new());
        let flush_lit = |c: &mut Content<'_>| {
            let mut lit = lit.borrow_mut();
            c.lit_layer(&lit);
            lit.clear();
        };
        let on_run = |run: &[Frag<'p>], style: &Style| {
            let mut c = c.borrow_mut();
            let lit_run = matches!(*style, Style::Textured(_, None, a) if a >= 1000);
            if !lit_run || !layer.borrow().clear_of(run) {
                flush_lit(&mut c);
            }
            if let Style::Gouraud(a) = *style {
                if a < 1000 && checked.outline.is_none() {
                    let key = (run[0].src.object, a);
                    if !layer.borrow_mut().join(key, run) {
                        flush_layer(&mut c, &mut stats.borrow_mut());
                        layer.borrow_mut().join(key, run);
                    }
                    return Ok(());
                }
            }
            if !layer.borrow().clear_of(run) {
                flush_layer(&mut c, &mut stats.borrow_mut());
            }
            match *style {
                Style::Flat(rgb, a) => {
                    c.fill_alpha(a);
                    c.flat_run(run, rgb);
                }
                Style::Gouraud(a) => {
                    c.fill_alpha(a);
                    c.gouraud_run(run, false);
                }
                Style::Textured(k, rgb, a) => {
                    c.fill_alpha(a);
                    let approximated = c.textured_run(run, k, rgb, means[k as usize]);
                    stats.borrow_mut().approximated += approximated;
                    if rgb.is_none() {
                        lit.borrow_mut().extend(run.iter().cloned());
                        if !lit_run || checked.outline.is_some() {
                            // Translucent: blended at once (counted as approximated);
                            // outlined: the outline goes over the lit texture.
                            flush_lit(&mut c);
                        }
                        if !lit_run {
                            stats.borrow_mut().approximated += run.len();
                        }
                    }
                }
            }
            let mut stats = stats.borrow_mut();
            stats.paths += 1;
            if checked.outline.is_some() && run.iter().any(Frag::has_outline) {
                c.outline(run);
                stats.strokes += 1;
            }
            Ok(())
        };
        let on_mark = |m: &super::Mark| {
            let mut c = c.borrow_mut();
            flush_lit(&mut c);
            flush_layer(&mut c, &mut stats.borrow_mut());
            paint_mark(m, &checked.guard, &mut *c, &mut stats.borrow_mut())
        };
        let counts = walk_with_marks(
            picture,
            &checked.guard,
            checked.runs(),
            key,
            on_run,
            on_mark,
        )?;
        let mut c = c.into_inner();
        let mut stats = stats.into_inner();
        flush_lit(&mut c);
        flush_layer(&mut c, &mut stats);
        stats.skipped += counts.skipped;
        stats.clipped += counts.clipped;

        stats.bytes = c.write_document(w, h)?;
        Ok(stats)
    }
}

/// Writes the area of `outline` (path operators, y up) filled from the page image:
/// clipped to it, each tile the fragments of `run` read, placed at its rectangle
/// (`images`: each tile's XObject index; the page is `height` high).
fn write_tiled(
    buf: &mut Vec<u8>,
    outline: &[u8],
    run: &[Frag<'_>],
    tiles: &Tiles,
    images: &[Option<usize>],
    height: f64,
    d: u8,
) {
    let mut touched = vec![false; tiles.count()];
    for f in run {
        tiles.mark(&f.points, &mut touched);
    }
    buf.extend_from_slice(b"q ");
    buf.extend_from_slice(outline);
    buf.extend_from_slice(b"W n\n");
    for id in (0..touched.len()).filter(|&id| touched[id]) {
        let Some(n) = images[id] else { continue };
        let [x, y, w, h] = tiles.rect(id);
        buf.extend_from_slice(b"q ");
        for v in [w, 0.0, 0.0, h, x, height - y - h] {
            push_num(buf, v, d + 4);
            buf.push(b' ');
        }
        buf.extend_from_slice(b"cm /Im");
        push_uint(buf, n as u64);
        buf.extend_from_slice(b" Do Q\n");
    }
    buf.extend_from_slice(b"Q\n");
}

impl Content<'_> {
    /// Finishes the document begun when painting started (its shadings written as they
    /// were made): the page, the content stream and the other resources, object by
    /// object (never whole in memory: a million-face picture's was 188 MB); returns its
    /// length in bytes, or the first error met writing a shading.
    fn write_document(mut self, w: f64, h: f64) -> std::io::Result<u64> {
        if let Some(e) = self.failed.take() {
            return Err(e);
        }
        let mut pdf = self.pdf;
        let catalog = Ref::new(1);
        let pages = Ref::new(2);
        let page = Ref::new(3);
        let content = Ref::new(4);
        let mut next = self.next - 1;
        let mut alloc = || {
            next += 1;
            Ref::new(next)
        };
        let mut states: Vec<(Vec<u8>, Ref, bool, u16)> = Vec::new();
        for &m in &self.fill_alphas {
            states.push((format!("a{m}").into_bytes(), alloc(), false, m));
        }
        for &m in &self.stroke_alphas {
            states.push((format!("s{m}").into_bytes(), alloc(), true, m));
        }
        let font = self.font.then(&mut alloc);
        // (The page image, written in tiles, is left out: see `page_tiles`.)
        let images: Vec<Option<(Vec<u8>, Ref)>> = (0..self.images.len())
            .map(|i| (self.images[i].1 > 0).then(|| (format!("Im{i}").into_bytes(), alloc())))
            .collect();
        let multiply = self.multiply.then(&mut alloc);
        let soft_masks: Vec<Option<Ref>> = self
            .image_alphas
            .iter()
            .map(|a| a.as_ref().map(|_| alloc()))
            .collect();

        pdf.object(catalog)?
            .indirect(catalog)
            .start::<Catalog>()
            .pages(pages);
        pdf.object(pages)?.pages(pages).kids([page]).count(1);
        {
            let mut p = pdf.object(page)?.page(page);
            p.media_box(Rect::new(0.0, 0.0, w as f32, h as f32));
            p.parent(pages);
            p.contents(content);
            let mut res = p.resources();
            if !states.is_empty() || multiply.is_some() {
                let mut dict = res.ext_g_states();
                for (name, r, _, _) in &states {
                    dict.pair(Name(name), *r);
                }
                if let Some(r) = multiply {
                    dict.pair(Name(b"Mul"), r);
                }
            }
            if images.iter().any(Option::is_some) || self.meshes.iter().any(|m| m.form.is_some()) {
                let mut dict = res.x_objects();
                for (name, r) in images.iter().flatten() {
                    dict.pair(Name(name), *r);
                }
                for (i, m) in self.meshes.iter().enumerate() {
                    if let Some(r) = m.form {
                        dict.pair(Name(format!("Fm{i}").as_bytes()), r);
                    }
                }
            }
            if !self.meshes.is_empty() {
                let mut dict = res.shadings();
                for (i, m) in self.meshes.iter().enumerate() {
                    dict.pair(Name(format!("Sh{i}").as_bytes()), m.shading);
                }
            }
            if let Some(f) = font {
                res.fonts().pair(Name(b"F1"), f);
            }
        }
        if let Some(f) = font {
            pdf.object(f)?
                .type1_font(f)
                .base_font(Name(b"Helvetica"))
                .encoding_predefined(Name(b"WinAnsiEncoding"));
        }
        pdf.object(content)?.stream(content, &self.buf);
        // The copy is on its way out now; give the memory back before the rest is written.
        drop(self.buf);
        drop(self.meshes);
        let (pixels, image_alphas) = (self.images, self.image_alphas);
        for ((image, (rgb, iw, ih)), soft_mask) in images.iter().zip(&pixels).zip(&soft_masks) {
            let Some((_, r)) = image else { continue };
            let data = miniz_oxide::deflate::compress_to_vec_zlib(rgb, 6);
            let mut x = pdf.object(*r)?.image_xobject(*r, &data);
            x.filter(pdf_writer::Filter::FlateDecode);
            x.width(*iw as i32);
            x.height(*ih as i32);
            x.color_space().device_rgb();
            x.bits_per_component(8);
            x.interpolate(true);
            if let Some(m) = soft_mask {
                x.s_mask(*m);
            }
        }
        // Blended textures' alpha: a grey image of the same size, interpolated as the
        // colours are.
        for ((alpha, m), (_, iw, ih)) in image_alphas.iter().zip(&soft_masks).zip(&pixels) {
            let (Some(alpha), Some(m)) = (alpha, m) else {
                continue;
            };
            let data = miniz_oxide::deflate::compress_to_vec_zlib(alpha, 6);
            let mut x = pdf.object(*m)?.image_xobject(*m, &data);
            x.filter(pdf_writer::Filter::FlateDecode);
            x.width(*iw as i32);
            x.height(*ih as i32);
            x.color_space().device_gray();
            x.bits_per_component(8);
            x.interpolate(true);
        }
        if let Some(r) = multiply {
            pdf.object(r)?
                .ext_graphics(r)
                .blend_mode(pdf_writer::types::BlendMode::Multiply);
        }
        for (_, r, stroke, m) in &states {
            let a = f32::from(*m) / 1000.0;
            let mut gs = pdf.object(*r)?.ext_graphics(*r);
            if *stroke {
                gs.stroking_alpha(a);
            } else {
                gs.non_stroking_alpha(a);
            }
        }
        pdf.finish(catalog)
    }
}

impl Content<'_> {
    /// `q`, the colour and opacity of a mark (fill or stroke).
    fn mark_begin(&mut self, color: [f64; 4], stroke: bool) {
        self.buf.extend_from_slice(b"q ");
        let rgb = self.quantise([color[0], color[1], color[2]]);
        self.color(rgb, if stroke { b"RG\n" } else { b"rg\n" });
        let milli = alpha_milli(color[3]);
        if milli < 1000 {
            self.buf
                .extend_from_slice(if stroke { b"/s" } else { b"/a" });
            push_uint(&mut self.buf, milli.into());
            self.buf.extend_from_slice(b" gs\n");
            if stroke {
                self.stroke_alphas.insert(milli);
            } else {
                self.fill_alphas.insert(milli);
            }
        }
    }
}

impl MarkSink for Content<'_> {
    fn polylines(
        &mut self,
        lines: &[Vec<[f64; 2]>],
        closed: bool,
        color: [f64; 4],
        width: f64,
        dash: &[f64],
        offset: f64,
    ) -> Result<(), PaintError> {
        self.mark_begin(color, true);
        push_num(&mut self.buf, width, self.d);
        self.buf.extend_from_slice(b" w 0 J 1 j");
        if !dash.is_empty() {
            self.buf.extend_from_slice(b" [");
            for (i, &v) in dash.iter().enumerate() {
                if i > 0 {
                    self.buf.push(b' ');
                }
                push_num(&mut self.buf, v, self.d);
            }
            self.buf.extend_from_slice(b"] ");
            push_num(&mut self.buf, offset, self.d);
            self.buf.extend_from_slice(b" d");
        }
        self.buf.push(b'\n');
        for line in lines {
            for (k, &p) in line.iter().enumerate() {
                self.point(p);
                self.buf
                    .extend_from_slice(if k == 0 { b" m " } else { b" l " });
            }
            if closed {
                self.buf.extend_from_slice(b"h ");
            }
        }
        self.buf.extend_from_slice(b"S Q\n");
        Ok(())
    }

    fn circle(
        &mut self,
        c: [f64; 2],
        r: f64,
        color: [f64; 4],
        stroke: Option<f64>,
    ) -> Result<(), PaintError> {
        self.mark_begin(color, stroke.is_some());
        if let Some(w) = stroke {
            push_num(&mut self.buf, w, self.d);
            self.buf.extend_from_slice(b" w ");
        }
        let (start, quarters) = circle_beziers(c, r);
        self.point(start);
        self.buf.extend_from_slice(b" m");
        for q in quarters {
            for p in q {
                self.buf.push(b' ');
                self.point(p);
            }
            self.buf.extend_from_slice(b" c");
        }
        self.buf.extend_from_slice(if stroke.is_some() {
            b" h S Q\n"
        } else {
            b" h f Q\n"
        });
        Ok(())
    }

    fn triangle(&mut self, points: [[f64; 2]; 3], color: [f64; 4]) -> Result<(), PaintError> {
        self.mark_begin(color, false);
        for (k, p) in points.into_iter().enumerate() {
            self.point(p);
            self.buf
                .extend_from_slice(if k == 0 { b" m " } else { b" l " });
        }
        self.buf.extend_from_slice(b"h f Q\n");
        Ok(())
    }

    fn text(&mut self, origin: [f64; 2], label: &Label) -> Result<bool, PaintError> {
        self.font = true;
        let (text, changed) = ascii_text(&label.text);
        self.mark_begin(label.color, false);
        self.buf.extend_from_slice(b"BT /F1 ");
        push_num(&mut self.buf, label.size, self.d);
        self.buf.extend_from_slice(b" Tf ");
        self.point(origin);
        self.buf.extend_from_slice(b" Td (");
        push_ps_string(&mut self.buf, &text);
        self.buf.extend_from_slice(b") Tj ET Q\n");
        Ok(changed)
    }
}

/// The bytes of a PDF or PostScript string literal's content: `(`, `)` and `\\` escaped.
pub(crate) fn push_ps_string(b: &mut Vec<u8>, text: &str) {
    for c in text.bytes() {
        if matches!(c, b'(' | b')' | b'\\') {
            b.push(b'\\');
        }
        b.push(c);
    }
}
