//! The effects part of a scene file: `shading` in `[output]` and the `[fog]` table.

use toml::Spanned;

use super::doc::{FogDoc, FogModeDoc, ShadingDoc};
use super::Ctx;
use crate::LoadError;
use limn_scene::{Fog, FogFalloff, Shading};

pub(super) fn shading(d: ShadingDoc) -> Shading {
    match d {
        ShadingDoc::Flat => Shading::Flat,
        ShadingDoc::Gouraud => Shading::Gouraud,
        ShadingDoc::Phong => Shading::Phong,
    }
}

/// `[fog]`: `color` (default white), `start` (default 0), `end` (needed for linear fog),
/// `mode` = `linear` (default) or `exponential` (then `density` is needed and `end`
/// is not allowed).
pub(super) fn fog(cx: &Ctx, f: &Spanned<FogDoc>) -> Result<Fog, LoadError> {
    let d = f.get_ref();
    let color = match &d.color {
        Some(c) => cx.colour(c, 1.0)?,
        None => [1.0; 3],
    };
    let mode = d.mode.unwrap_or(FogModeDoc::Linear);
    let (end, falloff) = match mode {
        FogModeDoc::Linear => {
            if d.density.is_some() {
                return Err(cx.invalid(f.span(), "linear fog has no density (give start and end)"));
            }
            let Some(end) = d.end else {
                return Err(cx.invalid(f.span(), "linear fog needs end"));
            };
            (end, FogFalloff::Linear)
        }
        FogModeDoc::Exponential => {
            if d.end.is_some() {
                return Err(cx.invalid(f.span(), "exponential fog has no end (give density)"));
            }
            let Some(density) = d.density else {
                return Err(cx.invalid(f.span(), "exponential fog needs density"));
            };
            (0.0, FogFalloff::Exponential { density })
        }
    };
    let fog = Fog {
        color,
        start: d.start.unwrap_or(0.0),
        end,
        falloff,
    };
    fog.validate()
        .map_err(|e| cx.invalid(f.span(), e.to_string()))?;
    Ok(fog)
}
