//! Screen bins of the occluders' bounding boxes: which occluders may overlap a box on the
//! screen. Pruning only: a box is grown by a margin, so a float error costs work and never
//! drops an occluder that overlaps.

use crate::geom::Box2;

/// Cells per side of the grid.
const CELLS: usize = 64;

/// A uniform grid over the occluders' boxes.
pub(crate) struct Bins {
    area: Box2,
    cell_w: f64,
    cell_h: f64,
    cells: Vec<Vec<u32>>,
    /// Occluders whose box is not finite (they may overlap anything).
    everywhere: Vec<u32>,
    boxes: Vec<Box2>,
}

/// The margin added to every box: relative to the coordinates' size, and at least a
/// thousandth of a pixel.
pub(crate) fn margin(b: &Box2) -> f64 {
    let m = b
        .min_x
        .abs()
        .max(b.max_x.abs())
        .max(b.min_y.abs())
        .max(b.max_y.abs());
    1e-3 + m * 1e-9
}

fn finite(b: &Box2) -> bool {
    b.min_x.is_finite() && b.min_y.is_finite() && b.max_x.is_finite() && b.max_y.is_finite()
}

impl Bins {
    /// Bins the boxes (one per occluder, in occluder order).
    pub(crate) fn new(boxes: Vec<Box2>) -> Bins {
        let boxes: Vec<Box2> = boxes.iter().map(|b| b.grown(margin(b))).collect();
        let area = boxes
            .iter()
            .filter(|b| finite(b))
            .fold(Box2::EMPTY, |a, b| a.union(b));
        let cell_w = (area.width() / CELLS as f64).max(f64::MIN_POSITIVE);
        let cell_h = (area.height() / CELLS as f64).max(f64::MIN_POSITIVE);
        let mut bins = Bins {
            area,
            cell_w,
            cell_h,
            cells: vec![Vec::new(); CELLS * CELLS],
            everywhere: Vec::new(),
            boxes: Vec::new(),
        };
        for (i, b) in boxes.iter().enumerate() {
            if !finite(b) {
                bins.everywhere.push(i as u32);
                continue;
            }
            let (x0, x1, y0, y1) = bins.range(b);
            for y in y0..=y1 {
                for x in x0..=x1 {
                    bins.cells[y * CELLS + x].push(i as u32);
                }
            }
        }
        bins.boxes = boxes;
        bins
    }

    fn cell(&self, v: f64, lo: f64, size: f64) -> usize {
        let c = ((v - lo) / size).floor();
        if c.is_nan() || c < 0.0 {
            0
        } else {
            (c as usize).min(CELLS - 1)
        }
    }

    fn range(&self, b: &Box2) -> (usize, usize, usize, usize) {
        (
            self.cell(b.min_x, self.area.min_x, self.cell_w),
            self.cell(b.max_x, self.area.min_x, self.cell_w),
            self.cell(b.min_y, self.area.min_y, self.cell_h),
            self.cell(b.max_y, self.area.min_y, self.cell_h),
        )
    }

    /// The occluders whose (grown) box meets `query` (grown too), each once, in
    /// increasing order; every occluder when `query` is not finite.
    pub(crate) fn query(&self, query: &Box2) -> Vec<u32> {
        if !finite(query) {
            return (0..self.boxes.len() as u32).collect();
        }
        let q = query.grown(margin(query));
        let meets = |i: u32| {
            let b = &self.boxes[i as usize];
            b.min_x <= q.max_x && q.min_x <= b.max_x && b.min_y <= q.max_y && q.min_y <= b.max_y
        };
        let mut out: Vec<u32> = self
            .everywhere
            .iter()
            .copied()
            .filter(|&i| meets(i))
            .collect();
        if finite(&self.area)
            && q.max_x >= self.area.min_x
            && q.min_x <= self.area.max_x
            && q.max_y >= self.area.min_y
            && q.min_y <= self.area.max_y
        {
            let (x0, x1, y0, y1) = self.range(&q);
            for y in y0..=y1 {
                for x in x0..=x1 {
                    out.extend(
                        self.cells[y * CELLS + x]
                            .iter()
                            .copied()
                            .filter(|&i| meets(i)),
                    );
                }
            }
        }
        out.sort_unstable();
        out.dedup();
        out
    }
}
