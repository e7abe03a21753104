//! The full-screen z-buffer.

use crate::depth::{D16Depth, D24Depth, Depth, F32Depth, F64Depth};
use crate::image::NO_FACE;
use crate::setup::Prepared;
use crate::span::TriSetup;
use crate::DepthFormat;

/// Face ids, depths and statistics of a screen-space rendering.
pub(crate) struct Buffers {
    pub ids: Vec<u32>,
    pub depths: Vec<f64>,
    pub fragments: u64,
    pub working_bytes: usize,
}

/// Rasterises the triangles in order with a depth test `stored ≤ buffer` (so among
/// equal stored depths the later face wins).
pub(crate) fn zbuffer(prep: &Prepared, width: u32, height: u32, format: DepthFormat) -> Buffers {
    match format {
        DepthFormat::F64 => run::<F64Depth>(prep, width, height),
        DepthFormat::F32 => run::<F32Depth>(prep, width, height),
        DepthFormat::D24 => run::<D24Depth>(prep, width, height),
        DepthFormat::D16 => run::<D16Depth>(prep, width, height),
    }
}

fn run<D: Depth>(prep: &Prepared, width: u32, height: u32) -> Buffers {
    let n = width as usize * height as usize;
    let mut zb = vec![D::FAR; n];
    let mut ids = vec![NO_FACE; n];
    let mut fragments = 0u64;
    for (tri, &face) in prep.tris.iter().zip(&prep.faces) {
        let [a, b, c] = tri.map(|v| prep.verts[v as usize]);
        let Some(s) = TriSetup::new(a, b, c, width, height) else {
            continue;
        };
        for row in s.row_lo..=s.row_hi {
            let base = row as usize * width as usize;
            let (zrow, irow) = (
                &mut zb[base..base + width as usize],
                &mut ids[base..base + width as usize],
            );
            s.for_each_in_row(row, 0, width, |x, d| {
                fragments += 1;
                let q = D::store(d);
                let x = x as usize;
                if q <= zrow[x] {
                    zrow[x] = q;
                    irow[x] = face;
                }
            });
        }
    }
    let depths = zb
        .iter()
        .zip(&ids)
        .map(|(&z, &id)| {
            if id == NO_FACE {
                f64::INFINITY
            } else {
                D::load(z)
            }
        })
        .collect();
    Buffers {
        ids,
        depths,
        fragments,
        working_bytes: n * (std::mem::size_of::<D::Stored>() + 4),
    }
}
