//! `limn.Scene`: several meshes, lights and a camera; render, check against a
//! reference, or hand the painted polygons to another drawing system.

use std::borrow::Cow;
use std::collections::{HashMap, VecDeque};
use std::path::PathBuf;

use glam::DVec3;
use limn::{Collected, Input, Request, SceneOptions, ViewOptions};
use limn_depthsort::order_with_marks;
use limn_paint::{
    add_seam_flaps_beside_strokes, picture_with_marks_unflapped, Mark, MarkKind, PaintFragment,
    Style,
};
use limn_scene::{Light, LightKind, Scene};
use numpy::{PyArray2, PyReadonlyArray1, PyReadonlyArray2};
use pyo3::prelude::*;
use pyo3::types::{PyAny, PyDict};

use crate::errors::{raise, value_error, warn};
use crate::mesh::{add_mesh, vec3, Colors, Faces};
use crate::render::{check_options, json_object, on_threads, order_names, RenderKeywords};

/// A scene; see the Python stub `limn/_limn.pyi` for the documentation.
#[pyclass(name = "Scene", module = "limn")]
pub(crate) struct PyScene {
    scene: Scene,
    /// What a scene file said (size, background, outline, style, …); unset otherwise.
    settings: SceneOptions,
    /// The scene's name in messages: its file, or `scene`.
    name: String,
    /// The camera set with `set_camera` (and a loaded file's `allow_outside`).
    view: ViewOptions,
}

impl PyScene {
    /// The input of a render or check: this scene, borrowed.
    fn input(&self) -> Input<'_> {
        Input::Scene {
            scene: Cow::Borrowed(&self.scene),
            settings: self.settings.clone(),
            name: self.name.clone(),
        }
    }
}

/// Loads a mesh or scene file; see the Python wrapper `limn.load`.
#[pyfunction]
#[pyo3(signature = (path, allow_outside=false))]
pub(crate) fn load(py: Python<'_>, path: PathBuf, allow_outside: bool) -> PyResult<PyScene> {
    let view = ViewOptions {
        allow_outside,
        ..ViewOptions::default()
    };
    let mut events = Collected::default();
    let input = Input::File(path);
    let loaded = py
        .detach(|| {
            limn::load(&input, &view, &mut events)
                .map(|l| (l.scene.into_owned(), l.settings, l.name))
        })
        .map_err(raise)?;
    warn(py, &events.warnings)?;
    Ok(PyScene {
        scene: loaded.0,
        settings: loaded.1,
        name: loaded.2,
        view,
    })
}

/// A painted polygon: face, points `(n, 2)` in pixels, fill RGBA, original edges.
type Painted<'py> = (u32, Bound<'py, PyAny>, (f64, f64, f64, f64), Vec<bool>);

/// Pixel points as an `(n, 2)` array.
fn xy<'py>(py: Python<'py>, pts: &[[f64; 2]]) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let rows: Vec<Vec<f64>> = pts.iter().map(|p| p.to_vec()).collect();
    PyArray2::from_vec2(py, &rows).map_err(value_error)
}

/// One entry of `paint_with_marks`: a fragment, or a run of fragments joined.
struct Entry {
    /// The (first) fragment's index in the picture.
    first: usize,
    /// For a joined run, the rings of its union (outer rings and holes turned opposite
    /// ways); `None` for a fragment given as it is.
    rings: Option<Vec<Vec<[f64; 2]>>>,
}

/// One value per face from the optional array argument `name` (empty when not given);
/// a `ValueError` counting its `what` when there are not `faces` of them.
fn per_face<T: numpy::Element + Copy>(
    values: Option<&PyReadonlyArray1<'_, T>>,
    (name, what): (&str, &str),
    faces: usize,
) -> PyResult<Vec<T>> {
    let Some(values) = values else {
        return Ok(Vec::new());
    };
    let values = values.as_slice().map_err(value_error)?.to_vec();
    if values.len() != faces {
        return Err(value_error(format!(
            "{name} has {} {what} for {faces} faces",
            values.len()
        )));
    }
    Ok(values)
}

/// Decimals of the grid a joined run is rounded to: a millionth of a pixel, fewer where
/// the run reaches so far from the origin that the grid would leave the integer
/// engine's range (`None` below a hundredth of a pixel: the run stays as it is).
fn join_decimals(run: &[PaintFragment]) -> Option<u8> {
    let reach = run
        .iter()
        .flat_map(|f| f.points.iter())
        .fold(0.0f64, |m, p| m.max(p[0].abs()).max(p[1].abs()));
    (2..=6u8)
        .rev()
        .find(|&d| reach * 10f64.powi(i32::from(d)) < f64::from(1u32 << 30) / 2.0)
}

/// The picture's fragments as entries: each maximal run of fragments of faces of one
/// group of `join` (per face; negative: none), flat (no vertex colours, no texture) in
/// one fill, with no mark painted between them and two or more pieces (fragments that
/// are not seam flaps), as
/// the union of its pieces (`limn_paint::union_of_polygons`: what their subpaths fill,
/// on a grid of a millionth of a pixel) and its flaps, turned as the union's outer
/// rings; every other fragment as it is. Also, per picture position (0 to the fragment count), the entry
/// position it becomes, for the marks' `before`.
fn joined(pic: &limn_paint::Picture, join: &[i64]) -> (Vec<Entry>, Vec<usize>) {
    let frags = &pic.fragments;
    let n = frags.len();
    let mut mark_at = vec![false; n + 1];
    for m in &pic.marks {
        mark_at[m.before.min(n)] = true;
    }
    let group = |f: &PaintFragment| join.get(f.face as usize).copied().unwrap_or(-1);
    let joinable =
        |f: &PaintFragment| group(f) >= 0 && f.vertex_colors.is_none() && f.texture.is_none();
    let mut entries = Vec::with_capacity(n);
    let mut before = vec![0; n + 1];
    let mut i = 0;
    while i < n {
        let mut j = i + 1;
        if joinable(&frags[i]) {
            while j < n
                && !mark_at[j]
                && joinable(&frags[j])
                && group(&frags[j]) == group(&frags[i])
                && frags[j].fill == frags[i].fill
            {
                j += 1;
            }
        }
        let run = &frags[i..j];
        // The pieces tile the face's part: their union is cheap (shared edges, no
        // crossings). Seam flaps overlap later fragments: they stay rings of their own.
        let pieces: Vec<&[[f64; 2]]> = run
            .iter()
            .filter(|f| !f.flap)
            .map(|f| f.points.as_slice())
            .collect();
        let union = (pieces.len() >= 2)
            .then(|| join_decimals(run))
            .flatten()
            .and_then(|d| limn_paint::union_of_polygons(&pieces, d));
        let start = entries.len();
        match union {
            Some(shapes) => {
                let mut rings: Vec<Vec<[f64; 2]>> = shapes.into_iter().flatten().collect();
                let outer = rings.first().map_or(0.0, |r| area2(r));
                for f in run.iter().filter(|f| f.flap) {
                    let mut ring = f.points.clone();
                    if area2(&ring) * outer < 0.0 {
                        ring.reverse();
                    }
                    rings.push(ring);
                }
                if !rings.is_empty() {
                    entries.push(Entry {
                        first: i,
                        rings: Some(rings),
                    });
                }
            }
            None => entries.extend((i..j).map(|k| Entry {
                first: k,
                rings: None,
            })),
        }
        // A mark is never painted inside a joined run: its fragments all map to the
        // entry's place.
        for (k, b) in before.iter_mut().enumerate().take(j).skip(i) {
            *b = (start + k - i).min(entries.len());
        }
        i = j;
    }
    before[n] = entries.len();
    (entries, before)
}

/// Twice the signed area of a polygon.
fn area2(p: &[[f64; 2]]) -> f64 {
    (0..p.len())
        .map(|i| {
            let (a, b) = (p[i], p[(i + 1) % p.len()]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum()
}

/// One painted mark as a dict (see `paint_with_marks`).
fn mark_dict<'py>(py: Python<'py>, m: &Mark) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("before", m.before)?;
    let rgba = |c: [f64; 4]| (c[0], c[1], c[2], c[3]);
    match &m.kind {
        MarkKind::Line(l) => {
            d.set_item("kind", "line")?;
            d.set_item("points", xy(py, &l.points)?)?;
            d.set_item("color", rgba(l.style.color))?;
            d.set_item("width", l.style.width)?;
            d.set_item("dash", l.style.dash.clone())?;
            d.set_item("dash_offset", l.dash_offset)?;
        }
        MarkKind::Marker(k) => {
            d.set_item("kind", "marker")?;
            d.set_item("at", (k.at[0], k.at[1]))?;
            d.set_item("shape", k.shape.name())?;
            d.set_item("size", k.size)?;
            d.set_item("color", rgba(k.color))?;
            d.set_item("stroke", k.stroke)?;
        }
        MarkKind::Label(l) => {
            d.set_item("kind", "label")?;
            d.set_item("at", (l.at[0], l.at[1]))?;
            d.set_item("offset", (l.offset[0], l.offset[1]))?;
            d.set_item("anchor", l.anchor.name())?;
            d.set_item("text", l.text.clone())?;
            d.set_item("size", l.size)?;
            d.set_item("color", rgba(l.color))?;
        }
        MarkKind::Head(h) => {
            d.set_item("kind", "head")?;
            d.set_item("points", xy(py, &h.points)?)?;
            d.set_item("color", rgba(h.color))?;
        }
    }
    Ok(d)
}

/// An RGB colour in 0..1 from Python.
fn rgb(what: &str, c: (f64, f64, f64)) -> PyResult<[f64; 3]> {
    let c = [c.0, c.1, c.2];
    if c.iter().all(|v| (0.0..=1.0).contains(v)) {
        Ok(c)
    } else {
        Err(value_error(format!("{what} {c:?} is outside 0..1")))
    }
}

#[pymethods]
impl PyScene {
    #[new]
    fn new() -> Self {
        PyScene {
            scene: Scene::default(),
            settings: SceneOptions::default(),
            name: "scene".into(),
            view: ViewOptions::default(),
        }
    }

    /// Adds a mesh; returns the id of its first face (faces are numbered in the order
    /// they are added, over all meshes).
    #[pyo3(signature = (vertices, faces, counts=None, colors=None, opacity=None, name="mesh"))]
    fn add_mesh(
        &mut self,
        vertices: PyReadonlyArray2<'_, f64>,
        faces: Bound<'_, PyAny>,
        counts: Option<PyReadonlyArray1<'_, i64>>,
        colors: Colors<'_>,
        opacity: Option<f64>,
        name: &str,
    ) -> PyResult<u32> {
        let faces = Faces {
            faces: &faces,
            counts: counts.as_ref(),
        };
        add_mesh(&mut self.scene, name, &vertices, &faces, &colors, opacity)
    }

    /// Adds a polyline through `points` `(N, 3)`; returns its index.
    #[pyo3(signature = (points, color, width, dash, head, name="line"))]
    #[allow(clippy::too_many_arguments)]
    fn add_line(
        &mut self,
        points: PyReadonlyArray2<'_, f64>,
        color: Vec<f64>,
        width: f64,
        dash: Vec<f64>,
        head: bool,
        name: &str,
    ) -> PyResult<u32> {
        crate::marks::add_line(&mut self.scene, name, &points, &color, width, &dash, head)
    }

    /// Adds point markers at `positions` `(N, 3)`, one size `(N,)` and one colour
    /// `(N, 3|4)` each; returns the index of the first.
    #[pyo3(signature = (positions, marker, sizes, colors, name="points"))]
    fn add_points(
        &mut self,
        positions: PyReadonlyArray2<'_, f64>,
        marker: &str,
        sizes: PyReadonlyArray1<'_, f64>,
        colors: PyReadonlyArray2<'_, f64>,
        name: &str,
    ) -> PyResult<u32> {
        crate::marks::add_points(&mut self.scene, name, &positions, marker, &sizes, &colors)
    }

    /// Adds a text label anchored at `at`; returns its index.
    #[pyo3(signature = (at, text, size, color, anchor, offset, name="label"))]
    #[allow(clippy::too_many_arguments)]
    fn add_label(
        &mut self,
        at: (f64, f64, f64),
        text: &str,
        size: f64,
        color: Vec<f64>,
        anchor: &str,
        offset: (f64, f64),
        name: &str,
    ) -> PyResult<u32> {
        crate::marks::add_label(
            &mut self.scene,
            name,
            at,
            text,
            size,
            &color,
            anchor,
            offset,
        )
    }

    /// Numbers of lines, point markers and labels.
    #[getter]
    fn mark_counts(&self) -> (usize, usize, usize) {
        (
            self.scene.lines.len(),
            self.scene.points.len(),
            self.scene.labels.len(),
        )
    }

    /// Adds a light: `"ambient"`, `"directional"` (`vector` points towards the light),
    /// `"point"` (`vector` is its position) or `"headlight"`; `shadows` makes a
    /// directional or point light cast exact shadows.
    #[pyo3(signature = (kind, vector=None, color=(1.0, 1.0, 1.0), shadows=false))]
    fn add_light(
        &mut self,
        kind: &str,
        vector: Option<(f64, f64, f64)>,
        color: (f64, f64, f64),
        shadows: bool,
    ) -> PyResult<()> {
        let v = vec3("light vector", vector)?;
        let need = || value_error(format!("a {kind} light needs a vector"));
        let kind = match kind {
            "ambient" => LightKind::Ambient,
            "headlight" => LightKind::Headlight,
            "directional" => LightKind::Directional(v.ok_or_else(need)?),
            "point" => LightKind::Point(v.ok_or_else(need)?),
            _ => {
                return Err(value_error(format!(
                    "unknown light `{kind}` (ambient, directional, point or headlight)"
                )))
            }
        };
        if let LightKind::Directional(d) = kind {
            if d == DVec3::ZERO {
                return Err(value_error("a directional light needs a non-zero vector"));
            }
        }
        if shadows && matches!(kind, LightKind::Ambient | LightKind::Headlight) {
            return Err(value_error(
                "only directional and point lights cast shadows (shadows=True)",
            ));
        }
        self.scene.lights.push(Light {
            kind,
            color: rgb("light color", color)?,
            shadows,
        });
        Ok(())
    }

    /// Sets the camera (see the stub for the parameters).
    #[pyo3(signature = (eye=None, target=None, up=(0.0, 1.0, 0.0), fov=45.0, size=(800, 600),
        projection="perspective", height=None, matrix=None))]
    #[allow(clippy::too_many_arguments)]
    fn set_camera(
        &mut self,
        eye: Option<(f64, f64, f64)>,
        target: Option<(f64, f64, f64)>,
        up: (f64, f64, f64),
        fov: f64,
        size: (i64, i64),
        projection: &str,
        height: Option<f64>,
        matrix: Option<PyReadonlyArray1<'_, f64>>,
    ) -> PyResult<()> {
        let ortho = match projection {
            "perspective" if height.is_none() => None,
            "perspective" => return Err(value_error("height needs projection=\"orthographic\"")),
            "orthographic" => Some(height),
            _ => {
                return Err(value_error(format!(
                    "unknown projection `{projection}` (perspective or orthographic)"
                )))
            }
        };
        let matrix = matrix.as_ref().map(crate::mesh::matrix).transpose()?;
        let ok = |v: i64| (1..=65536).contains(&v);
        if !ok(size.0) || !ok(size.1) {
            return Err(value_error(format!(
                "size ({}, {}) must be two whole numbers from 1 to 65536",
                size.0, size.1
            )));
        }
        let p = |v: Option<DVec3>| v.map(|d| d.to_array());
        let view = ViewOptions {
            size: Some((size.0 as u32, size.1 as u32)),
            eye: p(vec3("eye", eye)?),
            target: p(vec3("target", target)?),
            up: p(vec3("up", Some(up))?),
            fov: Some(fov),
            ortho,
            matrix: matrix.map(|m| m.to_cols_array()),
            allow_outside: self.view.allow_outside,
            ..ViewOptions::default()
        };
        view.validate().map_err(raise)?;
        self.view = view;
        Ok(())
    }

    /// Number of faces.
    #[getter]
    fn face_count(&self) -> usize {
        self.scene.faces.len()
    }

    /// Renders to `path` with the command's options; returns the statistics of
    /// `limn --stats` (for a painter's render) or `{"method", "warnings"}`.
    #[pyo3(signature = (path, format=None, sort=None, arith=None, cull=None, outline=false,
        outline_color=None, outline_width=None, background=None, style=None, hidden=None,
        fill=None, crease=None, seams=limn::DEFAULT_SEAMS, shading=None,
        shading_tolerance=limn::DEFAULT_SHADING_TOLERANCE,
        texture_samples=limn::DEFAULT_TEXTURE_SAMPLES, method="painter",
        shadow_map_size=limn::DEFAULT_SHADOW_MAP_SIZE, shadow_bias=limn::DEFAULT_SHADOW_BIAS,
        standalone=false, max_fragments=None, visible=false, near=None, far=None, threads=None,
        stats=None))]
    #[allow(clippy::too_many_arguments)]
    fn render<'py>(
        &self,
        py: Python<'py>,
        path: PathBuf,
        format: Option<&str>,
        sort: Option<&str>,
        arith: Option<&str>,
        cull: Option<&str>,
        outline: bool,
        outline_color: Option<(f64, f64, f64)>,
        outline_width: Option<f64>,
        background: Option<Bound<'py, PyAny>>,
        style: Option<&str>,
        hidden: Option<&str>,
        fill: Option<&str>,
        crease: Option<f64>,
        seams: f64,
        shading: Option<&str>,
        shading_tolerance: f64,
        texture_samples: f64,
        method: &str,
        shadow_map_size: u32,
        shadow_bias: f64,
        standalone: bool,
        max_fragments: Option<usize>,
        visible: bool,
        near: Option<f64>,
        far: Option<f64>,
        threads: Option<usize>,
        stats: Option<PathBuf>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let kw = RenderKeywords {
            format,
            sort,
            arith,
            cull,
            outline,
            outline_color,
            outline_width,
            background: background.as_ref(),
            style,
            hidden,
            fill,
            crease,
            seams,
            shading,
            shading_tolerance,
            texture_samples,
            method,
            shadow_map_size,
            shadow_bias,
            standalone,
            max_fragments,
            visible,
            near,
            far,
            stats,
        };
        let (options, settings) = kw.options(&self.view, &self.settings)?;
        let req = Request {
            input: Input::Scene {
                scene: Cow::Borrowed(&self.scene),
                settings,
                name: self.name.clone(),
            },
            output: Some(path),
            options,
        };
        let mut events = Collected::default();
        let done = py
            .detach(|| on_threads(threads, || limn::render(&req, &mut events)))?
            .map_err(raise)?;
        warn(py, &done.warnings)?;
        match &done.stats {
            Some(s) => json_object(py, &s.to_json()),
            None => {
                let d = PyDict::new(py);
                d.set_item("method", done.method.name())?;
                d.set_item("warnings", done.warnings.clone())?;
                Ok(d.into_any())
            }
        }
    }

    /// Compares the painted picture with an image-space reference pixel by pixel; the
    /// report `limn check` prints, with `agrees` and `failures`.
    #[pyo3(signature = (against="raycast", sort=None, arith=None, seams=limn::DEFAULT_SEAMS,
        visible=false, diff=None, stats=None, threads=None))]
    #[allow(clippy::too_many_arguments)]
    fn check<'py>(
        &self,
        py: Python<'py>,
        against: &str,
        sort: Option<&str>,
        arith: Option<&str>,
        seams: f64,
        visible: bool,
        diff: Option<PathBuf>,
        stats: Option<PathBuf>,
        threads: Option<usize>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let o = check_options(
            &self.view, against, sort, arith, seams, visible, diff, stats,
        )?;
        let input = self.input();
        let mut events = Collected::default();
        let report = py
            .detach(|| on_threads(threads, || limn::check(&input, &o, &mut events)))?
            .map_err(raise)?;
        warn(py, &events.warnings)?;
        let d = json_object(py, &report.json)?;
        d.set_item("agrees", report.agrees())?;
        d.set_item("failures", report.failures.clone())?;
        Ok(d)
    }

    /// The painted picture as polygons in paint order (back to front), in pixels (x
    /// right, y down): a list of `(face, points (n, 2), fill (r, g, b, a), original
    /// edges)`, seam flaps `seams` pixels wide included.
    #[pyo3(signature = (sort=None, arith=None, seams=limn::DEFAULT_SEAMS))]
    fn paint<'py>(
        &self,
        py: Python<'py>,
        sort: Option<&str>,
        arith: Option<&str>,
        seams: f64,
    ) -> PyResult<Vec<Painted<'py>>> {
        Ok(self.paint_with_marks(py, sort, arith, seams, None, None)?.0)
    }

    /// [`PyScene::paint`] and the visible marks: a list of dicts with `before` (the
    /// index of the polygon they are painted before; the polygons' count = after all)
    /// and `kind` (`"line"`: `points (n, 2)`, `color`, `width`, `dash`, `dash_offset`;
    /// `"marker"`: `at`, `shape`, `size`, `color`, `stroke`; `index`: the input line,
    /// point or label (in the order they were added; `None` for heads); `"label"`: `at`, `offset`,
    /// `anchor`, `text`, `size`, `color`; `"head"`: `points (3, 2)`, `color`).
    /// `join`, one group per face (negative: none): the flat fragments of faces of one
    /// group painted one after another in one fill with no mark between them come as
    /// one entry whose points are the rings of their union (see [`joined`]); the faces
    /// of a group must not overlap (a polygon's triangles, the faces of one region).
    /// `stroked`, one flag per face: the caller strokes every original edge of the face,
    /// opaque and at least `seams` pixels wide, right after its fill; such edges get no
    /// seam flap (the stroke covers the seam).
    #[pyo3(signature = (sort=None, arith=None, seams=limn::DEFAULT_SEAMS, join=None, stroked=None))]
    fn paint_with_marks<'py>(
        &self,
        py: Python<'py>,
        sort: Option<&str>,
        arith: Option<&str>,
        seams: f64,
        join: Option<PyReadonlyArray1<'py, i64>>,
        stroked: Option<PyReadonlyArray1<'py, bool>>,
    ) -> PyResult<(Vec<Painted<'py>>, Vec<Bound<'py, PyDict>>)> {
        let mut view = self.view.clone();
        order_names(&mut view, sort, arith, None)?;
        limn::values::seams(seams).map_err(value_error)?;
        view.validate().map_err(raise)?;
        self.scene.validate().map_err(value_error)?;
        let cam =
            limn::camera(&self.scene, &view, self.settings.size, &self.name).map_err(raise)?;
        let mut oo = limn::order_options(&view, &self.settings).map_err(raise)?;
        // The bridge draws a translucent polygon whole where its fragments follow one
        // another: its parts behind opaque faces must stay in their places.
        oo.translucent_last = false;
        let (mut ordered, marks) = py
            .detach(|| order_with_marks(&self.scene, &cam, &oo))
            .map_err(value_error)?;
        let style = Style {
            seams,
            ..Style::default()
        };
        let faces = self.scene.faces.len();
        let stroked = per_face(stroked.as_ref(), ("stroked", "flags"), faces)?;
        let mut pic = picture_with_marks_unflapped(&self.scene, &mut ordered, &marks, &style);
        add_seam_flaps_beside_strokes(&mut pic, &style, &stroked);
        let join = per_face(join.as_ref(), ("join", "groups"), faces)?;
        let (runs, before) = joined(&pic, &join);
        for m in &mut pic.marks {
            m.before = before[m.before];
        }
        let polys = runs
            .into_iter()
            .map(|run| {
                let f = &pic.fragments[run.first];
                let [r, g, b, a] = f.fill;
                let edges = if run.rings.is_some() {
                    Vec::new()
                } else {
                    f.original_edges.clone()
                };
                let points = match run.rings {
                    None => xy(py, &f.points)?.into_any(),
                    Some(rings) => {
                        let arrays = rings
                            .iter()
                            .map(|ring| xy(py, ring))
                            .collect::<PyResult<Vec<_>>>()?;
                        pyo3::types::PyList::new(py, arrays)?.into_any()
                    }
                };
                Ok((f.face, points, (r, g, b, a), edges))
            })
            .collect::<PyResult<Vec<_>>>()?;
        // The picture's markers and labels carry no input index: they come in the order
        // of the visible anchors at each position (a stable sort), so the first unused
        // anchor at the same pixel is theirs.
        let queue = |v: &[limn_depthsort::VisibleAnchor]| {
            let mut q: HashMap<[u64; 2], VecDeque<u32>> = HashMap::new();
            for a in v {
                q.entry(a.at.map(f64::to_bits))
                    .or_default()
                    .push_back(a.index);
            }
            q
        };
        let (mut points, mut labels) = (queue(&marks.points), queue(&marks.labels));
        let marks = pic
            .marks
            .iter()
            .map(|m| {
                let index = match &m.kind {
                    MarkKind::Line(l) => Some(l.line),
                    MarkKind::Marker(k) => points
                        .get_mut(&k.at.map(f64::to_bits))
                        .and_then(VecDeque::pop_front),
                    MarkKind::Label(l) => labels
                        .get_mut(&l.at.map(f64::to_bits))
                        .and_then(VecDeque::pop_front),
                    MarkKind::Head(_) => None,
                };
                let d = mark_dict(py, m)?;
                d.set_item("index", index)?;
                Ok(d)
            })
            .collect::<PyResult<Vec<_>>>()?;
        Ok((polys, marks))
    }
}
