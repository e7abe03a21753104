//! The settings part of a scene file: lights, output options and the camera.

use glam::DVec3;
use toml::Spanned;

use super::doc::{self, lower, Doc, LightKindDoc, SizeDoc, StyleDoc, V3};
use super::{Ctx, SceneOptions};
use crate::LoadError;
use limn_scene::DEFAULT_VIEW_DIRECTION;
use limn_scene::{Camera, Light, LightKind, Scene};

pub(super) fn light(cx: &Ctx, l: &Spanned<doc::LightDoc>) -> Result<Light, LoadError> {
    let d = l.get_ref();
    let need = |v: &Option<V3>, what: &str| -> Result<DVec3, LoadError> {
        match v {
            Some(v) => cx.finite3(v, what),
            None => Err(cx.invalid(l.span(), format!("a {:?} light needs {what}", d.kind))),
        }
    };
    let extra = |v: &Option<V3>, what: &str| -> Result<(), LoadError> {
        match v {
            Some(v) => Err(cx.invalid(v.span(), format!("a {:?} light has no {what}", d.kind))),
            None => Ok(()),
        }
    };
    let kind = match d.kind {
        LightKindDoc::Directional => {
            extra(&d.position, "position")?;
            let dir = need(&d.direction, "direction")?;
            if dir.length_squared() == 0.0 {
                return Err(cx.invalid(l.span(), "the light direction is zero"));
            }
            LightKind::Directional(dir)
        }
        LightKindDoc::Point => {
            extra(&d.direction, "direction")?;
            LightKind::Point(need(&d.position, "position")?)
        }
        LightKindDoc::Ambient | LightKindDoc::Headlight => {
            extra(&d.direction, "direction")?;
            extra(&d.position, "position")?;
            if d.kind == LightKindDoc::Ambient {
                LightKind::Ambient
            } else {
                LightKind::Headlight
            }
        }
    };
    let colour = match &d.color {
        Some(c) => cx.colour(c, f64::MAX)?,
        None => [1.0; 3],
    };
    let k = d.intensity.unwrap_or(1.0);
    if !(k.is_finite() && k >= 0.0) {
        return Err(cx.invalid(l.span(), "intensity must be a finite number >= 0"));
    }
    let shadows = match &d.shadows {
        Some(s)
            if *s.get_ref() && !matches!(kind, LightKind::Directional(_) | LightKind::Point(_)) =>
        {
            return Err(cx.invalid(
                s.span(),
                format!(
                    "a {:?} light casts no shadows (only directional and point lights do)",
                    d.kind
                ),
            ))
        }
        Some(s) => *s.get_ref(),
        None => false,
    };
    Ok(Light {
        kind,
        color: colour.map(|c| c * k),
        shadows,
    })
}

pub(super) fn options(cx: &Ctx, doc: &Doc) -> Result<SceneOptions, LoadError> {
    let Some(o) = &doc.output else {
        return Ok(SceneOptions::default());
    };
    let size = match &o.size {
        None => None,
        Some(s) => {
            let (w, h) = match s.get_ref() {
                SizeDoc::Pair([w, h]) => (*w, *h),
                SizeDoc::Text(t) => t
                    .split_once(['x', 'X'])
                    .and_then(|(w, h)| Some((w.trim().parse().ok()?, h.trim().parse().ok()?)))
                    .ok_or_else(|| cx.invalid(s.span(), format!("size {t:?} is not WxH")))?,
            };
            if !(1..=65536).contains(&w) || !(1..=65536).contains(&h) {
                return Err(cx.invalid(
                    s.span(),
                    format!("size {w}x{h}: each side must be 1 to 65536"),
                ));
            }
            Some((w, h))
        }
    };
    let outline_width = match &o.outline_width {
        Some(w) if !(w.get_ref().is_finite() && *w.get_ref() > 0.0) => {
            return Err(cx.invalid(w.span(), "outline_width must be a finite number > 0"))
        }
        w => w.as_ref().map(|w| *w.get_ref()),
    };
    Ok(SceneOptions {
        size,
        background: o
            .background
            .as_ref()
            .map(|c| cx.colour(c, 1.0))
            .transpose()?,
        outline: o.outline,
        outline_color: o
            .outline_color
            .as_ref()
            .map(|c| cx.colour(c, 1.0))
            .transpose()?,
        outline_width,
        format: o.format.map(lower),
        sort: o.sort.map(lower),
        arith: o.arith.map(lower),
        cull: o.cull.map(lower),
        style: o.style.map(|s| match s {
            StyleDoc::Filled => "filled".to_string(),
            StyleDoc::HiddenLine => "hidden-line".to_string(),
        }),
        crease: match &o.crease {
            Some(c) if !(c.get_ref().is_finite() && (0.0..=180.0).contains(c.get_ref())) => {
                return Err(cx.invalid(c.span(), "crease must be an angle from 0 to 180 degrees"))
            }
            c => c.as_ref().map(|c| *c.get_ref()),
        },
        hidden: o.hidden.map(lower),
        fill: o.fill.map(lower),
        visible: o.visible,
    })
}

pub(super) fn camera(
    cx: &Ctx,
    c: &Spanned<doc::CameraDoc>,
    scene: &Scene,
    (width, height): (u32, u32),
) -> Result<Camera, LoadError> {
    let d = c.get_ref();
    let at = || cx.line(c.span());
    let cam_err = |source| LoadError::Camera { at: at(), source };
    let fov = d.fov.unwrap_or(45.0);
    let target = d
        .target
        .as_ref()
        .map(|t| cx.finite3(t, "camera target"))
        .transpose()?;
    let mut cam = match &d.eye {
        Some(e) => {
            let eye = cx.finite3(e, "camera eye")?;
            let target = match target {
                Some(t) => t,
                None => scene
                    .bounds()
                    .map_or(DVec3::ZERO, |(lo, hi)| (lo + hi) * 0.5),
            };
            Camera::new(eye, target, width, height)
        }
        None => {
            let dir = DVec3::from(DEFAULT_VIEW_DIRECTION);
            let mut cam = Camera::framing_scene(scene, dir, fov, width, height).map_err(cam_err)?;
            if let Some(t) = target {
                cam.eye = t + (cam.eye - cam.target);
                cam.target = t;
            }
            cam
        }
    };
    cam.fov_deg = fov;
    if let Some(up) = &d.up {
        cam.up = cx.finite3(up, "camera up")?;
    }
    let ortho = d.projection == Some(doc::ProjectionDoc::Orthographic);
    if ortho {
        let dir = cam.eye - cam.target;
        let framed = Camera::framing_orthographic(scene, dir, width, height).map_err(cam_err)?;
        let height = d.height.unwrap_or(match framed.projection {
            limn_scene::Projection::Orthographic { height } => height,
            _ => 1.0,
        });
        if d.eye.is_none() {
            // Framed: the eye stands back far enough that nothing is clipped.
            cam.eye = cam.target + (framed.eye - framed.target);
        }
        cam.projection = limn_scene::Projection::Orthographic { height };
    } else if d.height.is_some() {
        return Err(LoadError::Invalid {
            at: at(),
            message: "camera `height` needs `projection = \"orthographic\"`".into(),
        });
    }
    cam.near = d.near;
    cam.far = d.far;
    if let (Some(n), None) = (cam.near, cam.far) {
        if !(n > 0.0 && n.is_finite()) {
            return Err(cam_err(limn_scene::CameraError::BadClip(n, f64::NAN)));
        }
    }
    if let (None, Some(f)) = (cam.near, cam.far) {
        if !(f > 0.0 && f.is_finite()) {
            return Err(cam_err(limn_scene::CameraError::BadClip(f64::NAN, f)));
        }
    }
    cam.validate().map_err(cam_err)?;
    Ok(cam)
}
