//! A cut-out texture's shown texels as rectangles, the clip the vector writers draw its
//! image through (see [`limn_scene::TextureAlpha::Mask`]).
//!
//! A cut-out is decided per texel: a point shows exactly when the texel it lies in
//! shows, so the shown part of one repetition of the texture is a union of texel
//! squares, whose edges lie on the lines `s = i / W` and `t = j / H`. The vector
//! writers clip each repetition's image to it (where an opaque texture is clipped to its
//! unit square grown by half a texel), so their boundary is where the PNG painter puts
//! it, hard-edged, and the colours inside are the opaque image's, as the PNG painter
//! samples them. The rectangles are runs of shown texels along a row, each carried down
//! the rows below while they hold the same run: a solid region is a few rectangles, a
//! texel-by-texel pattern one per run.

use limn_scene::{Texture, TextureAlpha};

/// The shown texels of cut-out `t` as rectangles `[x, y, width, height]` in its unit
/// square (`x = i / W`, `y = j / H`); `None` when `t` is not a cut-out. An empty list:
/// no texel shows.
pub(crate) fn shown_rects(t: &Texture) -> Option<Vec<[f64; 4]>> {
    if t.alpha() != TextureAlpha::Mask {
        return None;
    }
    let (w, h) = (t.width() as usize, t.height() as usize);
    let shows = |i: usize, j: usize| t.rgba()[4 * (j * w + i) + 3] != 0;
    // Runs open from the row above: (first, end, first row).
    let mut open: Vec<(usize, usize, usize)> = Vec::new();
    let mut rects: Vec<[usize; 4]> = Vec::new();
    for j in 0..=h {
        let mut runs = Vec::new();
        if j < h {
            let mut i = 0;
            while i < w {
                if shows(i, j) {
                    let first = i;
                    while i < w && shows(i, j) {
                        i += 1;
                    }
                    runs.push((first, i));
                } else {
                    i += 1;
                }
            }
        }
        // Both lists run left to right: a run continues an open one with the same ends.
        let mut next = Vec::with_capacity(runs.len());
        let mut k = 0;
        for &(a, b) in &runs {
            while k < open.len() && open[k].0 < a {
                rects.push([open[k].0, open[k].2, open[k].1, j]);
                k += 1;
            }
            if k < open.len() && (open[k].0, open[k].1) == (a, b) {
                next.push(open[k]);
                k += 1;
            } else {
                next.push((a, b, j));
            }
        }
        for &(a, b, top) in &open[k..] {
            rects.push([a, top, b, j]);
        }
        open = next;
    }
    rects.sort_unstable_by_key(|r| (r[1], r[0]));
    let (fw, fh) = (w as f64, h as f64);
    Some(
        rects
            .into_iter()
            .map(|[i0, j0, i1, j1]| {
                let x = i0 as f64 / fw;
                let y = j0 as f64 / fh;
                [x, y, i1 as f64 / fw - x, j1 as f64 / fh - y]
            })
            .collect(),
    )
}

/// [`shown_rects`] with `y` running up (PDF and PostScript place an image's first row
/// at the top of its unit square): `[x, 1 − y − height, width, height]`.
pub(crate) fn shown_rects_y_up(t: &Texture) -> Option<Vec<[f64; 4]>> {
    let mut rects = shown_rects(t)?;
    for r in &mut rects {
        r[1] = 1.0 - r[1] - r[3];
    }
    Some(rects)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mask(w: u32, h: u32, shown: &[(u32, u32)]) -> Texture {
        let mut rgba = vec![200u8; 4 * (w * h) as usize];
        for px in rgba.chunks_exact_mut(4) {
            px[3] = 0;
        }
        for &(i, j) in shown {
            rgba[4 * (j * w + i) as usize + 3] = 255;
        }
        Texture::new("m", w, h, rgba)
            .unwrap()
            .with_alpha(TextureAlpha::Mask)
    }

    #[test]
    fn runs_join_down_the_rows_and_cover_exactly_the_shown_texels() {
        // 4 × 3: a 2 × 2 block at the left, one texel alone at the right.
        let t = mask(4, 3, &[(0, 0), (1, 0), (0, 1), (1, 1), (3, 2)]);
        let rects = shown_rects(&t).unwrap();
        assert_eq!(
            rects,
            vec![
                [0.0, 0.0, 0.5, 2.0 / 3.0],
                [0.75, 2.0 / 3.0, 0.25, 1.0 - 2.0 / 3.0]
            ]
        );
        // Every texel centre is inside a rectangle exactly when its texel shows.
        for j in 0..3 {
            for i in 0..4 {
                let c = [(f64::from(i) + 0.5) / 4.0, (f64::from(j) + 0.5) / 3.0];
                let inside = rects.iter().any(|r| {
                    c[0] > r[0] && c[0] < r[0] + r[2] && c[1] > r[1] && c[1] < r[1] + r[3]
                });
                assert_eq!(inside, t.texel_alpha(i.into(), j.into()) == 1.0, "{i} {j}");
            }
        }
    }

    #[test]
    fn only_cut_outs_have_rectangles() {
        let t = mask(2, 1, &[]);
        assert_eq!(shown_rects(&t), Some(vec![]));
        let opaque = Texture::new("o", 1, 1, vec![1, 2, 3, 255]).unwrap();
        assert_eq!(shown_rects(&opaque), None);
        // The top row of two, y up: the upper half of the square.
        let top = mask(1, 2, &[(0, 0)]);
        assert_eq!(shown_rects_y_up(&top), Some(vec![[0.0, 0.5, 1.0, 0.5]]));
    }
}
