//! Depth formats: how a z-buffer stores window depth.
//!
//! Depth is always interpolated in `f64` (window depth `(z_ndc + 1) / 2` is affine in
//! pixel coordinates, so interpolating it linearly is perspective-correct); the format
//! only decides how it is *stored* and therefore which depths compare equal. Integer
//! formats quantise `round(d · (2ⁿ − 1))` with `d` clamped to [0, 1]. Equal stored depths
//! are ties, won by the later face in input order, so a coarse format shows depth
//! fighting as wrong faces.

/// How depth is stored in a z-buffer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
pub enum DepthFormat {
    /// 64-bit float (the default).
    #[default]
    F64,
    /// 32-bit float.
    F32,
    /// 24-bit unsigned integer.
    D24,
    /// 16-bit unsigned integer.
    D16,
}

impl DepthFormat {
    /// Every format, finest first.
    pub const ALL: [DepthFormat; 4] = [
        DepthFormat::F64,
        DepthFormat::F32,
        DepthFormat::D24,
        DepthFormat::D16,
    ];

    /// The depth `d` as this format stores it, read back as `f64`.
    pub fn round_trip(self, d: f64) -> f64 {
        match self {
            DepthFormat::F64 => F64Depth::load(F64Depth::store(d)),
            DepthFormat::F32 => F32Depth::load(F32Depth::store(d)),
            DepthFormat::D24 => D24Depth::load(D24Depth::store(d)),
            DepthFormat::D16 => D16Depth::load(D16Depth::store(d)),
        }
    }

    /// Bytes per stored depth value.
    pub fn bytes(self) -> usize {
        match self {
            DepthFormat::F64 => 8,
            DepthFormat::F32 | DepthFormat::D24 => 4,
            DepthFormat::D16 => 2,
        }
    }
}

/// A stored depth representation (implemented by zero-sized markers, one per format, so
/// the rasterisers are monomorphised per format).
pub(crate) trait Depth {
    /// The stored value; smaller is nearer.
    type Stored: Copy + PartialOrd;
    /// The value of an empty pixel (farther than everything).
    const FAR: Self::Stored;
    /// Quantises a window depth.
    fn store(d: f64) -> Self::Stored;
    /// Reads a stored value back.
    fn load(s: Self::Stored) -> f64;
}

pub(crate) struct F64Depth;
pub(crate) struct F32Depth;
pub(crate) struct D24Depth;
pub(crate) struct D16Depth;

impl Depth for F64Depth {
    type Stored = f64;
    const FAR: f64 = f64::INFINITY;
    #[inline]
    fn store(d: f64) -> f64 {
        d
    }
    #[inline]
    fn load(s: f64) -> f64 {
        s
    }
}

impl Depth for F32Depth {
    type Stored = f32;
    const FAR: f32 = f32::INFINITY;
    #[inline]
    fn store(d: f64) -> f32 {
        d as f32
    }
    #[inline]
    fn load(s: f32) -> f64 {
        s as f64
    }
}

const MAX24: f64 = ((1u32 << 24) - 1) as f64;

impl Depth for D24Depth {
    type Stored = u32;
    const FAR: u32 = u32::MAX;
    #[inline]
    fn store(d: f64) -> u32 {
        // Round half up (the value is non-negative); `as` maps NaN to 0.
        (d.clamp(0.0, 1.0) * MAX24 + 0.5) as u32
    }
    #[inline]
    fn load(s: u32) -> f64 {
        if s == u32::MAX {
            f64::INFINITY
        } else {
            s as f64 / MAX24
        }
    }
}

impl Depth for D16Depth {
    // The empty value equals the far plane's depth; ties go to the face (the depth test
    // is `<=`), and coverage is read from the id buffer, never from depth.
    type Stored = u16;
    const FAR: u16 = u16::MAX;
    #[inline]
    fn store(d: f64) -> u16 {
        (d.clamp(0.0, 1.0) * 65535.0 + 0.5) as u16
    }
    #[inline]
    fn load(s: u16) -> f64 {
        s as f64 / 65535.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_formats_quantise() {
        assert_eq!(DepthFormat::D16.round_trip(0.5), 32768.0 / 65535.0);
        assert_eq!(DepthFormat::D16.round_trip(2.0), 1.0);
        assert_eq!(DepthFormat::D24.round_trip(-1.0), 0.0);
        assert_eq!(DepthFormat::D24.round_trip(f64::NAN), 0.0);
        assert_eq!(DepthFormat::F64.round_trip(0.1), 0.1);
        assert_ne!(DepthFormat::F32.round_trip(0.1), 0.1);
    }
}
