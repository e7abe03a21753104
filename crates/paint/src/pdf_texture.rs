//! Textured fragments in PDF content streams: each affine piece (see
//! `texture_pieces.rs`) clipped to its triangle, the texture's image XObject `/ImK`
//! placed with `cm` once per repetition of the texture that the piece reaches. The
//! image carries a wrapped border (see `texture_images.rs`); each repetition is clipped
//! to its unit square grown by half a texel, so neighbouring repetitions overlap only
//! where both interpolate correctly.

use super::number::{push_num, push_uint};
use super::texture_images::unit_square_placement;
#[cfg(doc)]
use super::texture_pieces::push_flipped_outline;
use super::texture_pieces::AffinePiece;

/// Writes the area of `outline` (path operators on the page, y up: see
/// [`push_flipped_outline`]) textured under `piece`'s map: `q`, the outline as the clip
/// (non-zero rule), one `cm /ImK Do` per texture repetition it reaches, `Q`.
/// Returns `false`, writing nothing, when it reaches too many repetitions (see
/// [`AffinePiece::repetitions`]).
/// `padded` is the size of the embedded (padded) image; `mask` a cut-out's shown
/// texels (see `texture_mask.rs`), each repetition's clip instead of its unit square;
/// `multiply` what paints the fill multiplied over each repetition inside that clip.
#[allow(clippy::too_many_arguments)]
pub(crate) fn write_clipped(
    buf: &mut Vec<u8>,
    outline: &[u8],
    piece: &AffinePiece,
    k: u32,
    padded: (u32, u32),
    mask: Option<&[[f64; 4]]>,
    multiply: Option<&[u8]>,
    height: f64,
    d: u8,
) -> bool {
    let (clip, place) = unit_square_placement(padded.0, padded.1);
    let Some(tiles) = piece.repetitions() else {
        return false;
    };
    buf.extend_from_slice(b"q ");
    buf.extend_from_slice(outline);
    buf.extend_from_slice(b"W n\n");
    for tile in tiles {
        buf.extend_from_slice(b"q ");
        AffinePiece::push_tile_matrix(buf, piece.flipped_tile_matrix(tile, height), d);
        buf.extend_from_slice(b" cm ");
        // The unit square grown by half a texel (a cut-out: its shown texels, an empty
        // rectangle when none shows), then the padded image around it.
        let rects = match mask {
            None => std::slice::from_ref(&clip),
            Some([]) => &[[0.0; 4]],
            Some(m) => m,
        };
        for r in rects {
            for v in r {
                push_num(buf, *v, 9);
                buf.push(b' ');
            }
            buf.extend_from_slice(b"re ");
        }
        buf.extend_from_slice(b"W n ");
        for v in place {
            push_num(buf, v, 9);
            buf.push(b' ');
        }
        buf.extend_from_slice(b"cm /Im");
        push_uint(buf, k.into());
        buf.extend_from_slice(b" Do");
        if let Some(m) = multiply {
            buf.push(b' ');
            buf.extend_from_slice(m);
        }
        buf.extend_from_slice(b" Q\n");
    }
    buf.extend_from_slice(b"Q\n");
    true
}
