//! The scan-line z-buffer: one row of depth at a time.
//!
//! The *edge table* lists triangles by the first row they may cover; the *active table*
//! holds the triangles (with their three edges) that cross the current row. For each row
//! the active triangles' spans are found from the edges that cross the row's centre
//! line, exactly as the full z-buffer finds them (same edge tests, same incremental
//! depth from the span's first pixel), and depth-tested into a single row of depth, so
//! the face ids are identical to the full z-buffer's. Ties between equal stored depths
//! go to the later triangle in input order, as in the full z-buffer.

use crate::depth::{D16Depth, D24Depth, Depth, F32Depth, F64Depth};
use crate::image::NO_FACE;
use crate::setup::Prepared;
use crate::span::TriSetup;
use crate::zbuf::Buffers;
use crate::DepthFormat;

/// Renders row by row; `working_bytes` counts the row buffers, the edge table and the
/// largest active table.
pub(crate) fn scanline(prep: &Prepared, width: u32, height: u32, format: DepthFormat) -> Buffers {
    match format {
        DepthFormat::F64 => run::<F64Depth>(prep, width, height),
        DepthFormat::F32 => run::<F32Depth>(prep, width, height),
        DepthFormat::D24 => run::<D24Depth>(prep, width, height),
        DepthFormat::D16 => run::<D16Depth>(prep, width, height),
    }
}

fn run<D: Depth>(prep: &Prepared, width: u32, height: u32) -> Buffers {
    // Edge table: (first row, triangle), sorted by row then triangle.
    let mut table: Vec<(u32, u32)> = Vec::with_capacity(prep.tris.len());
    for (t, tri) in prep.tris.iter().enumerate() {
        let ys = tri.map(|v| prep.verts[v as usize].y);
        let ymin = ys[0].min(ys[1]).min(ys[2]);
        let ymax = ys[0].max(ys[1]).max(ys[2]);
        // Rows whose centre can be in [ymin, ymax]; the setup decides exactly.
        if !(ymax >= 0.0 && ymin <= height as f64) {
            continue;
        }
        let first = ((ymin - 0.5).ceil() - 1.0).max(0.0) as u32;
        table.push((first, t as u32));
    }
    table.sort_unstable();
    let w = width as usize;
    let mut zrow = vec![D::FAR; w];
    let mut trow = vec![u32::MAX; w];
    let mut ids = vec![NO_FACE; w * height as usize];
    let mut depths = vec![f64::INFINITY; w * height as usize];
    let mut active: Vec<(u32, TriSetup)> = Vec::new();
    let mut max_active = 0;
    let mut next = 0;
    let mut fragments = 0u64;
    for row in 0..height {
        active.retain(|(_, s)| s.row_hi >= row);
        while next < table.len() && table[next].0 <= row {
            let t = table[next].1;
            next += 1;
            let [a, b, c] = prep.tris[t as usize].map(|v| prep.verts[v as usize]);
            if let Some(s) = TriSetup::new(a, b, c, width, height) {
                if s.row_hi >= row {
                    active.push((t, s));
                }
            }
        }
        max_active = max_active.max(active.len());
        zrow.fill(D::FAR);
        trow.fill(u32::MAX);
        for (t, s) in &active {
            let t = *t;
            s.for_each_in_row(row, 0, width, |x, d| {
                fragments += 1;
                let q = D::store(d);
                let x = x as usize;
                let z = zrow[x];
                if q < z || (q == z && (trow[x] == u32::MAX || t > trow[x])) {
                    zrow[x] = q;
                    trow[x] = t;
                }
            });
        }
        let base = row as usize * w;
        for x in 0..w {
            if trow[x] != u32::MAX {
                ids[base + x] = prep.faces[trow[x] as usize];
                depths[base + x] = D::load(zrow[x]);
            }
        }
    }
    let working_bytes = w * (std::mem::size_of::<D::Stored>() + 4)
        + table.capacity() * std::mem::size_of::<(u32, u32)>()
        + max_active * std::mem::size_of::<(u32, TriSetup)>();
    Buffers {
        ids,
        depths,
        fragments,
        working_bytes,
    }
}
