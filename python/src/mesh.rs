//! numpy arrays to scene faces: shapes, finite values and indices checked at the
//! boundary, one unlit material per distinct face colour. A face may have any number of
//! corners (three or more); the kernel's face conversion draws every one, convex or
//! not, planar or not.

use std::collections::HashMap;

use glam::DVec3;
use limn_scene::{Material, Scene};
use numpy::{PyReadonlyArray1, PyReadonlyArray2};
use pyo3::prelude::*;

use crate::errors::value_error;

/// Per-face colours: `(M, 3)` or `(M, 4)` RGB(A) in 0..1.
pub(crate) type Colors<'py> = Option<PyReadonlyArray2<'py, f64>>;

/// The faces of a mesh as they come from Python: without `counts`, `faces` is an
/// `(M, k)` array of `M` faces of `k` corners each; with `counts` (`(M,)`, one corner
/// count per face), `faces` is the `(K,)` array of every face's corner indices one face
/// after another, `K` being the sum of the counts.
pub(crate) struct Faces<'a, 'py> {
    /// The `(M, k)` or `(K,)` index array.
    pub(crate) faces: &'a Bound<'py, PyAny>,
    /// The corner count of each face, when `faces` is flat.
    pub(crate) counts: Option<&'a PyReadonlyArray1<'py, i64>>,
}

/// Every face's corners checked against `n` vertices: the indices one face after
/// another, and where each face starts in them (`M + 1` entries, the last one the
/// number of indices).
struct Corners {
    /// Vertex indices of the mesh, one face after another.
    indices: Vec<u32>,
    /// Face `j` is `indices[starts[j]..starts[j + 1]]`.
    starts: Vec<usize>,
}

impl Corners {
    /// The number of faces.
    fn faces(&self) -> usize {
        self.starts.len() - 1
    }

    /// The corners of face `j`.
    fn face(&self, j: usize) -> &[u32] {
        &self.indices[self.starts[j]..self.starts[j + 1]]
    }
}

/// The message for face `j` of `count` corners, when `count` is less than three.
fn too_few(j: usize, count: i64) -> PyErr {
    value_error(format!(
        "faces[{j}] has {count} corners; at least 3 are needed"
    ))
}

/// Reads and checks the faces: at least three corners each, every index in `0..n`.
fn corners(faces: &Faces<'_, '_>, n: usize) -> PyResult<Corners> {
    let index = |j: usize, k: i64| -> PyResult<u32> {
        if k < 0 || k as u64 >= n as u64 {
            Err(value_error(format!(
                "faces[{j}] refers to vertex {k}, outside 0..{n}"
            )))
        } else {
            Ok(k as u32)
        }
    };
    match faces.counts {
        None => {
            let f = faces
                .faces
                .extract::<PyReadonlyArray2<'_, i64>>()
                .map_err(|_| value_error("faces must be an (M, k) array of int64 indices"))?;
            let f = f.as_array();
            let (m, k) = (f.nrows(), f.ncols());
            if k < 3 {
                return Err(if m == 0 {
                    value_error(format!(
                        "faces must have shape (M, k) with k >= 3, not {:?}",
                        f.shape()
                    ))
                } else {
                    too_few(0, k as i64)
                });
            }
            let mut indices = Vec::with_capacity(m * k);
            for (j, row) in f.outer_iter().enumerate() {
                for &v in row.iter() {
                    indices.push(index(j, v)?);
                }
            }
            Ok(Corners {
                indices,
                starts: (0..=m).map(|j| j * k).collect(),
            })
        }
        Some(counts) => {
            let f = faces
                .faces
                .extract::<PyReadonlyArray1<'_, i64>>()
                .map_err(|_| {
                    value_error("with counts, faces must be a flat (K,) array of int64 indices")
                })?;
            let f = f.as_array();
            let counts = counts.as_array();
            if let Some((j, &c)) = counts.iter().enumerate().find(|(_, &c)| c < 3) {
                return Err(too_few(j, c));
            }
            let total: i128 = counts.iter().map(|&c| i128::from(c)).sum();
            if total != f.len() as i128 {
                return Err(value_error(format!(
                    "the counts add up to {total} corners, but faces holds {} indices",
                    f.len()
                )));
            }
            let mut starts = Vec::with_capacity(counts.len() + 1);
            starts.push(0);
            for &c in counts.iter() {
                starts.push(starts[starts.len() - 1] + c as usize);
            }
            let mut indices = Vec::with_capacity(f.len());
            let mut j = 0;
            for (i, &v) in f.iter().enumerate() {
                while i >= starts[j + 1] {
                    j += 1;
                }
                indices.push(index(j, v)?);
            }
            Ok(Corners { indices, starts })
        }
    }
}

/// Adds one mesh to `scene` as object `name`. Vertices `(N, 3)` finite; `faces` (see
/// [`Faces`]) of any number of corners from three up, indices into the vertices;
/// colours per face `(M, 3)` or `(M, 4)` in 0..1 (alpha is opacity, multiplied by
/// `opacity` when given). Faces without colours are drawn in a grey lit by the scene's
/// lights (a headlight when there are none); coloured faces in exactly their colour.
/// Returns the id of the mesh's first face. On error the scene is left as it was.
pub(crate) fn add_mesh(
    target: &mut Scene,
    name: &str,
    vertices: &PyReadonlyArray2<'_, f64>,
    faces: &Faces<'_, '_>,
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
    let n = v.nrows();
    let corners = corners(faces, n)?;
    let m = corners.faces();
    if let Some(op) = opacity {
        if !(0.0..=1.0).contains(&op) {
            return Err(value_error(format!("opacity {op} is outside 0..1")));
        }
    }
    let colors = colors.as_ref().map(|c| c.as_array());
    if let Some(c) = &colors {
        if c.nrows() != m || (c.ncols() != 3 && c.ncols() != 4) {
            return Err(value_error(format!(
                "colors must have shape ({m}, 3) or ({m}, 4) (one per face), not {:?}",
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
    // Everything checked: change a copy, so that a face the scene refuses leaves the
    // scene as it was.
    let mut s = target.clone();
    let scene = &mut s;
    let first_vertex = scene.vertices.len() as u32;
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
    let mut face = Vec::new();
    for j in 0..m {
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
        face.clear();
        face.extend(corners.face(j).iter().map(|&k| first_vertex + k));
        scene
            .add_face(&face, material, object)
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
