//! How a scene asks to be shaded beyond its materials and lights: the interpolation
//! mode ([`Shading`]) and depth cueing ([`Fog`]).
//!
//! The default rule (when neither the scene file nor the command line names a mode):
//! lit faces (`illum` ≥ 1) with vertex normals are Gouraud-shaded, every other face is
//! flat. Phong interpolation is used only when asked for (`shading = "phong"` in a scene
//! file's `[output]`, or `--shading phong`): Gouraud is exact in PDF and EPS (a type-4
//! mesh is a linear interpolation of the vertex colours) and small, while Phong has to
//! be approximated by subdivision there; on finely tessellated meshes the two differ by
//! less than one 8-bit step except inside sharp highlights.

use std::fmt;
use std::str::FromStr;

use glam::DVec3;
use thiserror::Error;

use crate::{Face, Material, Rgb};

/// How colours vary across a lit face with vertex normals.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Shading {
    /// One colour per face, lit at its centroid with its geometric normal.
    Flat,
    /// Colours computed at the vertices (normals interpolated over the face) and
    /// interpolated linearly.
    Gouraud,
    /// Normals interpolated, lighting computed per point.
    Phong,
}

impl Shading {
    /// Every mode.
    pub const ALL: [Shading; 3] = [Shading::Flat, Shading::Gouraud, Shading::Phong];

    /// The mode's name: `flat`, `gouraud`, `phong`.
    pub fn name(self) -> &'static str {
        match self {
            Shading::Flat => "flat",
            Shading::Gouraud => "gouraud",
            Shading::Phong => "phong",
        }
    }

    /// The mode a face is drawn with when the scene asks for `asked` (`None`: the
    /// default rule of the module docs). `illum 0` materials and faces without vertex
    /// normals are always flat.
    pub fn of_face(asked: Option<Shading>, face: &Face, material: &Material) -> Shading {
        if material.illum == 0 || face.normals.is_none() {
            return Shading::Flat;
        }
        asked.unwrap_or(Shading::Gouraud)
    }
}

impl fmt::Display for Shading {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A shading name that [`Shading::from_str`] does not know.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("unknown shading {0:?} (expected flat, gouraud or phong)")]
pub struct ParseShadingError(pub String);

impl FromStr for Shading {
    type Err = ParseShadingError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Shading::ALL
            .into_iter()
            .find(|m| m.name().eq_ignore_ascii_case(s))
            .ok_or_else(|| ParseShadingError(s.to_string()))
    }
}

/// How fog thickens with distance from the eye.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FogFalloff {
    /// No fog before `start`, full fog from `end` on, linear in between.
    Linear,
    /// The share of the surface colour left is `exp(-density · (d − start))` beyond
    /// `start` (nothing before it); `end` is ignored.
    Exponential {
        /// Extinction per unit of distance, > 0.
        density: f64,
    },
}

/// Depth cueing: colours blended toward `color` with the distance from the eye.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fog {
    /// The colour of full fog, linear RGB in [0, 1].
    pub color: Rgb,
    /// Distance from the eye where fog begins (≥ 0).
    pub start: f64,
    /// Distance where linear fog is complete (> `start`).
    pub end: f64,
    /// Linear or exponential.
    pub falloff: FogFalloff,
}

/// A fog whose numbers cannot be used.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("fog {0}")]
pub struct FogError(pub &'static str);

impl Fog {
    /// Checks the numbers: a finite colour in [0, 1], `0 ≤ start < end` (finite), a
    /// finite positive density.
    pub fn validate(&self) -> Result<(), FogError> {
        if !self.color.iter().all(|c| (0.0..=1.0).contains(c)) {
            return Err(FogError("colour channels must be between 0 and 1"));
        }
        if !(self.start.is_finite() && self.end.is_finite() && 0.0 <= self.start) {
            return Err(FogError("start and end must be finite, start >= 0"));
        }
        match self.falloff {
            FogFalloff::Linear if self.end <= self.start => {
                Err(FogError("end must be greater than start"))
            }
            FogFalloff::Exponential { density } if !(density.is_finite() && density > 0.0) => {
                Err(FogError("density must be a finite number > 0"))
            }
            _ => Ok(()),
        }
    }

    /// The share of the surface colour that remains at distance `d` from the eye, in
    /// [0, 1].
    pub fn visibility(&self, d: f64) -> f64 {
        let v = match self.falloff {
            FogFalloff::Linear => (self.end - d) / (self.end - self.start),
            FogFalloff::Exponential { density } => (-density * (d - self.start).max(0.0)).exp(),
        };
        if v.is_nan() {
            1.0
        } else {
            v.clamp(0.0, 1.0)
        }
    }

    /// `rgb` seen through the fog at world point `p` from `eye`.
    pub fn apply(&self, rgb: Rgb, p: DVec3, eye: DVec3) -> Rgb {
        let v = self.visibility(p.distance(eye));
        [0, 1, 2].map(|k| v * rgb[k] + (1.0 - v) * self.color[k])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for m in Shading::ALL {
            assert_eq!(m.name().parse::<Shading>(), Ok(m));
        }
        assert!("smooth".parse::<Shading>().is_err());
    }

    #[test]
    fn linear_fog_by_hand() {
        let fog = Fog {
            color: [1.0, 1.0, 1.0],
            start: 2.0,
            end: 6.0,
            falloff: FogFalloff::Linear,
        };
        fog.validate().unwrap();
        let eye = DVec3::ZERO;
        // Before start: unchanged; at 3/4 of the way: a quarter of the colour left.
        assert_eq!(
            fog.apply([0.2, 0.4, 0.6], DVec3::new(0.0, 0.0, -1.0), eye),
            [0.2, 0.4, 0.6]
        );
        let c = fog.apply([0.2, 0.4, 0.6], DVec3::new(0.0, 0.0, -5.0), eye);
        let want = [0.25 * 0.2 + 0.75, 0.25 * 0.4 + 0.75, 0.25 * 0.6 + 0.75];
        for k in 0..3 {
            assert!((c[k] - want[k]).abs() < 1e-15, "{c:?} vs {want:?}");
        }
        assert_eq!(
            fog.apply([0.2, 0.4, 0.6], DVec3::new(0.0, 9.0, 0.0), eye),
            [1.0; 3]
        );
    }

    #[test]
    fn exponential_fog_by_hand() {
        let fog = Fog {
            color: [0.0, 0.0, 0.0],
            start: 1.0,
            end: 0.0,
            falloff: FogFalloff::Exponential { density: 0.5 },
        };
        fog.validate().unwrap();
        let c = fog.apply([1.0, 0.5, 0.0], DVec3::new(3.0, 0.0, 0.0), DVec3::ZERO);
        let v = (-1.0f64).exp(); // exp(-0.5 · (3 − 1))
        assert_eq!(c, [v, 0.5 * v, 0.0]);
    }

    #[test]
    fn bad_fog_is_refused() {
        let mut fog = Fog {
            color: [0.5; 3],
            start: 3.0,
            end: 3.0,
            falloff: FogFalloff::Linear,
        };
        assert!(fog.validate().is_err());
        fog.end = f64::NAN;
        assert!(fog.validate().is_err());
        fog.end = 4.0;
        fog.color[0] = 2.0;
        assert!(fog.validate().is_err());
        fog.color[0] = 0.5;
        fog.falloff = FogFalloff::Exponential { density: 0.0 };
        assert!(fog.validate().is_err());
    }
}
