//! The A-buffer: fragments are kept per pixel in a list; lists are sorted by depth and
//! composited front to back.
//!
//! A fragment strictly behind an opaque fragment already in its pixel's list can never
//! show and is not stored (that keeps opaque scenes to a few fragments per pixel).
//!
//! Each fragment carries its face's flat colour (`shade_face`) and the material's
//! opacity as alpha. Compositing is front to back with the *under* operator,
//! `C += T · α · c`, `T ·= 1 − α`, stopping at the first opaque fragment; what light
//! is left, `T`, shows the background. This is the same result as painting the same
//! fragments back to front with *over*. Among fragments of equal stored depth the later
//! face is in front (the painter's rule for coplanar faces). The face id and depth
//! images show the nearest fragment.

use crate::image::NO_FACE;
use crate::setup::Prepared;
use crate::span::TriSetup;
use crate::{DepthFormat, ZError};

/// Per-face flat colour and opacity (in [0, 1]).
pub(crate) struct FaceLook<'a> {
    pub color: &'a dyn Fn(u32) -> [f64; 3],
    pub alpha: &'a dyn Fn(u32) -> f64,
}

/// Result of the A-buffer: ids, depths, linear colours.
pub(crate) struct ABuffer {
    pub ids: Vec<u32>,
    pub depths: Vec<f64>,
    pub colors: Vec<[f64; 3]>,
    pub fragments: u64,
    pub working_bytes: usize,
}

struct Fragment {
    depth: f64,
    tri: u32,
    next: u32,
}

const END: u32 = u32::MAX;

/// Renders with per-pixel fragment lists. Fails only when more fragments must be kept
/// than 32-bit indices can address.
pub(crate) fn abuffer(
    prep: &Prepared,
    width: u32,
    height: u32,
    format: DepthFormat,
    background: [f64; 3],
    look: &FaceLook<'_>,
) -> Result<ABuffer, ZError> {
    let n = width as usize * height as usize;
    let mut heads = vec![END; n];
    // Nearest opaque depth stored at each pixel.
    let mut front = vec![f64::INFINITY; n];
    let mut frags: Vec<Fragment> = Vec::new();
    let mut full = false;
    for (t, (tri, &face)) in prep.tris.iter().zip(&prep.faces).enumerate() {
        let [a, b, c] = tri.map(|v| prep.verts[v as usize]);
        let Some(s) = TriSetup::new(a, b, c, width, height) else {
            continue;
        };
        let opaque = (look.alpha)(face) >= 1.0;
        for row in s.row_lo..=s.row_hi {
            let base = row as usize * width as usize;
            s.for_each_in_row(row, 0, width, |x, d| {
                let i = base + x as usize;
                let depth = format.round_trip(d);
                // Equal depth: this later fragment is in front, so it stays.
                if depth > front[i] {
                    return;
                }
                if opaque {
                    front[i] = depth;
                }
                if frags.len() >= END as usize {
                    full = true;
                    return;
                }
                frags.push(Fragment {
                    depth,
                    tri: t as u32,
                    next: heads[i],
                });
                heads[i] = (frags.len() - 1) as u32;
            });
        }
    }
    if full {
        return Err(ZError::TooManyFragments);
    }
    drop(front);
    let mut colors_of: Vec<Option<[f64; 3]>> = Vec::new();
    let mut ids = vec![NO_FACE; n];
    let mut depths = vec![f64::INFINITY; n];
    let mut colors = vec![background; n];
    let mut list: Vec<(f64, u32)> = Vec::new();
    for i in 0..n {
        list.clear();
        let mut f = heads[i];
        while f != END {
            let fr = &frags[f as usize];
            list.push((fr.depth, fr.tri));
            f = fr.next;
        }
        if list.is_empty() {
            continue;
        }
        // Nearest first; among equal depths the later triangle first.
        list.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(b.1.cmp(&a.1)));
        ids[i] = prep.faces[list[0].1 as usize];
        depths[i] = list[0].0;
        let mut acc = [0.0; 3];
        let mut trans = 1.0;
        for &(_, t) in &list {
            let face = prep.faces[t as usize];
            if colors_of.len() <= face as usize {
                colors_of.resize(face as usize + 1, None);
            }
            let color = *colors_of[face as usize].get_or_insert_with(|| (look.color)(face));
            let alpha = (look.alpha)(face);
            for (a, c) in acc.iter_mut().zip(color) {
                *a += trans * alpha * c;
            }
            trans *= 1.0 - alpha;
            if alpha >= 1.0 {
                break;
            }
        }
        for (a, b) in acc.iter_mut().zip(background) {
            *a += trans * b;
        }
        colors[i] = acc;
    }
    Ok(ABuffer {
        ids,
        depths,
        colors,
        fragments: frags.len() as u64,
        working_bytes: n * 4 + frags.capacity() * std::mem::size_of::<Fragment>(),
    })
}
