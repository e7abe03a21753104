//! Textured fragments in SVG (see the module docs of `svg.rs` for the markup).

use std::collections::HashMap;

use super::number::{push_hex_color, push_num, push_uint, rgb_u8};
use super::runs::{reversals, Frag};
use super::texture_page::{run_underlay, Tiles};
use super::texture_pieces::{pieces_over, AffinePiece};
use super::{merge, svg_smooth_run, texture_images, texture_mask, PaintError, Texture};

/// Ids handed out while writing: clip paths and colour filters.
#[derive(Default)]
pub(crate) struct SvgTextures {
    /// The picture's page image in tiles (`<image id="pgN">`), if it has one.
    pub tiles: Option<Tiles>,
    clips: u64,
    /// Fill colour → the id number of its `<filter id="mN">`.
    filters: HashMap<[u8; 3], usize>,
    /// Pieces filled with a mean colour (too many repetitions).
    pub approximated: usize,
}

/// Writes the `<defs>` of the textures (nothing when there are none): each texture
/// once, but the page image (`tiles`, with the flags of the tiles drawn) as its tiles
/// drawn, `<image id="pgN">` each placed on the page.
pub(crate) fn write_defs(
    b: &mut Vec<u8>,
    textures: &[std::sync::Arc<Texture>],
    tiles: Option<(&Tiles, &[bool])>,
) -> Result<(), PaintError> {
    if textures.is_empty() {
        return Ok(());
    }
    let unencodable = || PaintError::Style {
        what: "texture",
        reason: "the image cannot be encoded as PNG",
    };
    b.extend_from_slice(b"<defs>\n");
    if let Some((tiles, used)) = tiles {
        for id in (0..tiles.count()).filter(|&id| used[id]) {
            let uri = tiles
                .texture(id)
                .and_then(|t| texture_images::plain_png_data_uri(&t))
                .ok_or_else(unencodable)?;
            b.extend_from_slice(b"<image id=\"pg");
            push_uint(b, id as u64);
            b.push(b'"');
            rect_attrs(b, tiles.rect(id));
            b.extend_from_slice(
                b" preserveAspectRatio=\"none\" style=\"image-rendering:smooth\" href=\"",
            );
            b.extend_from_slice(uri.as_bytes());
            b.extend_from_slice(b"\"/>\n");
        }
    }
    for (k, t) in textures.iter().enumerate() {
        if tiles.is_some_and(|(tiles, _)| tiles.texture as usize == k) {
            continue;
        }
        let uri = texture_images::png_data_uri(t).ok_or_else(unencodable)?;
        // The padded image: its inner texels fill the unit square of texture space;
        // each repetition is clipped to that square grown by half a texel.
        let (tw, th) = (f64::from(t.width()), f64::from(t.height()));
        let pad = f64::from(texture_images::PAD);
        let (px, py) = (pad / tw, pad / th);
        b.extend_from_slice(b"<image id=\"tex");
        push_uint(b, k as u64);
        b.push(b'"');
        rect_attrs(b, [-px, -py, 1.0 + 2.0 * px, 1.0 + 2.0 * py]);
        b.extend_from_slice(
            b" preserveAspectRatio=\"none\" style=\"image-rendering:smooth\" href=\"",
        );
        b.extend_from_slice(uri.as_bytes());
        b.extend_from_slice(b"\"/>\n<clipPath id=\"unit");
        push_uint(b, k as u64);
        match texture_mask::shown_rects(t) {
            // A cut-out: its shown texels, edge to edge.
            Some(rects) => {
                b.extend_from_slice(b"\"><path d=\"");
                for [x, y, w, h] in rects {
                    b.push(b'M');
                    push_num(b, x, 9);
                    b.push(b' ');
                    push_num(b, y, 9);
                    b.push(b'h');
                    push_num(b, w, 9);
                    b.push(b'v');
                    push_num(b, h, 9);
                    b.push(b'h');
                    push_num(b, -w, 9);
                    b.push(b'Z');
                }
                b.extend_from_slice(b"\"/></clipPath>\n");
            }
            None => {
                b.extend_from_slice(b"\"><rect");
                rect_attrs(b, [-0.5 / tw, -0.5 / th, 1.0 + 1.0 / tw, 1.0 + 1.0 / th]);
                b.extend_from_slice(b"/></clipPath>\n");
            }
        }
    }
    b.extend_from_slice(b"</defs>\n");
    Ok(())
}

/// Appends polygons as SVG path data (`M x y L x y x y … Z` each).
fn push_path_data(b: &mut Vec<u8>, polys: &[Vec<[f64; 2]>], d: u8) {
    for poly in polys {
        for (i, p) in poly.iter().enumerate() {
            b.push(match i {
                0 => b'M',
                1 => b'L',
                _ => b' ',
            });
            push_num(b, p[0], d);
            b.push(b' ');
            push_num(b, p[1], d);
        }
        b.push(b'Z');
    }
}

/// Whether a run's texture lets what is behind show through (its alpha is drawn).
pub(crate) fn see_through(run: &[Frag<'_>]) -> bool {
    run.iter()
        .any(|f| f.src.texture.as_ref().is_some_and(|t| t.see_through()))
}

/// ` x="…" y="…" width="…" height="…"`.
fn rect_attrs(b: &mut Vec<u8>, r: [f64; 4]) {
    for (name, v) in [&b" x=\""[..], b"\" y=\"", b"\" width=\"", b"\" height=\""]
        .iter()
        .zip(r)
    {
        b.extend_from_slice(name);
        push_num(b, v, 9);
    }
    b.push(b'"');
}

impl SvgTextures {
    /// Nothing written yet; the picture's page image in `tiles`, if it has one.
    pub fn new(tiles: Option<Tiles>) -> Self {
        SvgTextures {
            tiles,
            ..SvgTextures::default()
        }
    }

    /// Writes a run of textured fragments with texture `k` (opacity in thousandths,
    /// `mean` the texture's mean colour); returns the number of elements drawn.
    /// Fragments with vertex colours (smoothly lit) get no colour filter: their smooth
    /// fill is multiplied over the texture (`mix-blend-mode:multiply`), here when `lit`
    /// (the smooth tolerance and the gradient counter) is given (inside the group, a
    /// translucent run's), else by the caller over a batch of runs. With `merge`, a run
    /// drawn from the page image is clipped to its union (see [`crate::merge`]).
    #[allow(clippy::too_many_arguments)]
    pub fn run(
        &mut self,
        b: &mut Vec<u8>,
        run: &[Frag<'_>],
        k: u32,
        alpha: u16,
        mean: [f64; 3],
        d: u8,
        merge: bool,
        lit: Option<(f64, &mut u64)>,
    ) -> usize {
        let rgb = rgb_u8(run[0].flat_rgb());
        // Fill times texture: a colour matrix over the group (exact at every pixel,
        // edges included, and the alpha kept). A smoothly lit run whose texture lets
        // what is behind show through takes its mean lit colour so (a multiplied smooth
        // fill would colour its transparent parts): counted as approximated.
        let smooth = run.iter().any(|f| f.colors.is_some());
        let see_through = see_through(run);
        if smooth && see_through {
            self.approximated += run.len();
        }
        let filter = (rgb != [255; 3] && (!smooth || see_through)).then(|| {
            let next = self.filters.len();
            let id = *self.filters.entry(rgb).or_insert(next);
            if id == next {
                b.extend_from_slice(b"<filter id=\"m");
                push_uint(b, id as u64);
                b.extend_from_slice(
                    b"\" color-interpolation-filters=\"sRGB\"><feColorMatrix values=\"",
                );
                for (i, c) in rgb.iter().enumerate() {
                    for j in 0..5 {
                        if i + j > 0 {
                            b.push(b' ');
                        }
                        if i == j {
                            push_num(b, f64::from(*c) / 255.0, 4);
                        } else {
                            b.push(b'0');
                        }
                    }
                }
                b.extend_from_slice(b" 0 0 0 1 0\"/></filter>\n");
            }
            id
        });
        b.extend_from_slice(b"<g");
        if alpha < 1000 {
            b.extend_from_slice(b" opacity=\"");
            super::number::push_milli(b, alpha);
            b.push(b'"');
        }
        if let Some(id) = filter {
            b.extend_from_slice(b" filter=\"url(#m");
            push_uint(b, id as u64);
            b.extend_from_slice(b")\"");
        }
        b.extend_from_slice(b">\n");
        let mut drawn = 0;
        // Under the pieces, the whole run (fragments and seam flaps, one clip path, so
        // their shared edges are covered at once) under one affine map, the first fan
        // triangle's: the anti-aliased edges between pieces then show nearly the same
        // texels, not the page.
        let polys: Vec<Vec<[f64; 2]>> = run
            .iter()
            .zip(reversals(run))
            .map(|(f, reverse)| f.oriented(reverse).collect())
            .collect();
        let (whole, one_map) = run_underlay(run, see_through);
        // Fragments drawn from the page image share one affine map (see
        // `texture_page.rs`): the whole run is all there is to draw, its outline their
        // union (the edges between them are then not in the clip).
        // The page image (see `texture_page.rs`) is drawn from its tiles, never under a
        // map of its own.
        let paged = self.tiles.as_ref().is_some_and(|t| t.texture == k);
        let shared = (paged || whole.is_some()) && one_map;
        if paged || whole.is_some() {
            let mut outline = Vec::new();
            match (shared && merge)
                .then(|| merge::union(run, d, |p| p))
                .flatten()
            {
                Some(shapes) => merge::push_svg_rings(&mut outline, shapes.iter().flatten(), d),
                None => push_path_data(&mut outline, &polys, d),
            }
            drawn += match &whole {
                _ if paged => self.tiled(b, &outline, run),
                Some(whole) => self.clipped(b, &outline, whole, k, mean, d),
                None => 0,
            };
        }
        for f in run.iter().filter(|_| !shared && !paged) {
            let Some(map) = &f.src.texture else { continue };
            for p in pieces_over(&f.points, map, whole.as_ref(), run.len() == 1) {
                let mut outline = Vec::new();
                push_path_data(&mut outline, std::slice::from_ref(&p.points), d);
                drawn += self.clipped(b, &outline, &p, k, mean, d);
            }
        }
        if let Some((tolerance, gradients)) = lit.filter(|_| !see_through) {
            // The lit colours as the untextured face's smooth fill, multiplied over the
            // texture inside the group (blended once with the opacity).
            b.extend_from_slice(b"<g style=\"mix-blend-mode:multiply\">\n");
            drawn += svg_smooth_run::write(b, run, 1000, tolerance, d, gradients, false);
            b.extend_from_slice(b"</g>\n");
        }
        b.extend_from_slice(b"</g>\n");
        drawn
    }

    /// The path data `outline` (non-zero rule) clipped out of the page image: the tiles
    /// the fragments of `run` read.
    fn tiled(&mut self, b: &mut Vec<u8>, outline: &[u8], run: &[Frag<'_>]) -> usize {
        let Some(tiles) = &self.tiles else { return 0 };
        let mut touched = vec![false; tiles.count()];
        for f in run {
            tiles.mark(&f.points, &mut touched);
        }
        b.extend_from_slice(b"<clipPath id=\"tc");
        push_uint(b, self.clips);
        b.extend_from_slice(b"\"><path d=\"");
        b.extend_from_slice(outline);
        b.extend_from_slice(b"\"/></clipPath>\n<g clip-path=\"url(#tc");
        push_uint(b, self.clips);
        b.extend_from_slice(b")\">\n");
        for id in (0..touched.len()).filter(|&id| touched[id]) {
            b.extend_from_slice(b"<use href=\"#pg");
            push_uint(b, id as u64);
            b.extend_from_slice(b"\"/>\n");
        }
        b.extend_from_slice(b"</g>\n");
        self.clips += 1;
        1
    }

    /// The path data `outline` (non-zero rule) clipped out of the texture placed by
    /// `piece`'s map (one `<use>` per repetition `piece` reaches), or filled with the
    /// mean colour when it reaches too many repetitions.
    fn clipped(
        &mut self,
        b: &mut Vec<u8>,
        outline: &[u8],
        piece: &AffinePiece,
        k: u32,
        mean: [f64; 3],
        d: u8,
    ) -> usize {
        let path = |b: &mut Vec<u8>| b.extend_from_slice(outline);
        let Some(tiles) = piece.repetitions() else {
            b.extend_from_slice(b"<path d=\"");
            path(b);
            b.extend_from_slice(b"\" fill=\"");
            push_hex_color(b, rgb_u8(mean));
            b.extend_from_slice(b"\"/>\n");
            self.approximated += 1;
            return 1;
        };
        b.extend_from_slice(b"<clipPath id=\"tc");
        push_uint(b, self.clips);
        b.extend_from_slice(b"\"><path d=\"");
        path(b);
        b.extend_from_slice(b"\"/></clipPath>\n<g clip-path=\"url(#tc");
        push_uint(b, self.clips);
        b.extend_from_slice(b")\">\n");
        let [ma, mb, mc, md, me, mf] = piece.st_to_page;
        for (i, j) in tiles {
            b.extend_from_slice(b"<use href=\"#tex");
            push_uint(b, k.into());
            b.extend_from_slice(b"\" transform=\"matrix(");
            let m = [ma, mb, mc, md, ma * i + mc * j + me, mb * i + md * j + mf];
            for (n, v) in m.iter().enumerate() {
                if n > 0 {
                    b.push(b' ');
                }
                // The linear part scales the unit square up to the page: more decimals.
                push_num(b, *v, if n < 4 { d + 4 } else { d + 2 });
            }
            b.extend_from_slice(b")\" clip-path=\"url(#unit");
            push_uint(b, k.into());
            b.extend_from_slice(b")\"/>\n");
        }
        b.extend_from_slice(b"</g>\n");
        self.clips += 1;
        1
    }
}
