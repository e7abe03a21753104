//! The in-memory scene: vertices, faces, materials, objects, lights.

use std::sync::Arc;

use glam::DVec3;
use thiserror::Error;

use crate::{Camera, Fog, PointMark, Polyline, Shading, TextLabel, Texture};

/// Errors raised while building a scene in code.
#[derive(Debug, Error, Clone, PartialEq)]
#[non_exhaustive]
pub enum SceneError {
    /// A face has fewer than three vertices.
    #[error("face has {0} vertices; at least 3 are needed")]
    TooFewVertices(usize),
    /// A face refers to a vertex that does not exist.
    #[error("face refers to vertex {index}, but the scene has {count} vertices")]
    VertexOutOfRange {
        /// The offending index.
        index: u32,
        /// Number of vertices in the scene.
        count: usize,
    },
    /// A vertex normal index is out of range.
    #[error("face refers to normal {index}, but the scene has {count} normals")]
    NormalOutOfRange {
        /// The offending index.
        index: u32,
        /// Number of normals in the scene.
        count: usize,
    },
    /// A face refers to a material or object that does not exist.
    #[error("face refers to {what} {index}, which does not exist")]
    BadReference {
        /// "material" or "object".
        what: &'static str,
        /// The offending index.
        index: u32,
    },
    /// A coordinate is NaN or infinite.
    #[error("non-finite coordinate in {0}")]
    NonFinite(&'static str),
    /// A line, point or label breaks a rule (too few points, a bad size or colour).
    #[error("{what}: {problem}")]
    BadMark {
        /// "line", "point" or "label".
        what: &'static str,
        /// What is wrong.
        problem: String,
    },
    /// A texture coordinate index is out of range, or a face gives texture coordinates
    /// for some corners only.
    #[error("face refers to texture coordinate {index}, but the scene has {count}")]
    TexcoordOutOfRange {
        /// The offending index (or the number of coordinates given, when it does not
        /// match the corners).
        index: u32,
        /// Number of texture coordinates in the scene.
        count: usize,
    },
    /// A vertex colour index is out of range, or a face gives colours for some corners
    /// only.
    #[error("face refers to vertex colour {index}, but the scene has {count}")]
    ColorOutOfRange {
        /// The offending index (or the number of colours given, when it does not match
        /// the corners).
        index: u32,
        /// Number of vertex colours in the scene.
        count: usize,
    },
    /// A vertex colour has a channel outside [0, 1].
    #[error("vertex colour {index} has a channel outside [0, 1]")]
    ColorOutOfGamut {
        /// The colour's index in [`Scene::colors`].
        index: usize,
    },
    /// Too many faces or vertices for 32-bit ids.
    #[error("scene too large: more than 2^32 - 1 {0}")]
    TooLarge(&'static str),
    /// A light asks for shadows it cannot cast (an ambient light or a headlight), or is
    /// beyond the first [`crate::LightSet::CAPACITY`] lights.
    #[error("light {index}: {problem}")]
    BadShadows {
        /// The light's index in [`Scene::lights`].
        index: usize,
        /// What is wrong.
        problem: &'static str,
    },
}

/// A surface material, following the Wavefront MTL model.
#[derive(Debug, Clone, PartialEq)]
pub struct Material {
    /// Name as given in the input (or generated).
    pub name: String,
    /// Diffuse colour `Kd`, each channel in [0, 1].
    pub kd: [f64; 3],
    /// Ambient colour `Ka`.
    pub ka: [f64; 3],
    /// Specular colour `Ks`.
    pub ks: [f64; 3],
    /// Specular exponent `Ns`.
    pub ns: f64,
    /// Opacity `d` (1 = opaque). `Tr` is read as `1 - d`.
    pub opacity: f64,
    /// MTL illumination model: 0 = exactly `kd`, no lighting; 1 = diffuse; 2 = diffuse +
    /// specular.
    pub illum: u8,
    /// The diffuse texture (`map_Kd`, glTF `baseColorTexture`), shared by every face
    /// that uses it. Its colour multiplies the face's colour (see [`crate::texture`]);
    /// it is drawn only on faces with texture coordinates.
    pub texture: Option<Arc<Texture>>,
}

impl Material {
    /// A material drawn with exactly `kd`: `illum 0`, opaque.
    pub fn unlit(name: &str, kd: [f64; 3]) -> Self {
        Material {
            name: name.to_string(),
            kd,
            ka: [0.0; 3],
            ks: [0.0; 3],
            ns: 0.0,
            opacity: 1.0,
            illum: 0,
            texture: None,
        }
    }

    /// A diffusely lit material (`illum 1`) with a small ambient term.
    pub fn diffuse(name: &str, kd: [f64; 3]) -> Self {
        Material {
            name: name.to_string(),
            kd,
            ka: [0.1, 0.1, 0.1],
            ks: [0.0; 3],
            ns: 0.0,
            opacity: 1.0,
            illum: 1,
            texture: None,
        }
    }

    /// A lit material with a specular highlight (`illum 2`).
    pub fn glossy(name: &str, kd: [f64; 3], ks: [f64; 3], ns: f64) -> Self {
        Material {
            name: name.to_string(),
            kd,
            ka: [0.1, 0.1, 0.1],
            ks,
            ns,
            opacity: 1.0,
            illum: 2,
            texture: None,
        }
    }

    /// The default material of faces that name none: a mid grey, diffusely lit.
    pub fn default_grey() -> Self {
        Material::diffuse("default", [0.7, 0.7, 0.7])
    }

    /// Whether this material is fully opaque: opacity 1 and no texture whose alpha is
    /// drawn (a cut-out or blended texture lets what is behind show through).
    pub fn is_opaque(&self) -> bool {
        self.opacity >= 1.0 && self.texture.as_ref().is_none_or(|t| t.is_opaque())
    }
}

/// A named group of faces (an OBJ `o`/`g`, a glTF node, a mesh of a scene file).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Object {
    /// The object's name (free text; writers escape it).
    pub name: String,
    /// Its faces are seen from the front only (glTF `doubleSided: false`): their back
    /// faces are culled under the default culling, closed or not.
    pub single_sided: bool,
}

/// One input polygon. Vertices are indices into [`Scene::vertices`], counter-clockwise
/// when seen from the front (right-handed), which defines the face's outward normal.
///
/// The index lists are boxed slices (made from a `Vec` with `.into()`): a face is 72
/// bytes, where vectors made it 104 (a million-face scene held 33 MB more while it was
/// ordered).
#[derive(Debug, Clone, PartialEq)]
pub struct Face {
    /// Vertex indices, at least three.
    pub vertices: Box<[u32]>,
    /// Per-corner normal indices into [`Scene::normals`], if the input gave them.
    pub normals: Option<Box<[u32]>>,
    /// Per-corner texture coordinate indices into [`Scene::texcoords`], if the input
    /// gave them.
    pub texcoords: Option<Box<[u32]>>,
    /// Per-corner vertex colour indices into [`Scene::colors`], if the input gave them.
    /// A corner's colour multiplies the material's `Kd` and `Ka` there (as glTF's
    /// `COLOR_0` multiplies `baseColorFactor`); colours are interpolated between the
    /// corners, so the face is not one colour even when lit flat.
    pub colors: Option<Box<[u32]>>,
    /// Index into [`Scene::materials`].
    pub material: u32,
    /// Index into [`Scene::objects`].
    pub object: u32,
}

/// The kind of a light source.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LightKind {
    /// Light arriving from a direction (pointing *from* the scene *towards* the light).
    Directional(DVec3),
    /// A point light at a position.
    Point(DVec3),
    /// A light at the eye (a headlight).
    Headlight,
    /// Ambient light, the same everywhere.
    Ambient,
}

/// A light source with an RGB intensity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Light {
    /// Where the light comes from.
    pub kind: LightKind,
    /// Intensity per channel (1 = full).
    pub color: [f64; 3],
    /// Whether the light casts shadows (directional and point lights only; see
    /// [`Scene::shadow_lights`]). Nothing about shadows is computed for a light that
    /// does not ask.
    pub shadows: bool,
}

impl Light {
    /// A light of `kind` and `color` that casts no shadows.
    pub fn new(kind: LightKind, color: [f64; 3]) -> Light {
        Light {
            kind,
            color,
            shadows: false,
        }
    }
}

/// A whole scene in world coordinates.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Scene {
    /// Vertex positions.
    pub vertices: Vec<DVec3>,
    /// Vertex normals (referenced by [`Face::normals`]).
    pub normals: Vec<DVec3>,
    /// Texture coordinates `(s, t)`, `t` down the image (referenced by
    /// [`Face::texcoords`]; see [`crate::texture`]).
    pub texcoords: Vec<[f64; 2]>,
    /// Vertex colours, RGB in [0, 1] as `Kd` (referenced by [`Face::colors`]).
    pub colors: Vec<[f64; 3]>,
    /// Faces in input order; a face's index here is its face id.
    pub faces: Vec<Face>,
    /// Materials.
    pub materials: Vec<Material>,
    /// Objects.
    pub objects: Vec<Object>,
    /// Light sources. Empty means: a headlight for lit materials.
    pub lights: Vec<Light>,
    /// Camera given by the input, if any.
    pub camera: Option<Camera>,
    /// The view a model file suggests (a glTF file's first camera): used when neither
    /// the options nor a scene file give a camera or an eye.
    pub default_camera: Option<Camera>,
    /// Polylines drawn over the surfaces where visible.
    pub lines: Vec<Polyline>,
    /// Points drawn as markers when visible.
    pub points: Vec<PointMark>,
    /// Text labels drawn when their anchor is visible.
    pub labels: Vec<TextLabel>,
    /// The interpolation asked for (`None`: the default rule of [`Shading::of_face`]).
    pub shading: Option<Shading>,
    /// Depth cueing, when asked for.
    pub fog: Option<Fog>,
    /// Warnings collected while loading (missing MTL, dropped faces, ...).
    pub warnings: Vec<String>,
    /// The files the scene was read from: the input and every file it referenced
    /// (material libraries, buffers, a scene file's meshes). A program writing a picture
    /// must never write over one of them.
    pub files: Vec<std::path::PathBuf>,
}

impl Scene {
    /// Adds a vertex and returns its index.
    pub fn add_vertex(&mut self, p: DVec3) -> u32 {
        self.vertices.push(p);
        (self.vertices.len() - 1) as u32
    }

    /// Adds a material and returns its index.
    pub fn add_material(&mut self, m: Material) -> u32 {
        self.materials.push(m);
        (self.materials.len() - 1) as u32
    }

    /// Adds an object and returns its index.
    pub fn add_object(&mut self, name: &str) -> u32 {
        self.objects.push(Object {
            name: name.to_string(),
            single_sided: false,
        });
        (self.objects.len() - 1) as u32
    }

    /// Adds a face (checked) and returns its face id.
    pub fn add_face(
        &mut self,
        vertices: &[u32],
        material: u32,
        object: u32,
    ) -> Result<u32, SceneError> {
        let face = Face {
            vertices: vertices.into(),
            normals: None,
            texcoords: None,
            colors: None,
            material,
            object,
        };
        self.check_face(&face)?;
        if self.faces.len() >= u32::MAX as usize {
            return Err(SceneError::TooLarge("faces"));
        }
        self.faces.push(face);
        Ok((self.faces.len() - 1) as u32)
    }

    /// Adds a polygon given by its corner positions (a convenience for tests and
    /// generated scenes) and returns its face id.
    pub fn add_polygon(
        &mut self,
        corners: &[DVec3],
        material: u32,
        object: u32,
    ) -> Result<u32, SceneError> {
        let idx: Vec<u32> = corners.iter().map(|&p| self.add_vertex(p)).collect();
        self.add_face(&idx, material, object)
    }

    fn check_face(&self, face: &Face) -> Result<(), SceneError> {
        if face.vertices.len() < 3 {
            return Err(SceneError::TooFewVertices(face.vertices.len()));
        }
        for &v in &face.vertices {
            if v as usize >= self.vertices.len() {
                return Err(SceneError::VertexOutOfRange {
                    index: v,
                    count: self.vertices.len(),
                });
            }
        }
        if let Some(ns) = &face.normals {
            for &n in ns {
                if n as usize >= self.normals.len() {
                    return Err(SceneError::NormalOutOfRange {
                        index: n,
                        count: self.normals.len(),
                    });
                }
            }
        }
        if let Some(ts) = &face.texcoords {
            let count = self.texcoords.len();
            if ts.len() != face.vertices.len() {
                return Err(SceneError::TexcoordOutOfRange {
                    index: ts.len() as u32,
                    count,
                });
            }
            if let Some(&index) = ts.iter().find(|&&t| t as usize >= count) {
                return Err(SceneError::TexcoordOutOfRange { index, count });
            }
        }
        if let Some(cs) = &face.colors {
            let count = self.colors.len();
            if cs.len() != face.vertices.len() {
                return Err(SceneError::ColorOutOfRange {
                    index: cs.len() as u32,
                    count,
                });
            }
            if let Some(&index) = cs.iter().find(|&&c| c as usize >= count) {
                return Err(SceneError::ColorOutOfRange { index, count });
            }
        }
        if face.material as usize >= self.materials.len() {
            return Err(SceneError::BadReference {
                what: "material",
                index: face.material,
            });
        }
        if face.object as usize >= self.objects.len() {
            return Err(SceneError::BadReference {
                what: "object",
                index: face.object,
            });
        }
        Ok(())
    }

    /// Checks every invariant the rest of limn relies on: indices in range, finite
    /// coordinates, at least three vertices per face.
    pub fn validate(&self) -> Result<(), SceneError> {
        if self.vertices.iter().any(|v| !v.is_finite()) {
            return Err(SceneError::NonFinite("vertex"));
        }
        if self.normals.iter().any(|v| !v.is_finite()) {
            return Err(SceneError::NonFinite("normal"));
        }
        if self.texcoords.iter().flatten().any(|v| !v.is_finite()) {
            return Err(SceneError::NonFinite("texture coordinate"));
        }
        if let Some(index) = self
            .colors
            .iter()
            .position(|c| !c.iter().all(|v| (0.0..=1.0).contains(v)))
        {
            return Err(SceneError::ColorOutOfGamut { index });
        }
        for f in &self.faces {
            self.check_face(f)?;
        }
        let objects = self.objects.len();
        for l in &self.lines {
            l.validate(objects)?;
        }
        for p in &self.points {
            p.validate(objects)?;
        }
        for l in &self.labels {
            l.validate(objects)?;
        }
        for (index, l) in self.lights.iter().enumerate() {
            if !l.shadows {
                continue;
            }
            if matches!(l.kind, LightKind::Ambient | LightKind::Headlight) {
                return Err(SceneError::BadShadows {
                    index,
                    problem: "only directional and point lights cast shadows",
                });
            }
            if index >= crate::LightSet::CAPACITY {
                return Err(SceneError::BadShadows {
                    index,
                    problem: "only the first 64 lights can cast shadows",
                });
            }
        }
        Ok(())
    }

    /// The lights that cast shadows (`shadows = true`), as a set of light indices;
    /// empty when none asks (then nothing about shadows is computed).
    pub fn shadow_lights(&self) -> crate::LightSet {
        let mut set = crate::LightSet::EMPTY;
        for (i, l) in self.lights.iter().enumerate() {
            if l.shadows && i < crate::LightSet::CAPACITY {
                set.insert(i);
            }
        }
        set
    }

    /// The positions of a face's corners.
    pub fn face_points(&self, face: u32) -> Vec<DVec3> {
        self.faces[face as usize]
            .vertices
            .iter()
            .map(|&v| self.vertices[v as usize])
            .collect()
    }

    /// Axis-aligned bounds (min, max) of the vertices used by faces, the points of lines
    /// and the anchors of markers and labels, or `None` when there are none.
    pub fn bounds(&self) -> Option<(DVec3, DVec3)> {
        let mut it = self
            .faces
            .iter()
            .flat_map(|f| f.vertices.iter())
            .map(|&v| self.vertices[v as usize])
            .chain(self.lines.iter().flat_map(|l| l.points.iter().copied()))
            .chain(self.points.iter().map(|p| p.at))
            .chain(self.labels.iter().map(|l| l.at));
        let first = it.next()?;
        Some(it.fold((first, first), |(lo, hi), p| (lo.min(p), hi.max(p))))
    }

    /// Whether every material used by a face is opaque.
    pub fn all_opaque(&self) -> bool {
        self.faces
            .iter()
            .all(|f| self.materials[f.material as usize].is_opaque())
    }

    /// Whether the faces of each object form closed surfaces: every undirected edge
    /// (by vertex position) is used exactly twice, once in each direction.
    pub fn is_closed(&self) -> bool {
        use std::collections::HashMap;
        if self.faces.is_empty() {
            return false;
        }
        // Key edges by position bits so that duplicated vertices still match.
        let key = |v: u32| {
            let p = self.vertices[v as usize];
            [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()]
        };
        let mut count: HashMap<([u64; 3], [u64; 3]), i64> = HashMap::new();
        for f in &self.faces {
            let n = f.vertices.len();
            for i in 0..n {
                let a = key(f.vertices[i]);
                let b = key(f.vertices[(i + 1) % n]);
                if a == b {
                    continue;
                }
                *count.entry((a, b)).or_insert(0) += 1;
            }
        }
        count
            .iter()
            .all(|(&(a, b), &c)| c == 1 && count.get(&(b, a)) == Some(&1))
    }

    /// Appends all faces of `other` (with its vertices, normals, materials and objects),
    /// keeping their order after this scene's faces, and its lines, points and labels.
    pub fn append(&mut self, other: &Scene) {
        let vo = self.vertices.len() as u32;
        let no = self.normals.len() as u32;
        let to = self.texcoords.len() as u32;
        let co = self.colors.len() as u32;
        let mo = self.materials.len() as u32;
        let oo = self.objects.len() as u32;
        self.vertices.extend_from_slice(&other.vertices);
        self.normals.extend_from_slice(&other.normals);
        self.texcoords.extend_from_slice(&other.texcoords);
        self.colors.extend_from_slice(&other.colors);
        self.materials.extend(other.materials.iter().cloned());
        self.objects.extend(other.objects.iter().cloned());
        for f in &other.faces {
            self.faces.push(Face {
                vertices: f.vertices.iter().map(|v| v + vo).collect(),
                normals: f
                    .normals
                    .as_ref()
                    .map(|ns| ns.iter().map(|n| n + no).collect()),
                texcoords: f
                    .texcoords
                    .as_ref()
                    .map(|ts| ts.iter().map(|t| t + to).collect()),
                colors: f
                    .colors
                    .as_ref()
                    .map(|cs| cs.iter().map(|c| c + co).collect()),
                material: f.material + mo,
                object: f.object + oo,
            });
        }
        let shift = |o: u32| o + oo;
        self.lines.extend(other.lines.iter().map(|l| Polyline {
            object: shift(l.object),
            ..l.clone()
        }));
        self.points.extend(other.points.iter().map(|p| PointMark {
            object: shift(p.object),
            ..p.clone()
        }));
        self.labels.extend(other.labels.iter().map(|l| TextLabel {
            object: shift(l.object),
            ..l.clone()
        }));
        self.lights.extend_from_slice(&other.lights);
        self.warnings.extend(other.warnings.iter().cloned());
        self.files.extend(other.files.iter().cloned());
    }
}
