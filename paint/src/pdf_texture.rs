//! Textured fragments in PDF content streams: each affine piece (see
//! `texture_pieces.rs`) clipped to its triangle, the texture's image XObject `/ImK`
//! placed with `cm` once per repetition of the texture that the piece reaches. The
//! image carries a wrapped border (see `texture_images.rs`); each repetition is clipped
//! to its unit square grown by half a texel, so neighbouring repetitions overlap only
//! where both interpolate correctly.

use super::number::{push_num, push_uint};
use super::texture_images::PAD;
use super::texture_pieces::{push_flipped_outline, AffinePiece};

/// Writes the polygons `polys` (page coordinates y down; the page is `height` high)
/// textured under `piece`'s map: `q`, the polygons as the clip (non-zero rule), one `cm /ImK Do` per texture repetition it reaches, `Q`.
/// Returns `false`, writing nothing, when it reaches too many repetitions (see
/// [`AffinePiece::repetitions`]).
/// `padded` is the size of the embedded (padded) image.
pub(crate) fn write_clipped(
    buf: &mut Vec<u8>,
    polys: &[Vec<[f64; 2]>],
    piece: &AffinePiece,
    k: u32,
    padded: (u32, u32),
    height: f64,
    d: u8,
) -> bool {
    let (w, h) = (f64::from(padded.0 - 2 * PAD), f64::from(padded.1 - 2 * PAD));
    let (px, py) = (f64::from(PAD) / w, f64::from(PAD) / h);
    let (hx, hy) = (0.5 / w, 0.5 / h);
    let Some(tiles) = piece.repetitions() else {
        return false;
    };
    buf.extend_from_slice(b"q ");
    push_flipped_outline(buf, polys, height, d);
    buf.extend_from_slice(b"W n\n");
    for tile in tiles {
        buf.extend_from_slice(b"q ");
        AffinePiece::push_tile_matrix(buf, piece.flipped_tile_matrix(tile, height), d);
        buf.extend_from_slice(b" cm ");
        // The unit square grown by half a texel, then the padded image around it.
        for v in [-hx, -hy, 1.0 + 2.0 * hx, 1.0 + 2.0 * hy] {
            push_num(buf, v, 9);
            buf.push(b' ');
        }
        buf.extend_from_slice(b"re W n ");
        for v in [1.0 + 2.0 * px, 0.0, 0.0, 1.0 + 2.0 * py, -px, -py] {
            push_num(buf, v, 9);
            buf.push(b' ');
        }
        buf.extend_from_slice(b"cm /Im");
        push_uint(buf, k.into());
        buf.extend_from_slice(b" Do Q\n");
    }
    buf.extend_from_slice(b"Q\n");
    true
}
