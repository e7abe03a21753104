//! Wrap modes other than repetition, drawn as repetition of a larger texture.
//!
//! Every painter samples a texture by repetition (see [`crate::texture`]). A texture
//! sampled with other wrap modes — glTF `MIRRORED_REPEAT` and `CLAMP_TO_EDGE`, chosen
//! per axis, and MTL `-clamp on` — is turned, once per material, into a texture that
//! gives the same bilinear samples under repetition, with the material's texture
//! coordinates moved onto it (each axis by `u = a·s + b`). Face boundaries do not
//! change; only the colours that fill them.
//!
//! * **Mirrored repeat** along an axis: the image followed by its mirror image (twice
//!   as many texels), read at `u = s / 2`. Texel `W + k` of the doubled image is texel
//!   `W − 1 − k`, so bilinear sampling under repetition is that of the mirrored
//!   sampler, also across the seams (where a texel meets its own copy).
//! * **Clamp to edge** along an axis: the image with `E₀` copies of its first texel
//!   column (row) before it and `E₁` copies of its last after it, read at
//!   `u = (s·W + E₀) / (W + E₀ + E₁)`. The copies are chosen so that every coordinate the
//!   material's faces reach, `s ∈ [s₀, s₁]`, lies at least half a texel inside the
//!   larger image: there the bilinear neighbours of repetition are those of the
//!   clamped sampler (outside `[0, 1]` the edge texels extend: a stretched strip of the
//!   edge column or row, the corner texel beyond both). The larger the reach beyond
//!   `[0, 1]`, the larger the image: [`MAX_GROWTH`] bounds it.

use std::sync::Arc;

use thiserror::Error;

use crate::texture::check_texture_size;
use crate::{Scene, Texture};

/// How a texture is sampled outside `[0, 1]` along one axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Wrap {
    /// Repeated (glTF `REPEAT`, the default of glTF and OBJ).
    #[default]
    Repeat,
    /// Repeated with every other repetition mirrored (glTF `MIRRORED_REPEAT`).
    MirroredRepeat,
    /// The edge texels extended (glTF `CLAMP_TO_EDGE`, MTL `-clamp on`).
    ClampToEdge,
}

/// The most texels the repeating form of a clamped or mirrored texture may have, as a
/// multiple of the texture's own (or 2^16 texels, if more).
pub const MAX_GROWTH: u64 = 16;

/// Why a texture's wrap modes cannot be drawn.
#[derive(Debug, Error, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum WrapError {
    /// The repeating form would exceed [`MAX_GROWTH`] or the texture size limits
    /// (texture coordinates reach far beyond `[0, 1]` under clamping).
    #[error(
        "drawing the wrap modes needs a texture of {width} × {height} texels (coordinates \
         reach far outside [0, 1])"
    )]
    TooLarge {
        /// Width of the repeating form.
        width: u32,
        /// Height of the repeating form.
        height: u32,
    },
}

/// One axis of the repeating form: texel sources and the coordinate map.
struct Axis {
    /// Per texel of the repeating form, the texel of the texture it copies.
    source: Vec<u32>,
    /// `u = a·s + b`.
    map: [f64; 2],
}

impl Axis {
    /// The axis of `n` texels under `wrap`, for coordinates in `range` (`None`: no
    /// finite coordinate).
    fn new(n: u32, wrap: Wrap, range: Option<[f64; 2]>) -> Axis {
        match wrap {
            Wrap::Repeat => Axis {
                source: (0..n).collect(),
                map: [1.0, 0.0],
            },
            Wrap::MirroredRepeat => Axis {
                source: (0..n).chain((0..n).rev()).collect(),
                map: [0.5, 0.0],
            },
            Wrap::ClampToEdge => {
                let w = f64::from(n);
                let [lo, hi] = range.unwrap_or([0.0, 1.0]);
                // Texel index x = s·W + E₀ − ½ must stay in [0, W + E₀ + E₁ − 1).
                let before = (0.5 - lo * w).ceil().clamp(0.0, f64::from(u32::MAX));
                let after = ((hi - 1.0) * w + 0.5).floor() + 1.0;
                let after = after.clamp(0.0, f64::from(u32::MAX));
                let (e0, e1) = (before as u64, after as u64);
                let total = u64::from(n) + e0 + e1;
                // Beyond the size limits the caller refuses it before anything is built.
                if total > u64::from(crate::texture::MAX_TEXTURE_SIDE) {
                    return Axis {
                        source: Vec::new(),
                        map: [0.0, total as f64],
                    };
                }
                let source = std::iter::repeat_n(0, e0 as usize)
                    .chain(0..n)
                    .chain(std::iter::repeat_n(n - 1, e1 as usize))
                    .collect();
                let t = total as f64;
                Axis {
                    source,
                    map: [w / t, e0 as f64 / t],
                }
            }
        }
    }

    /// Texels of the repeating form along this axis (beyond the size limits, the
    /// number that would be needed).
    fn len(&self) -> u64 {
        if self.source.is_empty() {
            self.map[1] as u64
        } else {
            self.source.len() as u64
        }
    }
}

/// Per axis `[a, b]`: texture coordinates `s` move to `u = a·s + b`.
pub type CoordinateMaps = [[f64; 2]; 2];

/// The repeating form of `texture` under `wrap` (along s, then t) for texture
/// coordinates within `ranges` (per axis `[min, max]` of the finite coordinates; `None`
/// when there are none), and the maps `u = a·s + b` of the coordinates onto it, per
/// axis `[a, b]`. `Ok(None)` when both axes repeat.
pub fn repeating_form(
    texture: &Texture,
    wrap: [Wrap; 2],
    ranges: [Option<[f64; 2]>; 2],
) -> Result<Option<(Texture, CoordinateMaps)>, WrapError> {
    if wrap == [Wrap::Repeat; 2] {
        return Ok(None);
    }
    let (w, h) = (texture.width(), texture.height());
    let xs = Axis::new(w, wrap[0], ranges[0]);
    let ys = Axis::new(h, wrap[1], ranges[1]);
    let (nw, nh) = (xs.len(), ys.len());
    let limit = (MAX_GROWTH * u64::from(w) * u64::from(h)).max(1 << 16);
    let too_large = WrapError::TooLarge {
        width: nw.min(u64::from(u32::MAX)) as u32,
        height: nh.min(u64::from(u32::MAX)) as u32,
    };
    if nw.saturating_mul(nh) > limit || xs.source.is_empty() || ys.source.is_empty() {
        return Err(too_large);
    }
    let (nw, nh) = (nw as u32, nh as u32);
    if check_texture_size(nw, nh).is_err() {
        return Err(too_large);
    }
    let src = texture.rgba();
    let mut rgba = Vec::with_capacity(4 * nw as usize * nh as usize);
    for &j in &ys.source {
        let row = j as usize * w as usize;
        for &i in &xs.source {
            let at = 4 * (row + i as usize);
            rgba.extend_from_slice(&src[at..at + 4]);
        }
    }
    let t = Texture::new(texture.name(), nw, nh, rgba)
        .map_err(|_| too_large)?
        .with_alpha(texture.alpha());
    Ok(Some((t, [xs.map, ys.map])))
}

/// Draws the texture of scene material `material` under `wrap`: replaces it by its
/// repeating form (see the module docs) and moves the texture coordinates of the
/// material's faces onto it. Those coordinates must not be shared with faces of other
/// materials. Returns whether anything changed (both axes repeating: nothing to do).
pub fn wrap_material_texture(
    scene: &mut Scene,
    material: u32,
    wrap: [Wrap; 2],
) -> Result<bool, WrapError> {
    let Some(texture) = scene
        .materials
        .get(material as usize)
        .and_then(|m| m.texture.clone())
    else {
        return Ok(false);
    };
    let mut used: Vec<u32> = scene
        .faces
        .iter()
        .filter(|f| f.material == material)
        .filter_map(|f| f.texcoords.as_ref())
        .flatten()
        .copied()
        .collect();
    used.sort_unstable();
    used.dedup();
    let mut ranges: [Option<[f64; 2]>; 2] = [None; 2];
    for &i in &used {
        let st = scene.texcoords[i as usize];
        for k in 0..2 {
            if st[k].is_finite() {
                let r = ranges[k].get_or_insert([st[k], st[k]]);
                r[0] = r[0].min(st[k]);
                r[1] = r[1].max(st[k]);
            }
        }
    }
    let Some((form, maps)) = repeating_form(&texture, wrap, ranges)? else {
        return Ok(false);
    };
    for &i in &used {
        let st = &mut scene.texcoords[i as usize];
        for k in 0..2 {
            st[k] = maps[k][0] * st[k] + maps[k][1];
        }
    }
    scene.materials[material as usize].texture = Some(Arc::new(form));
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A texture whose texel (i, j) has red i and green j.
    fn ramp(w: u32, h: u32) -> Texture {
        let mut rgba = Vec::new();
        for j in 0..h {
            for i in 0..w {
                rgba.extend_from_slice(&[
                    (i as u8).wrapping_mul(10),
                    (j as u8).wrapping_mul(10),
                    0,
                    255,
                ]);
            }
        }
        Texture::new("r", w, h, rgba).unwrap()
    }

    /// The mirrored or clamped sampler written directly: bilinear between texel
    /// centres, each neighbour's index wrapped by the mode.
    fn reference(t: &Texture, wrap: [Wrap; 2], st: [f64; 2]) -> [f64; 3] {
        let index = |i: i64, n: i64, w: Wrap| match w {
            Wrap::Repeat => i.rem_euclid(n),
            Wrap::ClampToEdge => i.clamp(0, n - 1),
            Wrap::MirroredRepeat => {
                let m = i.rem_euclid(2 * n);
                if m < n {
                    m
                } else {
                    2 * n - 1 - m
                }
            }
        };
        let (w, h) = (i64::from(t.width()), i64::from(t.height()));
        let x = st[0] * w as f64 - 0.5;
        let y = st[1] * h as f64 - 0.5;
        let (fx, fy) = (x.floor(), y.floor());
        let (ax, ay) = (x - fx, y - fy);
        let texel = |i: i64, j: i64| t.texel(index(i, w, wrap[0]), index(j, h, wrap[1]));
        let (i, j) = (fx as i64, fy as i64);
        let (c00, c10, c01, c11) = (
            texel(i, j),
            texel(i + 1, j),
            texel(i, j + 1),
            texel(i + 1, j + 1),
        );
        [0, 1, 2].map(|k| {
            let top = c00[k] + (c10[k] - c00[k]) * ax;
            let bottom = c01[k] + (c11[k] - c01[k]) * ax;
            top + (bottom - top) * ay
        })
    }

    #[test]
    fn the_repeating_form_samples_as_the_wrap_modes() {
        let t = ramp(3, 2);
        let modes = [Wrap::Repeat, Wrap::MirroredRepeat, Wrap::ClampToEdge];
        let range = [-1.3, 2.6];
        for ws in modes {
            for wt in modes {
                let Some((form, maps)) =
                    repeating_form(&t, [ws, wt], [Some(range), Some(range)]).unwrap()
                else {
                    assert_eq!([ws, wt], [Wrap::Repeat; 2]);
                    continue;
                };
                for a in 0..=60 {
                    for b in 0..=60 {
                        let st = [
                            -1.3 + 3.9 * f64::from(a) / 60.0,
                            -1.3 + 3.9 * f64::from(b) / 60.0,
                        ];
                        let u = [0, 1].map(|k| maps[k][0] * st[k] + maps[k][1]);
                        let got = form.sample(u);
                        let want = reference(&t, [ws, wt], st);
                        for k in 0..3 {
                            assert!(
                                (got[k] - want[k]).abs() < 1e-9,
                                "{ws:?}/{wt:?} at {st:?}: {got:?} vs {want:?}"
                            );
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn clamping_far_outside_is_refused() {
        let t = ramp(64, 64);
        let far = Some([-100.0, 100.0]);
        assert!(matches!(
            repeating_form(&t, [Wrap::ClampToEdge, Wrap::Repeat], [far, None]),
            Err(WrapError::TooLarge { .. })
        ));
        // Both axes beyond every size: refused, no overflow counting the texels.
        let huge = Some([-1e12, 1e12]);
        assert!(matches!(
            repeating_form(&t, [Wrap::ClampToEdge; 2], [huge, huge]),
            Err(WrapError::TooLarge { .. })
        ));
        let near = Some([-0.5, 1.5]);
        let (form, _) = repeating_form(&t, [Wrap::ClampToEdge; 2], [near, near])
            .unwrap()
            .unwrap();
        assert_eq!((form.width(), form.height()), (130, 130));
    }
}
