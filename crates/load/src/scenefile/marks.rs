//! The scene file's `[[line]]`, `[[points]]` and `[[label]]` tables: content drawn over
//! the surfaces where visible, each checked with the line it stands on.

use std::path::Path;

use glam::DVec3;
use toml::Spanned;

use super::doc::{ColourDoc, LabelDoc, LineDoc, PointsDoc};
use super::Ctx;
use crate::{refs, Format, LoadError, LoadOptions};
use limn_scene::{LabelAnchor, MarkerShape, PointMark, Polyline, Scene, TextLabel};

/// Adds the tables' lines, points and labels to `scene`, each set in an object of its
/// own (named by `name`, or `line 1`, `points 2`, `label 3`).
pub(super) fn add(
    cx: &Ctx,
    lines: &[Spanned<LineDoc>],
    points: &[Spanned<PointsDoc>],
    labels: &[Spanned<LabelDoc>],
    scene: &mut Scene,
    opts: &LoadOptions,
) -> Result<(), LoadError> {
    for (i, l) in lines.iter().enumerate() {
        let object = scene.add_object(&name(&l.get_ref().name, "line", i));
        for pl in line(cx, l, object, opts, scene)? {
            scene.lines.push(pl);
        }
    }
    for (i, p) in points.iter().enumerate() {
        let object = scene.add_object(&name(&p.get_ref().name, "points", i));
        let d = p.get_ref();
        let shape = match &d.marker {
            None => MarkerShape::Dot,
            Some(m) => MarkerShape::from_name(m.get_ref()).ok_or_else(|| {
                cx.invalid(
                    m.span(),
                    format!(
                        "unknown marker {:?}; expected one of {}",
                        m.get_ref(),
                        MarkerShape::NAMES
                    ),
                )
            })?,
        };
        let size = positive(cx, &d.size, 4.0, "size")?;
        let color = colour(cx, &d.color, &d.opacity)?;
        for &at in d.positions.get_ref() {
            let at = finite(cx, at, d.positions.span(), "point position")?;
            scene.points.push(PointMark {
                at,
                shape,
                size,
                color,
                object,
            });
        }
    }
    for (i, l) in labels.iter().enumerate() {
        let object = scene.add_object(&name(&l.get_ref().name, "label", i));
        scene.labels.push(label(cx, l, object)?);
    }
    Ok(())
}

fn name(given: &Option<String>, kind: &str, i: usize) -> String {
    given.clone().unwrap_or_else(|| format!("{kind} {}", i + 1))
}

fn finite(
    cx: &Ctx,
    p: [f64; 3],
    span: std::ops::Range<usize>,
    what: &str,
) -> Result<DVec3, LoadError> {
    let p = DVec3::from(p);
    if !p.is_finite() {
        return Err(LoadError::NonFinite {
            at: cx.line(span),
            what: what.into(),
        });
    }
    Ok(p)
}

/// A positive finite size, or `default`.
fn positive(
    cx: &Ctx,
    v: &Option<Spanned<f64>>,
    default: f64,
    what: &str,
) -> Result<f64, LoadError> {
    match v {
        None => Ok(default),
        Some(s) if s.get_ref().is_finite() && *s.get_ref() > 0.0 => Ok(*s.get_ref()),
        Some(s) => Err(cx.invalid(s.span(), format!("{what} must be a positive number"))),
    }
}

/// A colour with its opacity (default black, opaque).
fn colour(
    cx: &Ctx,
    c: &Option<Spanned<ColourDoc>>,
    opacity: &Option<Spanned<f64>>,
) -> Result<[f64; 4], LoadError> {
    let rgb = match c {
        Some(c) => cx.colour(c, 1.0)?,
        None => [0.0; 3],
    };
    let a = match opacity {
        None => 1.0,
        Some(o) if (0.0..=1.0).contains(o.get_ref()) => *o.get_ref(),
        Some(o) => return Err(cx.invalid(o.span(), "opacity must be between 0 and 1")),
    };
    Ok([rgb[0], rgb[1], rgb[2], a])
}

/// The polylines of one `[[line]]` table: its `points`, or every line of the OBJ file
/// its `path` names (which must hold only lines).
fn line(
    cx: &Ctx,
    l: &Spanned<LineDoc>,
    object: u32,
    opts: &LoadOptions,
    scene: &mut Scene,
) -> Result<Vec<Polyline>, LoadError> {
    let d = l.get_ref();
    let width = positive(cx, &d.width, 1.0, "width")?;
    let color = colour(cx, &d.color, &d.opacity)?;
    let dash = match &d.dash {
        None => Vec::new(),
        Some(s) => {
            let v = s.get_ref();
            if v.iter().any(|x| !x.is_finite() || *x < 0.0) || v.iter().sum::<f64>() <= 0.0 {
                return Err(cx.invalid(
                    s.span(),
                    "dash lengths must be non-negative numbers with a positive sum",
                ));
            }
            v.clone()
        }
    };
    let style = |points: Vec<DVec3>| Polyline {
        points,
        color,
        width,
        dash: dash.clone(),
        head: d.head,
        object,
    };
    match (&d.points, &d.path) {
        (Some(p), None) => {
            if p.get_ref().len() < 2 {
                return Err(cx.invalid(
                    p.span(),
                    format!(
                        "a line has {} point(s); at least 2 are needed",
                        p.get_ref().len()
                    ),
                ));
            }
            let pts = p
                .get_ref()
                .iter()
                .map(|&q| finite(cx, q, p.span(), "line point"))
                .collect::<Result<Vec<_>, _>>()?;
            Ok(vec![style(pts)])
        }
        (None, Some(path)) => {
            let at = cx.line(path.span());
            if Format::from_path(Path::new(path.get_ref())) != Some(Format::Obj) {
                return Err(cx.invalid(path.span(), "a line's path must name an OBJ file"));
            }
            let file = refs::resolve(path.get_ref(), &at, opts)?;
            let sub = crate::load(&file, opts).map_err(|e| LoadError::InMesh {
                at: at.clone(),
                source: Box::new(e),
            })?;
            if !sub.faces.is_empty() || !sub.points.is_empty() {
                return Err(cx.invalid(
                    path.span(),
                    "a line's OBJ file must hold only lines (`l` elements)",
                ));
            }
            scene.files.extend(sub.files.iter().cloned());
            Ok(sub.lines.into_iter().map(|pl| style(pl.points)).collect())
        }
        _ => Err(cx.invalid(l.span(), "a [[line]] needs either `points` or `path`")),
    }
}

fn label(cx: &Ctx, l: &Spanned<LabelDoc>, object: u32) -> Result<TextLabel, LoadError> {
    let d = l.get_ref();
    let at = cx.finite3(&d.at, "label anchor")?;
    let text = d.text.get_ref().clone();
    if text.contains(['\n', '\r']) {
        return Err(cx.invalid(d.text.span(), "a label's text must be one line"));
    }
    let anchor = match &d.anchor {
        None => LabelAnchor::Center,
        Some(a) => LabelAnchor::from_name(a.get_ref()).ok_or_else(|| {
            cx.invalid(
                a.span(),
                format!(
                    "unknown anchor {:?}; expected center, north, south, east, west, \
                     north east, north west, south east or south west",
                    a.get_ref()
                ),
            )
        })?,
    };
    let offset = match &d.offset {
        None => [0.0, 0.0],
        Some(o) if o.get_ref().iter().all(|v| v.is_finite()) => *o.get_ref(),
        Some(o) => {
            return Err(LoadError::NonFinite {
                at: cx.line(o.span()),
                what: "label offset".into(),
            })
        }
    };
    Ok(TextLabel {
        at,
        text,
        size: positive(cx, &d.size, 10.0, "size")?,
        color: colour(cx, &d.color, &d.opacity)?,
        anchor,
        offset,
        object,
    })
}
