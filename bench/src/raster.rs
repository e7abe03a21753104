//! Counting wrong pixels: any program's SVG rasterised without anti-aliasing, each pixel
//! read back as the face its colour names, compared with exact ray casting outside the
//! edge band.

use limn_zbuffer::{IdImage, Mask, NO_FACE};

use crate::scenes::face_of;

/// What a rasterised picture shows at each pixel (`None`: background or an unknown
/// colour), row by row.
pub fn faces_shown(svg: &[u8], w: u32, h: u32) -> Result<Vec<Option<u32>>, String> {
    let text = std::str::from_utf8(svg).map_err(|_| "the SVG is not UTF-8".to_string())?;
    // Every program's SVG gets the same treatment: no anti-aliasing.
    let text = text.replacen("<svg ", "<svg shape-rendering=\"crispEdges\" ", 1);
    let opts = resvg::usvg::Options::default();
    let tree = resvg::usvg::Tree::from_str(&text, &opts).map_err(|e| e.to_string())?;
    let mut pixmap =
        resvg::tiny_skia::Pixmap::new(w, h).ok_or_else(|| "no pixel buffer".to_string())?;
    // Scale the SVG's own size to the picture (peers may write pt or another size).
    let size = tree.size();
    let t =
        resvg::tiny_skia::Transform::from_scale(w as f32 / size.width(), h as f32 / size.height());
    resvg::render(&tree, t, &mut pixmap.as_mut());
    Ok(pixmap
        .pixels()
        .iter()
        .map(|p| {
            if p.alpha() < 255 {
                return None;
            }
            face_of([p.red(), p.green(), p.blue()])
        })
        .collect())
}

/// Pixels outside `band` where `shown` differs from ray casting's `reference`; faces
/// at or above `faces` count as unknown colours.
pub fn wrong_pixels(
    shown: &[Option<u32>],
    reference: &IdImage,
    band: &Mask,
    faces: usize,
) -> usize {
    let (w, h) = (reference.width, reference.height);
    let mut wrong = 0;
    for y in 0..h {
        for x in 0..w {
            if band.get(x, y) {
                continue;
            }
            let want = reference.get(x, y).filter(|&id| id != NO_FACE);
            let got = shown[(y * w + x) as usize].filter(|&f| (f as usize) < faces);
            if got != want {
                wrong += 1;
            }
        }
    }
    wrong
}
