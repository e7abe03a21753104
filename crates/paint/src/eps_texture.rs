//! Textured fragments in EPS: the texture images defined once in the prolog, and each
//! affine piece (see `texture_pieces.rs`) clipped to its triangle with the image drawn
//! under the piece's map once per repetition of the texture it reaches.
//!
//! ```text
//! /td0 [ <a0b1c2…> <…> … ] def           the padded RGB rows, one hex string each
//! /T0{gsave concat -hx -hy sx sy rectclip [… padded placement …] concat /ti 0 def
//!   << /ImageType 1 … /Decode D /DataSource {td0 ti get /ti ti 1 add def}
//!      /Interpolate true >> image grestore}def
//! /D [0 r 0 g 0 b] def                   per run: the fill, applied by the image itself
//! gsave x y m x y l x y l h clip newpath [a b c d e f] T0 … grestore
//! ```
//!
//! The rows are an array of strings (one string per row: a PostScript string holds at
//! most 65,535 bytes, and a padded row at most 3 × 16,386), read in turn by a procedure
//! `DataSource` whose counter each drawing resets: the data is written once per texture
//! and reused by every piece (LanguageLevel 2). Hex rather than ASCII85 strings: twice
//! the bytes of the image, but the image is written once while each piece costs more
//! than a row; hex needs no encoder of its own.
//!
//! The fill multiplies the texture through `/Decode [lo_r hi_r lo_g hi_g lo_b hi_b]`:
//! sample `v` (0–255) is drawn as `lo + v/255 · (hi − lo)`. Opaque: `lo = 0`, `hi` the
//! fill, exactly `fill × texture`. Translucent with opacity `a` over the backdrop `B`
//! (EPS has no opacity, see `eps.rs`): `lo = (1 − a)·B`, `hi = lo + a·fill`, the same
//! flattening flat fills get (and counted as approximated likewise).
//!
//! The image carries a wrapped border (see `texture_images.rs`); each repetition is
//! clipped to its unit square grown by half a texel, as in PDF, or a cut-out's to its
//! shown texels (`[x y w h …] rectclip`, see `texture_mask.rs`). PostScript has no soft
//! alpha: a blended texture is drawn opaque (counted as approximated).

use super::number::{push_num, push_uint};
use super::texture_images::unit_square_placement;
use super::texture_pieces::{push_flipped_outline, AffinePiece};

/// Writes the prolog's definitions for texture `k`: its padded RGB rows `rgb` (`w` ×
/// `h`, rows top to bottom) as `/tdK` and the drawing procedure `/TK` (see the module
/// docs). `/TK` takes the matrix from the unit square of one repetition to the page.
/// A cut-out's shown texels `mask` (see `texture_mask.rs`) are its clip instead of the
/// unit square.
pub(crate) fn write_definition(
    buf: &mut Vec<u8>,
    k: u32,
    rgb: &[u8],
    (w, h): (u32, u32),
    mask: Option<&[[f64; 4]]>,
) {
    const HEX: &[u8; 16] = b"0123456789abcdef";
    buf.extend_from_slice(b"/td");
    push_uint(buf, k.into());
    buf.extend_from_slice(b" [\n");
    for row in rgb.chunks_exact(3 * w as usize) {
        buf.push(b'<');
        // Lines of at most 255 characters (DSC).
        for (i, &v) in row.iter().enumerate() {
            if i > 0 && i % 120 == 0 {
                buf.push(b'\n');
            }
            buf.push(HEX[usize::from(v >> 4)]);
            buf.push(HEX[usize::from(v & 15)]);
        }
        buf.extend_from_slice(b">\n");
    }
    buf.extend_from_slice(b"] def\n");
    let (clip, place) = unit_square_placement(w, h);
    buf.extend_from_slice(b"/T");
    push_uint(buf, k.into());
    buf.extend_from_slice(b"{gsave concat ");
    // The unit square grown by half a texel (a cut-out: its shown texels, as an array
    // of rectangles), then the padded image around it.
    match mask {
        None => {
            for v in clip {
                push_num(buf, v, 9);
                buf.push(b' ');
            }
        }
        Some(rects) => {
            buf.push(b'[');
            for (i, v) in rects.iter().flatten().enumerate() {
                if i > 0 {
                    buf.push(if i % 16 == 0 { b'\n' } else { b' ' });
                }
                push_num(buf, *v, 9);
            }
            if rects.is_empty() {
                buf.extend_from_slice(b"0 0 0 0");
            }
            buf.extend_from_slice(b"] ");
        }
    }
    buf.extend_from_slice(b"rectclip [");
    for v in place {
        push_num(buf, v, 9);
        buf.push(b' ');
    }
    buf.extend_from_slice(b"] concat /DeviceRGB setcolorspace /ti 0 def\n<< /ImageType 1 /Width ");
    push_uint(buf, w.into());
    buf.extend_from_slice(b" /Height ");
    push_uint(buf, h.into());
    buf.extend_from_slice(b" /BitsPerComponent 8 /Decode D /ImageMatrix [");
    push_uint(buf, w.into());
    buf.extend_from_slice(b" 0 0 -");
    push_uint(buf, h.into());
    buf.extend_from_slice(b" 0 ");
    push_uint(buf, h.into());
    buf.extend_from_slice(b"] /DataSource {td");
    push_uint(buf, k.into());
    buf.extend_from_slice(b" ti get /ti ti 1 add def} /Interpolate true >> image grestore}def\n");
}

/// Writes the polygons `polys` (page coordinates y down; the page is `height` high)
/// textured with texture `k` under `piece`'s map: `gsave`, the polygons as the clip
/// (non-zero rule), one `[…] TK` per texture repetition it reaches, `grestore`.
/// Returns `false`, writing nothing, when it reaches too many repetitions (see
/// [`AffinePiece::repetitions`]).
pub(crate) fn write_clipped(
    buf: &mut Vec<u8>,
    polys: &[Vec<[f64; 2]>],
    piece: &AffinePiece,
    k: u32,
    height: f64,
    d: u8,
) -> bool {
    let Some(tiles) = piece.repetitions() else {
        return false;
    };
    buf.extend_from_slice(b"gsave ");
    push_flipped_outline(buf, polys, height, d);
    buf.extend_from_slice(b"clip newpath\n");
    for tile in tiles {
        buf.push(b'[');
        AffinePiece::push_tile_matrix(buf, piece.flipped_tile_matrix(tile, height), d);
        buf.extend_from_slice(b"] T");
        push_uint(buf, k.into());
        buf.push(b'\n');
    }
    buf.extend_from_slice(b"grestore\n");
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_are_hex_strings_and_the_procedure_names_the_texture() {
        let rgb: Vec<u8> = (0..2 * 3 * 3).map(|v| v as u8 * 15).collect();
        let mut b = Vec::new();
        write_definition(&mut b, 4, &rgb, (3, 2), None);
        let s = String::from_utf8(b).unwrap();
        assert!(s.starts_with("/td4 [\n<000f1e2d3c4b5a6978>\n<8796a5b4c3d2e1f0ff>\n] def\n"));
        assert!(s.contains("/T4{gsave concat"));
        assert!(s.contains("/Width 3 /Height 2"));
        assert!(s.contains("/ImageMatrix [3 0 0 -2 0 2]"));
        assert!(s.contains("{td4 ti get /ti ti 1 add def}"));
    }

    #[test]
    fn a_piece_is_clipped_and_drawn_once_per_repetition() {
        // Texture space [0, 2] × [0, 1] onto a page triangle: two repetitions.
        let piece = AffinePiece {
            points: vec![[0.0, 0.0], [20.0, 0.0], [0.0, 10.0]],
            st_to_page: [10.0, 0.0, 0.0, 10.0, 0.0, 0.0],
        };
        let mut b = Vec::new();
        let tri = [piece.points.clone()];
        assert!(write_clipped(&mut b, &tri, &piece, 0, 10.0, 2));
        let s = String::from_utf8(b).unwrap();
        assert!(s.starts_with("gsave 0 10 m 20 10 l 0 0 l h clip newpath\n"));
        assert_eq!(s.matches("] T0\n").count(), 2, "{s}");
        assert!(s.ends_with("grestore\n"));
        // A degenerate map draws nothing.
        let flat = AffinePiece {
            st_to_page: [0.0; 6],
            ..piece.clone()
        };
        let mut b = Vec::new();
        assert!(!write_clipped(&mut b, &tri, &flat, 0, 10.0, 2));
        assert!(b.is_empty());
    }
}
