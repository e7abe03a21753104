//! Faces drawn from samples on the page: a small face whose texture map is far from
//! square (a sliver of texture space, each texel stretched hundreds of pixels one way
//! and squeezed the other) draws an image aligned with the page instead of its texture.
//!
//! Viewers resample an image to the page at the lengths of its transformed axes before
//! clipping it: a 14 × 14-texel patch whose texels cover 200 pixels each costs them
//! 2,800 × 2,800 pixels for a face of five (poppler spent most of a Duck's time there).
//! The page-aligned image holds the face's texture sampled at the centre of each page
//! pixel around it (as the PNG painter samples: perspective-correct, bilinear, alpha
//! included), so its pixels are those of the texture and the viewer's cost is the
//! face's size. Cut-out textures are not baked: their boundary follows their texels.

use limn_scene::Texture;

use crate::TextureMap;

/// A face is drawn from page samples when its image would cost a viewer more than this
/// many times the pixels of the face's box.
pub(crate) const BAKE_RATIO: f64 = 16.0;

/// Faces whose box (with its flaps) holds more pixels than this keep their texture.
pub(crate) const MAX_BAKED_PX: f64 = 4096.0;

/// Whether a fan triangle at page points `page` whose image `size` (texels) is placed
/// by the texel-to-page linear part `[a11, a12, a21, a22]` is better drawn from page
/// samples, `reach` pixels around it included (see the module docs).
pub(crate) fn worth_baking(
    page: [[f64; 2]; 3],
    size: (u32, u32),
    texel_to_page: [f64; 4],
    reach: f64,
) -> bool {
    let [a11, a12, a21, a22] = texel_to_page;
    let axes = f64::from(size.0) * a11.hypot(a21) * f64::from(size.1) * a12.hypot(a22);
    let [x0, y0, x1, y1] = page_box(page, reach);
    let area = (x1 - x0) * (y1 - y0);
    area <= MAX_BAKED_PX && axes > BAKE_RATIO * area
}

/// The whole pixels around `page` grown by `reach`: `[x0, y0, x1, y1]`.
fn page_box(page: [[f64; 2]; 3], reach: f64) -> [f64; 4] {
    let lo = [0, 1].map(|k| page.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min));
    let hi = [0, 1].map(|k| page.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max));
    [
        (lo[0] - reach).floor(),
        (lo[1] - reach).floor(),
        (hi[0] + reach).ceil(),
        (hi[1] + reach).ceil(),
    ]
}

/// The page-aligned image of `texture` under `map` (texture index and page-to-texture
/// map) over the pixels around `page` (grown by `reach`), one texel per page pixel
/// sampled at its centre, and its page-to-image map (texture index left to the
/// caller); `None` where the map is undefined at a sample.
pub(crate) fn bake(
    texture: &Texture,
    map: &TextureMap,
    page: [[f64; 2]; 3],
    reach: f64,
) -> Option<(Texture, [[f64; 3]; 3])> {
    let [x0, y0, x1, y1] = page_box(page, reach);
    let (w, h) = ((x1 - x0) as u32, (y1 - y0) as u32);
    let mut rgba = Vec::with_capacity(4 * (w * h) as usize);
    for j in 0..h {
        for i in 0..w {
            let st = map.st_at([x0 + f64::from(i) + 0.5, y0 + f64::from(j) + 0.5])?;
            let c = texture.sample_rgba(st);
            rgba.extend(c.map(|v| (v * 255.0).round() as u8));
        }
    }
    let name = format!("{} (page samples)", texture.name());
    // A blended texture's alpha is sampled with its colour (cut-outs are not baked:
    // their boundary stays on their texels).
    let baked = Texture::new(&name, w, h, rgba)
        .ok()?
        .with_alpha(texture.alpha());
    let (fw, fh) = (f64::from(w), f64::from(h));
    let to_image = [
        [1.0 / fw, 0.0, -x0 / fw],
        [0.0, 1.0 / fh, -y0 / fh],
        [0.0, 0.0, 1.0],
    ];
    Some((baked, to_image))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::TextureAlpha;

    #[test]
    fn a_baked_image_holds_the_texture_at_pixel_centres() {
        let rgba = (0..64u32)
            .flat_map(|k| [(k * 4) as u8, (255 - k * 3) as u8, (k * 7 % 256) as u8, 255])
            .collect();
        let t = Texture::new("t", 8, 8, rgba).unwrap();
        // A sliver: s runs fast along x, t slowly along y.
        let map = TextureMap {
            texture: 0,
            screen_to_st: [[0.05, 0.01, 0.0], [0.0, 0.002, 0.1], [0.0, 0.0, 1.0]],
            alpha: TextureAlpha::Opaque,
        };
        let page = [[10.2, 20.5], [14.7, 21.0], [12.0, 25.9]];
        let (baked, to_image) = bake(&t, &map, page, 2.0).unwrap();
        assert_eq!((baked.width(), baked.height()), (9, 10));
        let moved = TextureMap {
            texture: 0,
            screen_to_st: to_image,
            alpha: TextureAlpha::Opaque,
        };
        for p in [[12.5, 22.5], [9.5, 19.5], [16.5, 27.5]] {
            let want = t.sample(map.st_at(p).unwrap());
            let got = baked.sample(moved.st_at(p).unwrap());
            for k in 0..3 {
                assert!(
                    (want[k] - got[k]).abs() <= 0.5 / 255.0 + 1e-12,
                    "{want:?} {got:?}"
                );
            }
        }
        // Texels far longer one way than the other on a small face: baked; a face
        // showing a square texel: not.
        assert!(worth_baking(
            page,
            (14, 14),
            [200.0, 190.0, 210.0, 200.0],
            2.0
        ));
        assert!(!worth_baking(page, (14, 14), [1.0, 0.0, 0.0, 1.0], 2.0));
    }
}
