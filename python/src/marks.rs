//! numpy arrays to scene marks: polylines, point markers and text labels, every value
//! checked before the scene changes.

use glam::DVec3;
use limn_scene::{LabelAnchor, MarkerShape, PointMark, Polyline, Scene, TextLabel};
use numpy::{PyReadonlyArray1, PyReadonlyArray2};
use pyo3::prelude::*;

use crate::errors::value_error;

/// Finite points from an `(N, 3)` array named `what`.
fn points(what: &str, a: &PyReadonlyArray2<'_, f64>) -> PyResult<Vec<DVec3>> {
    let a = a.as_array();
    if a.ncols() != 3 {
        return Err(value_error(format!(
            "{what} must have shape (N, 3), not {:?}",
            a.shape()
        )));
    }
    (0..a.nrows())
        .map(|i| {
            let p = DVec3::new(a[[i, 0]], a[[i, 1]], a[[i, 2]]);
            if p.is_finite() {
                Ok(p)
            } else {
                Err(value_error(format!(
                    "{what}[{i}] = ({}, {}, {}) is not finite",
                    p.x, p.y, p.z
                )))
            }
        })
        .collect()
}

/// An RGBA colour in 0..1 from 3 or 4 numbers.
fn rgba(what: &str, c: &[f64]) -> PyResult<[f64; 4]> {
    let c = match c {
        [r, g, b] => [*r, *g, *b, 1.0],
        [r, g, b, a] => [*r, *g, *b, *a],
        _ => {
            return Err(value_error(format!(
                "{what} must have 3 or 4 channels, not {}",
                c.len()
            )))
        }
    };
    if c.iter().all(|v| (0.0..=1.0).contains(v)) {
        Ok(c)
    } else {
        Err(value_error(format!("{what} {c:?} is outside 0..1")))
    }
}

/// A positive finite number.
fn positive(what: &str, v: f64) -> PyResult<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(value_error(format!("{what} {v} must be a positive number")))
    }
}

/// Adds one polyline (points `(N, 3)`, N ≥ 2) as object `name`; returns its index.
pub(crate) fn add_line(
    scene: &mut Scene,
    name: &str,
    pts: &PyReadonlyArray2<'_, f64>,
    color: &[f64],
    width: f64,
    dash: &[f64],
    head: bool,
) -> PyResult<u32> {
    let points = points("points", pts)?;
    if points.len() < 2 {
        return Err(value_error(format!(
            "a line needs at least 2 points, not {}",
            points.len()
        )));
    }
    let color = rgba("line color", color)?;
    let width = positive("line width", width)?;
    if !dash.is_empty()
        && (dash.iter().any(|d| !(d.is_finite() && *d >= 0.0)) || dash.iter().sum::<f64>() <= 0.0)
    {
        return Err(value_error(format!(
            "dash {dash:?}: lengths must be non-negative numbers with a positive sum"
        )));
    }
    let object = scene.add_object(name);
    scene.lines.push(Polyline {
        points,
        color,
        width,
        dash: dash.to_vec(),
        head,
        object,
    });
    Ok(scene.lines.len() as u32 - 1)
}

/// Adds point markers at `positions` `(N, 3)` as object `name`, with colours `(N, 4)`
/// and sizes `(N,)` (one per point); returns the index of the first.
pub(crate) fn add_points(
    scene: &mut Scene,
    name: &str,
    positions: &PyReadonlyArray2<'_, f64>,
    marker: &str,
    sizes: &PyReadonlyArray1<'_, f64>,
    colors: &PyReadonlyArray2<'_, f64>,
) -> PyResult<u32> {
    let at = points("positions", positions)?;
    let shape = MarkerShape::from_name(marker).ok_or_else(|| {
        value_error(format!(
            "unknown marker `{marker}` ({})",
            MarkerShape::NAMES
        ))
    })?;
    let sizes = sizes.as_array();
    let colors = colors.as_array();
    if sizes.len() != at.len() {
        return Err(value_error(format!(
            "size must be one number or one per point ({}), not {}",
            at.len(),
            sizes.len()
        )));
    }
    if colors.nrows() != at.len() || !(colors.ncols() == 3 || colors.ncols() == 4) {
        return Err(value_error(format!(
            "color must be one colour or one per point: shape ({0}, 3) or ({0}, 4), not {1:?}",
            at.len(),
            colors.shape()
        )));
    }
    let mut marks = Vec::with_capacity(at.len());
    for (i, p) in at.into_iter().enumerate() {
        let c: Vec<f64> = colors.row(i).iter().copied().collect();
        marks.push(PointMark {
            at: p,
            shape,
            size: positive(&format!("size[{i}]"), sizes[i])?,
            color: rgba(&format!("color[{i}]"), &c)?,
            object: 0,
        });
    }
    let first = scene.points.len() as u32;
    let object = scene.add_object(name);
    scene
        .points
        .extend(marks.into_iter().map(|m| PointMark { object, ..m }));
    Ok(first)
}

/// Adds one text label anchored at `at`; returns its index.
#[allow(clippy::too_many_arguments)]
pub(crate) fn add_label(
    scene: &mut Scene,
    name: &str,
    at: (f64, f64, f64),
    text: &str,
    size: f64,
    color: &[f64],
    anchor: &str,
    offset: (f64, f64),
) -> PyResult<u32> {
    let p = DVec3::new(at.0, at.1, at.2);
    if !p.is_finite() {
        return Err(value_error(format!(
            "label position ({}, {}, {}) is not finite",
            p.x, p.y, p.z
        )));
    }
    if text.contains(['\n', '\r']) {
        return Err(value_error("a label is one line of text"));
    }
    let size = positive("label size", size)?;
    let color = rgba("label color", color)?;
    let anchor = LabelAnchor::from_name(anchor).ok_or_else(|| {
        value_error(format!(
            "unknown anchor `{anchor}` (center, north, south, east, west, north east, …)"
        ))
    })?;
    if !(offset.0.is_finite() && offset.1.is_finite()) {
        return Err(value_error(format!(
            "label offset {offset:?} is not finite"
        )));
    }
    let object = scene.add_object(name);
    scene.labels.push(TextLabel {
        at: p,
        text: text.to_string(),
        size,
        color,
        anchor,
        offset: [offset.0, offset.1],
        object,
    });
    Ok(scene.labels.len() as u32 - 1)
}
