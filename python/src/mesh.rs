//! numpy arrays to scene faces: shapes, finite values and indices checked at the
//! boundary, one unlit material per distinct face colour.

use std::collections::HashMap;

use glam::DVec3;
use limn_scene::{Material, Scene};
use numpy::{PyReadonlyArray1, PyReadonlyArray2};
use pyo3::prelude::*;

use crate::errors::value_error;

/// Per-face colours: `(M, 3)` or `(M, 4)` RGB(A) in 0..1.
pub(crate) type Colors<'py> = Option<PyReadonlyArray2<'py, f64>>;

/// Adds one mesh to `scene` as object `name`. Vertices `(N, 3)` finite; faces `(M, 3)`
/// or `(M, 4)` indices into the vertices; colours per face `(M, 3)` or `(M, 4)` in
/// 0..1 (alpha is opacity, multiplied by `opacity` when given). Faces without colours
/// are drawn in a grey lit by the scene's lights (a headlight when there are none);
/// coloured faces in exactly their colour. Returns the id of the mesh's first face.
pub(crate) fn add_mesh(
    target: &mut Scene,
    name: &str,
    vertices: &PyReadonlyArray2<'_, f64>,
    faces: &PyReadonlyArray2<'_, i64>,
    colors: &Colors<'_>,
    opacity: Option<f64>,
) -> PyResult<u32> {
    let v = vertices.as_array();
    if v.ncols() != 3 {
        return Err(value_error(format!(
            "vertices must have shape (N, 3), not {:?}",
            v.shape()
        )));
    }
    let f = faces.as_array();
    if f.ncols() != 3 && f.ncols() != 4 {
        return Err(value_error(format!(
            "faces must have shape (M, 3) or (M, 4), not {:?}",
            f.shape()
        )));
    }
    if let Some(op) = opacity {
        if !(0.0..=1.0).contains(&op) {
            return Err(value_error(format!("opacity {op} is outside 0..1")));
        }
    }
    let colors = colors.as_ref().map(|c| c.as_array());
    if let Some(c) = &colors {
        if c.nrows() != f.nrows() || (c.ncols() != 3 && c.ncols() != 4) {
            return Err(value_error(format!(
                "colors must have shape ({0}, 3) or ({0}, 4) (one per face), not {1:?}",
                f.nrows(),
                c.shape()
            )));
        }
        if let Some((i, x)) = c
            .iter()
            .enumerate()
            .find(|(_, x)| !(0.0..=1.0).contains(*x))
        {
            return Err(value_error(format!(
                "colors[{}, {}] = {x} is outside 0..1",
                i / c.ncols(),
                i % c.ncols()
            )));
        }
    }
    let first_vertex = target.vertices.len() as u32;
    let n = v.nrows();
    let mut points = Vec::with_capacity(n);
    for i in 0..n {
        let p = DVec3::new(v[[i, 0]], v[[i, 1]], v[[i, 2]]);
        if !p.is_finite() {
            return Err(value_error(format!(
                "vertices[{i}] = ({}, {}, {}) is not finite",
                p.x, p.y, p.z
            )));
        }
        points.push(p);
    }
    let mut corners: Vec<Vec<u32>> = Vec::with_capacity(f.nrows());
    for (j, row) in f.outer_iter().enumerate() {
        let mut face = Vec::with_capacity(row.len());
        for &k in row.iter() {
            if k < 0 || k as usize >= n {
                return Err(value_error(format!(
                    "faces[{j}] refers to vertex {k}, outside 0..{n}"
                )));
            }
            face.push(first_vertex + k as u32);
        }
        corners.push(face);
    }
    // Everything checked: change a copy, so that a face the scene refuses leaves the
    // scene as it was.
    let mut s = target.clone();
    let scene = &mut s;
    for p in points {
        scene.add_vertex(p);
    }
    let object = scene.add_object(name);
    let grey = opacity.map_or_else(Material::default_grey, |op| Material {
        opacity: op,
        ..Material::default_grey()
    });
    let mut materials: HashMap<[u64; 4], u32> = HashMap::new();
    let first_face = scene.faces.len() as u32;
    for (j, face) in corners.iter().enumerate() {
        let material = match &colors {
            None => *materials
                .entry([u64::MAX; 4])
                .or_insert_with(|| scene.add_material(grey.clone())),
            Some(c) => {
                let rgb = [c[[j, 0]], c[[j, 1]], c[[j, 2]]];
                let a = if c.ncols() == 4 { c[[j, 3]] } else { 1.0 };
                let a = a * opacity.unwrap_or(1.0);
                let key = [rgb[0], rgb[1], rgb[2], a].map(f64::to_bits);
                let count = materials.len();
                *materials.entry(key).or_insert_with(|| {
                    let mut m = Material::unlit(&format!("{name}{count}"), rgb);
                    m.opacity = a;
                    scene.add_material(m)
                })
            }
        };
        scene
            .add_face(face, material, object)
            .map_err(|e| value_error(format!("faces[{j}]: {e}")))?;
    }
    *target = s;
    Ok(first_face)
}

/// A 3-vector from Python.
pub(crate) fn vec3(what: &str, v: Option<(f64, f64, f64)>) -> PyResult<Option<DVec3>> {
    match v {
        None => Ok(None),
        Some((x, y, z)) => {
            let p = DVec3::new(x, y, z);
            if p.is_finite() {
                Ok(Some(p))
            } else {
                Err(value_error(format!("{what} ({x}, {y}, {z}) is not finite")))
            }
        }
    }
}

/// A flat array of 16 numbers (a 4×4 matrix in row-major order) from numpy.
pub(crate) fn matrix(m: &PyReadonlyArray1<'_, f64>) -> PyResult<glam::DMat4> {
    let a = m.as_array();
    if a.len() != 16 {
        return Err(value_error("the view-projection matrix must be 4×4"));
    }
    let rows: Vec<f64> = a.iter().copied().collect();
    let mut cols = [0.0; 16];
    for r in 0..4 {
        for c in 0..4 {
            cols[c * 4 + r] = rows[r * 4 + c];
        }
    }
    Ok(glam::DMat4::from_cols_array(&cols))
}
