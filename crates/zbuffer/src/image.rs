//! The images every method produces: face ids, colours, depths, and pixel masks.
//!
//! All images are row-major with `width × height` pixels; pixel `(i, j)` (column `i`,
//! row `j`, y down) is element `j · width + i`.

/// The face id stored where no face covers a pixel centre.
pub const NO_FACE: u32 = u32::MAX;

/// Which face covers each pixel centre ([`NO_FACE`] for none).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct IdImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Face ids, row-major.
    pub ids: Vec<u32>,
}

impl IdImage {
    /// An image with no face anywhere.
    pub fn new(width: u32, height: u32) -> Self {
        IdImage {
            width,
            height,
            ids: vec![NO_FACE; width as usize * height as usize],
        }
    }

    /// The id at pixel `(x, y)`, or `None` outside the image.
    pub fn get(&self, x: u32, y: u32) -> Option<u32> {
        if x < self.width && y < self.height {
            self.ids
                .get(y as usize * self.width as usize + x as usize)
                .copied()
        } else {
            None
        }
    }

    /// Number of pixels covered by some face.
    pub fn covered(&self) -> usize {
        self.ids.iter().filter(|&&id| id != NO_FACE).count()
    }
}

/// A set of pixels (for example the edge band of [`crate::edge_band`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Mask {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// One flag per pixel, row-major.
    pub bits: Vec<bool>,
}

impl Mask {
    /// An empty mask.
    pub fn new(width: u32, height: u32) -> Self {
        Mask {
            width,
            height,
            bits: vec![false; width as usize * height as usize],
        }
    }

    /// Whether pixel `(x, y)` is in the mask (`false` outside the image).
    pub fn get(&self, x: u32, y: u32) -> bool {
        x < self.width
            && y < self.height
            && self.bits[y as usize * self.width as usize + x as usize]
    }

    /// Number of pixels in the mask.
    pub fn count(&self) -> usize {
        self.bits.iter().filter(|&&b| b).count()
    }
}

/// An 8-bit RGB picture (each channel `round(c · 255)` of a linear colour in [0, 1]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ColorImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Pixels, row-major.
    pub pixels: Vec<[u8; 3]>,
}

impl ColorImage {
    /// An image filled with one colour.
    pub fn filled(width: u32, height: u32, color: [u8; 3]) -> Self {
        ColorImage {
            width,
            height,
            pixels: vec![color; width as usize * height as usize],
        }
    }

    /// The colour at pixel `(x, y)`, or `None` outside the image.
    pub fn get(&self, x: u32, y: u32) -> Option<[u8; 3]> {
        if x < self.width && y < self.height {
            Some(self.pixels[y as usize * self.width as usize + x as usize])
        } else {
            None
        }
    }
}

/// Window depth per pixel: `(z_ndc + 1) / 2` in [0, 1] (0 at the near plane, 1 at the
/// far plane), as stored by the method's depth format and read back as `f64`;
/// `f64::INFINITY` where no face covers the pixel centre.
#[derive(Debug, Clone, PartialEq)]
pub struct DepthImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Depths, row-major.
    pub depths: Vec<f64>,
}

impl DepthImage {
    /// An image with no depth anywhere.
    pub fn new(width: u32, height: u32) -> Self {
        DepthImage {
            width,
            height,
            depths: vec![f64::INFINITY; width as usize * height as usize],
        }
    }

    /// The depth at pixel `(x, y)`, or `None` outside the image.
    pub fn get(&self, x: u32, y: u32) -> Option<f64> {
        if x < self.width && y < self.height {
            Some(self.depths[y as usize * self.width as usize + x as usize])
        } else {
            None
        }
    }
}

/// Converts a linear colour channel in [0, 1] to 8 bits: `round(c · 255)`, clamped;
/// NaN becomes 0.
pub fn to_u8(c: f64) -> u8 {
    if c.is_nan() {
        return 0;
    }
    (c.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// [`to_u8`] on each channel.
pub fn rgb_to_u8(c: [f64; 3]) -> [u8; 3] {
    c.map(to_u8)
}
