//! Ordering and writing: options by name, the picture written atomically (nothing is
//! left on error), and the statistics `limn --stats` prints, as a dict.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Instant;

use limn_depthsort::{order_with_marks, Arith, MarkStats, OrderOptions, Ordered, SortMode};
use limn_paint::{painter_for, picture_with_marks, Format, PaintStats, Style};
use limn_scene::{Effects, Scene};
use numpy::{PyReadonlyArray1, PyReadonlyArray2};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::camera::CameraSpec;
use crate::errors::{os_error, value_error};
use crate::mesh::{add_mesh, vec3, Colors, Faces};

/// Ordering options by name, as the command takes them.
pub(crate) fn order_options(sort: &str, arith: &str) -> PyResult<OrderOptions> {
    let sort = SortMode::from_name(sort).ok_or_else(|| {
        value_error(format!(
            "unknown sort `{sort}` (adaptive, bsp, newell or simple)"
        ))
    })?;
    let arith = Arith::from_name(arith)
        .ok_or_else(|| value_error(format!("unknown arith `{arith}` (exact or float)")))?;
    Ok(OrderOptions {
        sort,
        arith,
        ..OrderOptions::default()
    })
}

/// The output format: the name given, else the path's extension.
pub(crate) fn format_of(path: &Path, format: Option<&str>) -> PyResult<Format> {
    if let Some(f) = format {
        return Format::from_name(f).ok_or_else(|| {
            value_error(format!("unknown format `{f}` (svg, pdf, eps, png or tikz)"))
        });
    }
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
    Format::from_extension(ext).ok_or_else(|| {
        value_error(format!(
            "{}: unknown extension `.{ext}` (use .svg, .pdf, .eps, .png, .tikz or format=)",
            path.display()
        ))
    })
}

/// Writes through a temporary file in the same folder, renamed over `path` once
/// complete: a failure leaves no file behind.
pub(crate) fn write_atomic(
    path: &Path,
    write: impl FnOnce(&mut dyn Write) -> Result<PaintStats, limn_paint::PaintError>,
) -> PyResult<PaintStats> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    if path.is_dir() {
        return Err(os_error(path, "is a folder"));
    }
    let mut tmp = tempfile::NamedTempFile::new_in(&dir).map_err(|e| os_error(path, e))?;
    let stats = {
        let mut w = std::io::BufWriter::new(tmp.as_file_mut());
        let stats = write(&mut w).map_err(|e| os_error(path, e))?;
        w.flush().map_err(|e| os_error(path, e))?;
        stats
    };
    tmp.persist(path).map_err(|e| os_error(path, e.error))?;
    Ok(stats)
}

/// Milliseconds since `t`.
fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

/// Orders `scene` and writes its picture to `path`; the statistics as `limn --stats`
/// prints them.
#[allow(clippy::too_many_arguments)]
pub(crate) fn render_scene<'py>(
    py: Python<'py>,
    scene: &Scene,
    spec: &CameraSpec,
    path: &Path,
    format: Option<&str>,
    oo: &OrderOptions,
    style: &Style,
    t_load: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let t0 = Instant::now();
    let format = format_of(path, format)?;
    let cam = spec.camera(scene)?;
    let (ordered, marks) = py
        .detach(|| order_with_marks(scene, &cam, oo))
        .map_err(value_error)?;
    let t_order = ms(t0);
    let t1 = Instant::now();
    let pic = picture_with_marks(scene, &ordered, &marks, style);
    let ps = write_atomic(path, |w| painter_for(format).paint(&pic, w))?;
    let t_write = ms(t1);
    stats_dict(
        py,
        scene,
        &ordered,
        oo,
        (&ps, &marks.stats),
        [t_load, t_order, t_write],
    )
}

/// The statistics of `limn --stats`, with the same keys.
pub(crate) fn stats_dict<'py>(
    py: Python<'py>,
    scene: &Scene,
    ordered: &Ordered,
    oo: &OrderOptions,
    (ps, marks): (&PaintStats, &MarkStats),
    [load, order, write]: [f64; 3],
) -> PyResult<Bound<'py, PyDict>> {
    let s = &ordered.stats;
    let d = PyDict::new(py);
    let mut effects: Vec<&str> = Effects::of(scene).names();
    if s.faces_culled > 0 {
        effects.push("backface-culling");
    }
    let counts: [(&str, usize); 18] = [
        ("faces_in", s.faces_in),
        ("faces_culled", s.faces_culled),
        ("faces_degenerate", s.faces_degenerate),
        ("faces_clipped", s.faces_clipped),
        ("faces_coincident", s.faces_coincident),
        ("faces_near_clipped", s.faces_near_clipped),
        ("polygons", s.polygons),
        ("candidate_pairs", s.candidate_pairs),
        ("constraints", s.constraints),
        ("components", s.components),
        ("largest_component", s.largest_component),
        ("splits", s.splits),
        ("parts_apart", s.parts_apart),
        ("fragments_before_merge", s.fragments_before_merge),
        ("fragments_out", s.fragments_out),
        ("fragments_made", s.fragments_made),
        ("fragment_limit", s.fragment_limit),
        ("fragments_in_shadow", s.fragments_in_shadow),
    ];
    for (k, v) in counts {
        d.set_item(k, v)?;
    }
    d.set_item("paths_out", ps.paths)?;
    d.set_item("bytes_out", ps.bytes)?;
    d.set_item("filter_fallbacks", s.filter_fallbacks)?;
    d.set_item("sort", oo.sort.name())?;
    d.set_item("arith", oo.arith.name())?;
    d.set_item("effects", effects)?;
    d.set_item("warnings", scene.warnings.clone())?;
    let l = PyDict::new(py);
    let mark_counts: [(&str, usize); 9] = [
        ("lines", marks.lines),
        ("segments_in", marks.segments_in),
        ("pieces_out", marks.pieces_out),
        ("hidden_pieces", marks.hidden_pieces),
        ("markers", marks.markers_in),
        ("markers_shown", marks.markers_shown),
        ("labels", marks.labels_in),
        ("labels_shown", marks.labels_shown),
        ("exact_tests", marks.exact_tests),
    ];
    for (k, v) in mark_counts {
        l.set_item(k, v)?;
    }
    l.set_item("line_paths_out", ps.lines)?;
    l.set_item("ms", marks.ms)?;
    d.set_item("lines", l)?;
    let t = PyDict::new(py);
    t.set_item("load", load)?;
    t.set_item("order", order)?;
    t.set_item("write", write)?;
    t.set_item("total", load + order + write)?;
    t.set_item("prepare", s.ms_prepare)?;
    t.set_item("sort", s.ms_order)?;
    t.set_item("merge", s.ms_merge)?;
    d.set_item("ms", t)?;
    Ok(d)
}

/// The picture style of the command's `render` (seam flaps on, no outlines, no
/// background).
pub(crate) fn command_style() -> Style {
    Style {
        seamless: true,
        smooth: true,
        ..Style::default()
    }
}

/// Renders one mesh; see the Python wrapper `limn.render_mesh` for the documentation.
#[pyfunction]
#[pyo3(signature = (vertices, faces, path, counts=None, colors=None, opacity=None, eye=None,
    target=None, up=(0.0, 1.0, 0.0), fov=45.0, size=(800, 600), sort="adaptive", arith="exact",
    format=None))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn render_mesh<'py>(
    py: Python<'py>,
    vertices: PyReadonlyArray2<'py, f64>,
    faces: Bound<'py, PyAny>,
    path: PathBuf,
    counts: Option<PyReadonlyArray1<'py, i64>>,
    colors: Colors<'py>,
    opacity: Option<f64>,
    eye: Option<(f64, f64, f64)>,
    target: Option<(f64, f64, f64)>,
    up: (f64, f64, f64),
    fov: f64,
    size: (i64, i64),
    sort: &str,
    arith: &str,
    format: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    let t0 = Instant::now();
    let oo = order_options(sort, arith)?;
    format_of(&path, format)?;
    let mut scene = Scene::default();
    let faces = Faces {
        faces: &faces,
        counts: counts.as_ref(),
    };
    add_mesh(&mut scene, "mesh", &vertices, &faces, &colors, opacity)?;
    scene.validate().map_err(value_error)?;
    let spec = CameraSpec {
        eye: vec3("eye", eye)?,
        target: vec3("target", target)?,
        up: vec3("up", Some(up))?.unwrap_or(glam::DVec3::Y),
        fov,
        size: crate::camera::size(size)?,
        ..CameraSpec::default()
    };
    render_scene(
        py,
        &scene,
        &spec,
        &path,
        format,
        &oo,
        &command_style(),
        ms(t0),
    )
}
