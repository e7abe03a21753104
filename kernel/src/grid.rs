//! Quantisation of world positions onto a uniform integer grid.
//!
//! The grid has the same power-of-two step on all three axes, so rotations by 90°,
//! mirrors and translations by whole steps map grid points to grid points exactly.

use glam::DVec3;

use crate::KernelError;

/// Default number of bits per axis of the grid.
///
/// With 26 bits a grid coordinate has magnitude at most `2^25 + 1`, a difference of two
/// grid coordinates at most `2^26 + 2`. Plane normals are cross products of such
/// differences (`< 2^55`) and offsets are `< 2^83`; the sign of a plane at the
/// intersection of three such planes is then a sum of products below `2^253`, which fits
/// 256-bit fixed-width integers (`ethnum::I256`) with room to spare. On a 1 m scene the
/// step is `2^-26` m (about 15 nm).
pub const DEFAULT_BITS: u32 = 26;

/// Largest number of bits per axis the coefficient bounds allow.
pub const MAX_BITS: u32 = 26;

/// Smallest number of bits per axis accepted.
pub const MIN_BITS: u32 = 2;

/// Largest magnitude of a "far" grid coordinate (the eye): `a·x + b·y + c·z + d` then stays
/// below `2^119` and is evaluated exactly in `i128`.
pub const FAR_LIMIT: i64 = 1 << 62;

/// A point of the integer grid. Coordinates are in grid steps from the grid origin.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct GridPoint {
    /// x in grid steps.
    pub x: i64,
    /// y in grid steps.
    pub y: i64,
    /// z in grid steps.
    pub z: i64,
}

impl GridPoint {
    /// A grid point from its coordinates.
    pub const fn new(x: i64, y: i64, z: i64) -> GridPoint {
        GridPoint { x, y, z }
    }

    /// The coordinates as an array `[x, y, z]`.
    pub const fn to_array(self) -> [i64; 3] {
        [self.x, self.y, self.z]
    }

    /// A grid point from an array `[x, y, z]`.
    pub const fn from_array(a: [i64; 3]) -> GridPoint {
        GridPoint {
            x: a[0],
            y: a[1],
            z: a[2],
        }
    }
}

/// Maps world positions to grid points and back.
///
/// Invariants (established by [`Quantizer::new`]): `step` is a positive normal power of
/// two; `origin` is a multiple of `step`; the box given to `new` snaps into coordinates of
/// magnitude at most `2^(bits-1) + 1`.
#[derive(Debug, Clone, PartialEq)]
pub struct Quantizer {
    origin: DVec3,
    step: f64,
    inv_step: f64,
    bits: u32,
    lo: [i64; 3],
    hi: [i64; 3],
}

/// The smallest power of two `>= x` for a positive normal finite `x`.
fn next_pow2(x: f64) -> f64 {
    let bits = x.to_bits();
    let exp = bits >> 52;
    let mant = bits & ((1u64 << 52) - 1);
    let exp = if mant == 0 { exp } else { exp + 1 };
    f64::from_bits(exp << 52)
}

impl Quantizer {
    /// A grid of `bits` bits per axis covering the box `[lo, hi]`.
    ///
    /// The step is the smallest power of two with `2^bits · step >= extent`, where the
    /// extent is the largest side of the box. A box of zero extent (a single point) gets the
    /// step of a box of side `max(1, |centre|)`. Errors: non-finite corners
    /// ([`KernelError::NonFinite`]); `lo > hi` on some axis, an extent whose step would be
    /// subnormal or infinite ([`KernelError::BadExtent`]); `bits` outside
    /// [`MIN_BITS`]`..=`[`MAX_BITS`] ([`KernelError::BadBits`]).
    pub fn new(lo: DVec3, hi: DVec3, bits: u32) -> Result<Quantizer, KernelError> {
        if !(MIN_BITS..=MAX_BITS).contains(&bits) {
            return Err(KernelError::BadBits(bits));
        }
        for p in [lo, hi] {
            if !p.is_finite() {
                return Err(KernelError::NonFinite(p.x, p.y, p.z));
            }
        }
        let size = hi - lo;
        if size.min_element() < 0.0 {
            return Err(KernelError::BadExtent(size.min_element()));
        }
        let mut extent = size.max_element();
        if !extent.is_finite() {
            return Err(KernelError::BadExtent(extent));
        }
        let centre = lo * 0.5 + hi * 0.5;
        if extent == 0.0 {
            extent = centre.abs().max_element().max(1.0);
        }
        let cells = (1u64 << bits) as f64;
        let raw = extent / cells;
        if !raw.is_normal() {
            return Err(KernelError::BadExtent(extent));
        }
        let step = next_pow2(raw);
        let inv_step = 1.0 / step;
        if !step.is_normal() || !inv_step.is_normal() {
            return Err(KernelError::BadExtent(extent));
        }
        let round_to_step = |c: f64| {
            let t = c * inv_step;
            if t.abs() < 4_503_599_627_370_496.0 {
                t.round() * step
            } else {
                // Already a multiple of the step (its ulp is at least the step).
                c
            }
        };
        let origin = DVec3::new(
            round_to_step(centre.x),
            round_to_step(centre.y),
            round_to_step(centre.z),
        );
        let mut q = Quantizer {
            origin,
            step,
            inv_step,
            bits,
            lo: [0; 3],
            hi: [0; 3],
        };
        let limit = (1i64 << (bits - 1)) + 1;
        let glo = q
            .snap_limited(lo, limit)
            .ok_or(KernelError::BadExtent(extent))?;
        let ghi = q
            .snap_limited(hi, limit)
            .ok_or(KernelError::BadExtent(extent))?;
        q.lo = glo.to_array();
        q.hi = ghi.to_array();
        Ok(q)
    }

    /// Snaps `p` to the nearest grid point if every coordinate is within `limit` steps of
    /// the origin.
    fn snap_limited(&self, p: DVec3, limit: i64) -> Option<GridPoint> {
        let t = (p - self.origin) * self.inv_step;
        let lim = limit as f64;
        let mut out = [0i64; 3];
        for (o, v) in out.iter_mut().zip(t.to_array()) {
            let r = v.round();
            // NaN fails both comparisons and is rejected here too.
            if r.is_nan() || r.abs() > lim {
                return None;
            }
            *o = r as i64;
        }
        Some(GridPoint::from_array(out))
    }

    /// Snaps a point of the scene to the nearest grid point.
    ///
    /// Errors: [`KernelError::NonFinite`] for NaN or infinite coordinates,
    /// [`KernelError::OutsideGrid`] when the snapped point lies outside the snapped box.
    pub fn snap(&self, p: DVec3) -> Result<GridPoint, KernelError> {
        if !p.is_finite() {
            return Err(KernelError::NonFinite(p.x, p.y, p.z));
        }
        let outside = KernelError::OutsideGrid(p.x, p.y, p.z);
        let g = self
            .snap_limited(p, (1i64 << (self.bits - 1)) + 1)
            .ok_or(outside.clone())?;
        let a = g.to_array();
        if (0..3).any(|i| a[i] < self.lo[i] || a[i] > self.hi[i]) {
            return Err(outside);
        }
        Ok(g)
    }

    /// Snaps a point that may lie far outside the box (such as the eye) to the grid.
    /// Coordinates may reach `limit` steps from the origin (at most [`FAR_LIMIT`]).
    ///
    /// Errors: [`KernelError::NonFinite`], or [`KernelError::TooFar`] beyond the limit.
    pub fn snap_far(&self, p: DVec3, limit: i64) -> Result<GridPoint, KernelError> {
        if !p.is_finite() {
            return Err(KernelError::NonFinite(p.x, p.y, p.z));
        }
        self.snap_limited(p, limit.min(FAR_LIMIT))
            .ok_or(KernelError::TooFar(p.x, p.y, p.z))
    }

    /// The world position of a grid point (exact while `origin + g·step` is representable;
    /// otherwise within half an ulp of it).
    pub fn world(&self, g: GridPoint) -> DVec3 {
        self.world_f([g.x as f64, g.y as f64, g.z as f64])
    }

    /// The world position of a point given in (fractional) grid coordinates.
    pub fn world_f(&self, g: [f64; 3]) -> DVec3 {
        self.origin + DVec3::from_array(g) * self.step
    }

    /// The grid step in scene units (a power of two).
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The largest distance between a point of the box and the grid point it snaps to:
    /// half the diagonal of a grid cell, `step · √3 / 2`.
    pub fn max_snap_error(&self) -> f64 {
        self.step * 3f64.sqrt() * 0.5
    }

    /// Bits per axis.
    pub fn bits(&self) -> u32 {
        self.bits
    }

    /// The world position of grid point (0, 0, 0).
    pub fn origin(&self) -> DVec3 {
        self.origin
    }

    /// The snapped corners of the box (lowest and highest grid coordinates accepted by
    /// [`Quantizer::snap`]).
    pub fn grid_box(&self) -> (GridPoint, GridPoint) {
        (
            GridPoint::from_array(self.lo),
            GridPoint::from_array(self.hi),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_box_has_expected_step() {
        let q = Quantizer::new(DVec3::ZERO, DVec3::ONE, 26).unwrap();
        assert_eq!(q.step(), 2f64.powi(-26));
        assert!(q.max_snap_error() < 1.3e-8);
        let (lo, hi) = q.grid_box();
        assert_eq!(lo.x, -(1 << 25));
        assert_eq!(hi.x, 1 << 25);
    }

    #[test]
    fn zero_extent_box_is_usable() {
        let p = DVec3::new(3.0, 3.0, 3.0);
        let q = Quantizer::new(p, p, 26).unwrap();
        assert!(q.step() > 0.0);
        assert!(q.snap(p).is_ok());
    }

    #[test]
    fn bad_boxes_are_errors() {
        assert!(Quantizer::new(DVec3::ONE, DVec3::ZERO, 26).is_err());
        assert!(Quantizer::new(DVec3::ZERO, DVec3::splat(f64::NAN), 26).is_err());
        assert!(Quantizer::new(DVec3::splat(-f64::MAX), DVec3::splat(f64::MAX), 26).is_err());
        assert!(Quantizer::new(DVec3::ZERO, DVec3::ONE, 40).is_err());
    }

    #[test]
    fn snapping_rejects_outside_and_nan() {
        let q = Quantizer::new(DVec3::ZERO, DVec3::ONE, 20).unwrap();
        assert!(matches!(
            q.snap(DVec3::new(2.0, 0.5, 0.5)),
            Err(KernelError::OutsideGrid(..))
        ));
        assert!(matches!(
            q.snap(DVec3::new(f64::NAN, 0.5, 0.5)),
            Err(KernelError::NonFinite(..))
        ));
        assert!(q.snap_far(DVec3::new(1e6, 0.0, 0.0), FAR_LIMIT).is_ok());
        assert!(matches!(
            q.snap_far(DVec3::new(1e300, 0.0, 0.0), FAR_LIMIT),
            Err(KernelError::TooFar(..))
        ));
    }
}
