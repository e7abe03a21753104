//! PLY (Stanford polygon files): ASCII, binary little endian, binary big endian.
//!
//! Written here rather than with `ply-rs`: that crate has not been maintained for years,
//! its errors carry no line, and it allocates from the header's counts before it knows
//! the body holds that much. Here the header's counts are checked against the body's
//! size (bytes for binary, lines for ASCII) before anything is allocated.
//!
//! Read: the `vertex` element's `x`, `y`, `z`, optional `nx`, `ny`, `nz` (vertex normals)
//! and optional colour `red`, `green`, `blue`, `alpha` (or `diffuse_red` …); the `face`
//! element's `vertex_indices` (or `vertex_index`) list and optional colour. Other
//! elements and properties are read past and ignored. ASCII bodies hold one element
//! per line. The `vertex` element must come before the `face` element.
//!
//! Colours: integer channels are scaled by their type's largest value (255 for
//! `uchar`), float channels are taken as they are; both are clamped to [0, 1]. A face
//! with its own colour gets it; otherwise, when vertices have colours, the face gets the
//! mean of its corners' colours. Each distinct colour becomes one *unlit* material
//! (`illum 0`, drawn with exactly that colour, as a coloured PLY is meant to look),
//! named `#rrggbb` (`#rrggbbaa` when translucent: alpha is the opacity). Faces of a PLY
//! without colours get [`Material::default_grey`].

mod header;
mod source;

use std::path::Path;

use glam::DVec3;

use self::header::{Element, Kind};
use self::source::Source;
use super::text::BitsMap;
use super::{check_u32, stem, LoadError, Location};
use limn_scene::{Face, Material, Scene};

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
    // Faces whose corners have different colours, drawn with their mean.
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
                        vertex_colours.push(c.read(el, &vals));
                    }
                }
            }
            "face" => {
                if !seen_vertex {
                    return Err(LoadError::Unsupported {
                        at: at_header,
                        what: "a face element before the vertex element".into(),
                    });
                }
                let Some(li) = el.find(&["vertex_indices", "vertex_index"]) else {
                    return Err(LoadError::Invalid {
                        at: at_header,
                        message: "the face element has no vertex_indices list".into(),
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
                check_u32(el.count as usize, "faces", path)?;
                scene.faces.reserve(el.count as usize);
                let nv = scene.vertices.len() as u64;
                for i in 0..el.count {
                    read_instance(&mut src, el, i, Some(li), &mut vals, &mut list, path)?;
                    if list.len() < 3 {
                        return Err(LoadError::TooFewVertices {
                            at: src.at(path),
                            count: list.len(),
                        });
                    }
                    let mut vertices = Vec::with_capacity(list.len());
                    for &v in &list {
                        if !(v >= 0.0 && (v as u64) < nv) {
                            return Err(LoadError::IndexOutOfRange {
                                at: src.at(path),
                                what: "vertex",
                                index: v as i64,
                                count: nv,
                            });
                        }
                        vertices.push(v as u32);
                    }
                    let rgba = match colour {
                        Some(c) => Some(c.read(el, &vals)),
                        None if !vertex_colours.is_empty() => {
                            let first = vertex_colours[vertices[0] as usize];
                            averaged += vertices
                                .iter()
                                .any(|&v| vertex_colours[v as usize] != first)
                                as usize;
                            let mut sum = [0.0; 4];
                            for &v in &vertices {
                                for (s, c) in sum.iter_mut().zip(vertex_colours[v as usize]) {
                                    *s += c;
                                }
                            }
                            Some(sum.map(|s| s / vertices.len() as f64))
                        }
                        None => None,
                    };
                    let material = material_for(&mut scene, &mut materials, rgba);
                    let normals = has_normals.then(|| vertices.clone());
                    scene.faces.push(Face {
                        vertices,
                        normals,
                        texcoords: None,
                        material,
                        object,
                    });
                }
            }
            other => {
                if other == "tristrips" && el.count > 0 {
                    scene.warnings.push(format!(
                        "{}:{}: triangle strips are not read",
                        path.display(),
                        el.line
                    ));
                }
                for i in 0..el.count {
                    read_instance(&mut src, el, i, None, &mut vals, &mut list, path)?;
                }
            }
        }
    }
    if averaged > 0 {
        scene.warnings.push(format!(
            "{}: {averaged} faces have corners of different colours; each is drawn in the \
             mean of its corners' colours",
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
        scene.warnings.push(format!("{}: no faces", path.display()));
    }
    Ok(scene)
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
    src.end(path)
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
