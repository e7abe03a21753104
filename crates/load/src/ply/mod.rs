//! PLY (Stanford polygon files): ASCII, binary little endian, binary big endian.
//!
//! Written here rather than with `ply-rs`: that crate has not been maintained for years,
//! its errors carry no line, and it allocates from the header's counts before it knows
//! the body holds that much. Here the header's counts are checked against the body's
//! size (bytes for binary, lines for ASCII) before anything is allocated.
//!
//! Read: the `vertex` element's `x`, `y`, `z`, optional `nx`, `ny`, `nz` (vertex normals)
//! and optional colour `red`, `green`, `blue`, `alpha` (or `diffuse_red` …); the `face`
//! element's `vertex_indices` (or `vertex_index`) list and optional colour; the
//! `tristrips` element's `vertex_indices` lists (triangle strips, -1 starting a new
//! strip, every second triangle turned to keep the strip's winding, as OpenGL draws
//! them; the triangles of a repeated corner that join strips have no area and are not
//! faces). A file with vertices and no faces is a point cloud: each vertex is drawn as
//! a dot (4 px) in its colour (black without one), with a warning. Other
//! elements and properties are read past and ignored. ASCII bodies hold one element
//! per line. The `vertex` element must come before the `face` and `tristrips` elements.
//!
//! Colours: integer channels are scaled by their type's largest value (255 for
//! `uchar`), float channels are taken as they are; both are clamped to [0, 1]. A face
//! with its own colour gets it; otherwise, when vertices have colours, a face whose
//! corners share one colour gets it, and a face whose corners differ gets their colours
//! as vertex colours ([`Face::colors`], interpolated between the corners) over a white
//! material. Each distinct colour becomes one *unlit* material (`illum 0`, drawn with
//! exactly that colour, as a coloured PLY is meant to look), named `#rrggbb`
//! (`#rrggbbaa` when translucent: alpha is the opacity; a face whose corners' alphas
//! differ is drawn with their mean, with a warning). Faces of a PLY without colours get
//! [`Material::default_grey`].

mod header;
mod source;

use std::path::Path;

use glam::DVec3;

use self::header::{Element, Kind};
use self::source::Source;
use super::text::BitsMap;
use super::{check_u32, stem, LoadError, Location};
use limn_scene::{Face, Material, PointMark, Scene};

const RED: &[&str] = &["red", "diffuse_red", "r"];
const GREEN: &[&str] = &["green", "diffuse_green", "g"];
const BLUE: &[&str] = &["blue", "diffuse_blue", "b"];
const ALPHA: &[&str] = &["alpha", "diffuse_alpha", "a"];

/// Positions of the colour properties of an element, with their scale.
#[derive(Clone, Copy)]
struct ColourProps {
    idx: [usize; 3],
    alpha: Option<usize>,
}

impl ColourProps {
    fn find(el: &Element) -> Option<ColourProps> {
        let r = el.find(RED)?;
        let g = el.find(GREEN)?;
        let b = el.find(BLUE)?;
        Some(ColourProps {
            idx: [r, g, b],
            alpha: el.find(ALPHA),
        })
    }

    fn read(&self, el: &Element, vals: &[f64]) -> [f64; 4] {
        let chan = |i: usize| match el.properties[i].kind {
            Kind::Scalar(s) => {
                let v = vals[i] / s.full_scale();
                if v.is_nan() {
                    1.0
                } else {
                    v.clamp(0.0, 1.0)
                }
            }
            Kind::List { .. } => 1.0,
        };
        [
            chan(self.idx[0]),
            chan(self.idx[1]),
            chan(self.idx[2]),
            self.alpha.map_or(1.0, chan),
        ]
    }
}

/// Parses a PLY file.
pub(crate) fn parse(bytes: &[u8], path: &Path) -> Result<Scene, LoadError> {
    let header = header::parse(bytes, path)?;
    let mut src = Source::new(
        header.encoding,
        &bytes[header.body_start..],
        header.body_line,
    );
    check_counts(&header.elements, &src, path)?;

    let mut scene = Scene::default();
    let object = scene.add_object(&stem(path));
    let mut vertex_colours: Vec<[f64; 4]> = Vec::new();
    // Faces whose corners have different alphas, drawn with their mean.
    let mut averaged = 0usize;
    let mut has_normals = false;
    let mut seen_vertex = false;
    let mut materials: BitsMap<[u64; 4], u32> = BitsMap::default();
    let mut vals: Vec<f64> = Vec::new();
    let mut list: Vec<f64> = Vec::new();

    for el in &header.elements {
        let at_header = Location::line(path, el.line);
        match el.name.as_str() {
            "vertex" => {
                if seen_vertex {
                    return Err(LoadError::Invalid {
                        at: at_header,
                        message: "a second vertex element".into(),
                    });
                }
                seen_vertex = true;
                let xyz = ["x", "y", "z"].map(|n| el.find(&[n]));
                let [Some(x), Some(y), Some(z)] = xyz else {
                    return Err(LoadError::Invalid {
                        at: at_header,
                        message: "the vertex element has no x, y and z properties".into(),
                    });
                };
                let normal = match ["nx", "ny", "nz"].map(|n| el.find(&[n])) {
                    [Some(a), Some(b), Some(c)] => Some([a, b, c]),
                    _ => None,
                };
                has_normals = normal.is_some();
                let colour = ColourProps::find(el);
                check_u32(el.count as usize, "vertices", path)?;
                // Counts were checked against the body's size.
                scene.vertices.reserve(el.count as usize);
                for i in 0..el.count {
                    read_instance(&mut src, el, i, None, &mut vals, &mut list, path)?;
                    let p = DVec3::new(vals[x], vals[y], vals[z]);
                    if !p.is_finite() {
                        return Err(LoadError::NonFinite {
                            at: src.at(path),
                            what: "vertex coordinate".into(),
                        });
                    }
                    scene.vertices.push(p);
                    if let Some([a, b, c]) = normal {
                        let nv = DVec3::new(vals[a], vals[b], vals[c]);
                        if !nv.is_finite() {
                            return Err(LoadError::NonFinite {
                                at: src.at(path),
                                what: "normal".into(),
                            });
                        }
                        scene.normals.push(nv);
                    }
                    if let Some(c) = colour {
                        let rgba = c.read(el, &vals);
                        vertex_colours.push(rgba);
                        scene.colors.push([rgba[0], rgba[1], rgba[2]]);
                    }
                }
            }
            "face" | "tristrips" => {
                let strips = el.name == "tristrips";
                if !seen_vertex {
                    return Err(LoadError::Unsupported {
                        at: at_header,
                        what: format!("a {} element before the vertex element", el.name),
                    });
                }
                let Some(li) = el.find(&["vertex_indices", "vertex_index"]) else {
                    return Err(LoadError::Invalid {
                        at: at_header,
                        message: format!("the {} element has no vertex_indices list", el.name),
                    });
                };
                let Kind::List { item, .. } = el.properties[li].kind else {
                    return Err(LoadError::Invalid {
                        at: at_header,
                        message: "vertex_indices is not a list".into(),
                    });
                };
                if !item.is_integer() {
                    return Err(LoadError::Invalid {
                        at: at_header,
                        message: "vertex_indices must have an integer type".into(),
                    });
                }
                let colour = ColourProps::find(el);
                if !strips {
                    check_u32(el.count as usize, "faces", path)?;
                    scene.faces.reserve(el.count as usize);
                }
                let nv = scene.vertices.len() as u64;
                let mut faces = Faces {
                    scene: &mut scene,
                    materials: &mut materials,
                    vertex_colours: &vertex_colours,
                    averaged: &mut averaged,
                    has_normals,
                    object,
                    path,
                };
                let mut corners = Vec::new();
                for i in 0..el.count {
                    read_instance(&mut src, el, i, Some(li), &mut vals, &mut list, path)?;
                    let rgba = colour.map(|c| c.read(el, &vals));
                    corners.clear();
                    for &v in &list {
                        if strips && v == -1.0 {
                            corners.push(RESTART);
                        } else if v >= 0.0 && (v as u64) < nv {
                            corners.push(v as u32);
                        } else {
                            return Err(LoadError::IndexOutOfRange {
                                at: src.at(path),
                                what: "vertex",
                                index: v as i64,
                                count: nv,
                            });
                        }
                    }
                    if strips {
                        faces.strips(&corners, rgba)?;
                        continue;
                    }
                    if corners.len() < 3 {
                        return Err(LoadError::TooFewVertices {
                            at: src.at(path),
                            count: corners.len(),
                        });
                    }
                    faces.push(corners.clone(), rgba)?;
                }
            }
            _ => {
                for i in 0..el.count {
                    read_instance(&mut src, el, i, None, &mut vals, &mut list, path)?;
                }
            }
        }
    }
    if averaged > 0 {
        scene.warnings.push(format!(
            "{}: {averaged} faces have corners of different alphas; each is drawn with the \
             mean of its corners' alphas",
            path.display()
        ));
    }
    if let Some((lines, first)) = src.extra_values() {
        scene.warnings.push(format!(
            "{}:{first}: values beyond those the header declares ignored ({lines} lines)",
            path.display()
        ));
    }
    let trailing = src.trailing();
    if trailing > 0 {
        scene.warnings.push(format!(
            "{}: {trailing} bytes after the last element ignored",
            path.display()
        ));
    }
    if scene.faces.is_empty() {
        points_for_vertices(&mut scene, &vertex_colours, object, path);
    }
    Ok(scene)
}

/// In a strip, the index -1 ends one strip and starts the next.
const RESTART: u32 = u32::MAX;

/// Adds faces to a PLY's scene with their material (the face's colour, else its
/// corners' shared colour, else white under their vertex colours, else the default grey).
struct Faces<'a> {
    scene: &'a mut Scene,
    materials: &'a mut BitsMap<[u64; 4], u32>,
    vertex_colours: &'a [[f64; 4]],
    /// Faces whose corners have different colours.
    averaged: &'a mut usize,
    has_normals: bool,
    object: u32,
    path: &'a Path,
}

impl Faces<'_> {
    /// Adds the face with corners `vertices` and its own colour `rgba`, if any.
    fn push(&mut self, vertices: Vec<u32>, rgba: Option<[f64; 4]>) -> Result<(), LoadError> {
        let mut colors = None;
        let rgba = rgba.or_else(|| {
            if self.vertex_colours.is_empty() {
                return None;
            }
            let first = self.vertex_colours[vertices[0] as usize];
            let corner = |v: &u32| self.vertex_colours[*v as usize];
            if vertices.iter().all(|v| corner(v) == first) {
                return Some(first);
            }
            *self.averaged += vertices.iter().any(|v| corner(v)[3] != first[3]) as usize;
            if vertices.iter().any(|v| corner(v)[..3] != first[..3]) {
                colors = Some(vertices.clone());
            }
            let alpha = vertices.iter().map(|v| corner(v)[3]).sum::<f64>() / vertices.len() as f64;
            Some(match colors {
                Some(_) => [1.0, 1.0, 1.0, alpha],
                None => [first[0], first[1], first[2], alpha],
            })
        });
        check_u32(self.scene.faces.len(), "faces", self.path)?;
        let material = material_for(self.scene, self.materials, rgba);
        let vertices: Box<[u32]> = vertices.into();
        let normals = self.has_normals.then(|| vertices.clone());
        self.scene.faces.push(Face {
            vertices,
            normals,
            texcoords: None,
            colors: colors.map(Into::into),
            material,
            object: self.object,
        });
        Ok(())
    }

    /// Adds the triangles of the strips in `corners` (separated by [`RESTART`]): corners
    /// k, k + 1, k + 2 of each strip, every second one turned (k + 1, k, k + 2) so that
    /// all keep the strip's winding, as OpenGL draws `GL_TRIANGLE_STRIP`. Triangles with
    /// a repeated corner are the strips' way of joining (no area) and are not faces.
    fn strips(&mut self, corners: &[u32], rgba: Option<[f64; 4]>) -> Result<(), LoadError> {
        for strip in corners.split(|&c| c == RESTART) {
            for k in 0..strip.len().saturating_sub(2) {
                let [a, b, c] = [strip[k], strip[k + 1], strip[k + 2]];
                if a == b || b == c || a == c {
                    continue;
                }
                let t = if k % 2 == 0 {
                    vec![a, b, c]
                } else {
                    vec![b, a, c]
                };
                self.push(t, rgba)?;
            }
        }
        Ok(())
    }
}

/// A PLY with vertices and no faces is a point cloud: each vertex becomes a dot
/// (4 px, its colour or black), with a warning saying so.
fn points_for_vertices(scene: &mut Scene, colours: &[[f64; 4]], object: u32, path: &Path) {
    if scene.vertices.is_empty() {
        scene.warnings.push(format!("{}: no faces", path.display()));
        return;
    }
    scene.points.reserve(scene.vertices.len());
    for (i, &at) in scene.vertices.iter().enumerate() {
        scene.points.push(PointMark {
            color: colours.get(i).copied().unwrap_or([0.0, 0.0, 0.0, 1.0]),
            object,
            ..PointMark::new(at)
        });
    }
    scene.warnings.push(format!(
        "{}: no faces; its {} vertices are drawn as points",
        path.display(),
        scene.vertices.len()
    ));
}

/// Checks, before anything is allocated, that the body can hold what the header
/// claims: for binary bodies each element's smallest size times its count, for ASCII
/// bodies one line per element.
fn check_counts(elements: &[Element], src: &Source, path: &Path) -> Result<(), LoadError> {
    let mut room = src.room();
    for el in elements {
        if el.count > 0 && el.properties.is_empty() {
            return Err(LoadError::Invalid {
                at: Location::line(path, el.line),
                message: format!("element {} has a count but no properties", el.name),
            });
        }
        let unit = if src.is_binary() {
            el.min_binary_size()
        } else {
            1
        };
        let need = el.count.checked_mul(unit);
        match need {
            Some(need) if need <= room => room -= need,
            _ => {
                return Err(LoadError::CountTooLarge {
                    at: Location::line(path, el.line),
                    what: format!("{} elements", el.name),
                    claimed: el.count,
                    room: room / unit.max(1),
                })
            }
        }
    }
    Ok(())
}

/// Reads one element instance: scalars into `vals` (by property position), the items
/// of list property `want` into `list`; other lists are read and dropped.
fn read_instance(
    src: &mut Source,
    el: &Element,
    index: u64,
    want: Option<usize>,
    vals: &mut Vec<f64>,
    list: &mut Vec<f64>,
    path: &Path,
) -> Result<(), LoadError> {
    src.begin(&el.name, index, path)?;
    vals.clear();
    list.clear();
    for (pi, p) in el.properties.iter().enumerate() {
        match p.kind {
            Kind::Scalar(s) => vals.push(src.scalar(s, path)?),
            Kind::List { count, item } => {
                let c = src.scalar(count, path)?;
                if !(c >= 0.0 && c.fract() == 0.0) {
                    return Err(LoadError::Invalid {
                        at: src.at(path),
                        message: format!("list length {c} of {}", p.name),
                    });
                }
                vals.push(c);
                let n = c as u64;
                if src.is_binary() && n.saturating_mul(item.size() as u64) > src.room() {
                    return Err(LoadError::Truncated {
                        at: src.at(path),
                        detail: format!("the list {} claims {n} items", p.name),
                    });
                }
                for _ in 0..n {
                    let v = src.scalar(item, path)?;
                    if Some(pi) == want {
                        list.push(v);
                    }
                }
            }
        }
    }
    src.end();
    Ok(())
}

/// The material of a face colour (deduplicated), or the default grey.
fn material_for(
    scene: &mut Scene,
    materials: &mut BitsMap<[u64; 4], u32>,
    rgba: Option<[f64; 4]>,
) -> u32 {
    let key = rgba.map_or([u64::MAX; 4], |c| c.map(f64::to_bits));
    if let Some(&m) = materials.get(&key) {
        return m;
    }
    let mat = match rgba {
        None => Material::default_grey(),
        Some([r, g, b, a]) => {
            let byte = |c: f64| (c * 255.0).round() as u8;
            let mut name = format!("#{:02x}{:02x}{:02x}", byte(r), byte(g), byte(b));
            if a < 1.0 {
                name.push_str(&format!("{:02x}", byte(a)));
            }
            let mut m = Material::unlit(&name, [r, g, b]);
            m.opacity = a;
            m
        }
    };
    let m = scene.add_material(mat);
    materials.insert(key, m);
    m
}
