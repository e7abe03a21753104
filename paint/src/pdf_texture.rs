//! Textured fragments in PDF content streams: each affine piece (see
//! `texture_pieces.rs`) clipped to its triangle, the texture's image XObject `/ImK`
//! placed with `cm` once per repetition of the texture that the piece reaches. The
//! image carries a wrapped border (see `texture_images.rs`); each repetition is clipped
//! to its unit square grown by half a texel, so neighbouring repetitions overlap only
//! where both interpolate correctly.

use super::number::{push_num, push_uint};
use super::texture_images::PAD;
use super::texture_pieces::AffinePiece;

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
    let [a, b, c, dd, e, f] = piece.st_to_page;
    let Some(tiles) = piece.repetitions() else {
        return false;
    };
    let point = |buf: &mut Vec<u8>, p: [f64; 2]| {
        push_num(buf, p[0], d);
        buf.push(b' ');
        push_num(buf, height - p[1], d);
    };
    buf.extend_from_slice(b"q ");
    for poly in polys {
        for (i, &p) in poly.iter().enumerate() {
            point(buf, p);
            buf.extend_from_slice(if i == 0 { b" m " } else { b" l " });
        }
        buf.extend_from_slice(b"h ");
    }
    buf.extend_from_slice(b"W n\n");
    for (i, j) in tiles {
        // The image fills the unit square, its first row at the top: unit point (u, v)
        // is texture point (i + u, j + 1 − v); then y flips for PDF.
        let ex = a * i + c * (j + 1.0) + e;
        let fy = b * i + dd * (j + 1.0) + f;
        buf.extend_from_slice(b"q ");
        for v in [a, -b, -c, dd] {
            push_num(buf, v, d + 4);
            buf.push(b' ');
        }
        push_num(buf, ex, d + 2);
        buf.push(b' ');
        push_num(buf, height - fy, d + 2);
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
