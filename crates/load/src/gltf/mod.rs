//! glTF 2.0, `.gltf` (JSON, buffers embedded as `data:` URIs or in files beside it) and
//! `.glb` (binary container).
//!
//! The `gltf` crate parses and validates the JSON; the binary data is read by
//! [`data`] with every offset checked. The nodes of the default scene (or of the first
//! scene; with no scene, every node without a parent) are walked depth first in file
//! order, each node's transform composed with its parents'. Every node with a mesh
//! becomes an object named after the node (or its mesh). Primitives in `TRIANGLES`,
//! `TRIANGLE_STRIP` and `TRIANGLE_FAN` mode become triangles; points and lines are
//! skipped with a warning. A transform that mirrors reverses the winding, as the
//! specification asks.
//!
//! Materials: `baseColorFactor` RGB becomes `Kd`; its alpha becomes the opacity when
//! `alphaMode` is `BLEND`. Under `MASK`, a factor alpha below `alphaCutoff` (default
//! 0.5) cuts the whole primitive away (its faces are not drawn, with a warning); a
//! base-colour texture's alpha is drawn: under `MASK` as a cut-out in which a texel
//! shows when the factor's alpha times its own is at least `alphaCutoff`
//! ([`limn_scene::TextureAlpha::Mask`]), under `BLEND` as opacity multiplying the
//! factor's ([`limn_scene::TextureAlpha::Blend`]). `OPAQUE` ignores alpha, as the
//! specification says. Materials with `KHR_materials_unlit` are unlit
//! (`illum 0`), others diffusely lit (`illum 1`). Primitives without a material get
//! [`Material::default_grey`]. A `baseColorTexture` becomes the material's texture,
//! for primitives that have its `TEXCOORD_n` (see [`textures`]); other textures
//! (normal, emissive, occlusion, metallic-roughness) are not drawn. `COLOR_0` becomes
//! vertex colours (multiplying `Kd`, as it multiplies the base colour).
//!
//! Sides: a node's primitives with `doubleSided: false` materials (the default, also of
//! primitives without a material) form an object of their own marked
//! [`limn_scene::Object::single_sided`] (their back faces are culled), those with
//! double-sided materials another. The first camera met while walking the nodes
//! becomes the scene's [`Scene::default_camera`] (see [`camera`]).

mod camera;
mod compression;
mod data;
mod draco;
mod textures;

use std::borrow::Cow;
use std::collections::HashMap;
use std::path::Path;
use std::sync::Arc;

use ::gltf::material::AlphaMode;
use ::gltf::mesh::Mode;
use ::gltf::texture::WrappingMode;
use ::gltf::Document;
use glam::DMat4;
use limn_scene::Wrap;

use super::{check_u32, transform, LoadError, LoadOptions, Location};
use limn_scene::{Face, Material, Scene, Texture, TextureAlpha};

/// Extensions a file may require and still be drawn correctly (they only add material
/// or texture detail that limn does not use).
const HARMLESS: &[&str] = &[
    "KHR_materials_unlit",
    "KHR_texture_transform",
    "KHR_materials_emissive_strength",
    "KHR_materials_ior",
    "KHR_materials_specular",
    "KHR_materials_transmission",
    "KHR_materials_volume",
    "KHR_materials_variants",
    "KHR_materials_clearcoat",
    "KHR_materials_sheen",
    "KHR_lights_punctual",
];

/// Triangles after instancing beyond which a file is refused (a small file can place
/// one big mesh in many nodes).
const MAX_TRIANGLES: usize = 200_000_000;

/// Parses a `.gltf` or `.glb` file (told apart by the `glTF` magic).
pub(crate) fn parse(bytes: &[u8], path: &Path, opts: &LoadOptions) -> Result<Scene, LoadError> {
    let glb = bytes.starts_with(b"glTF");
    let (json, blob) = if glb {
        data::split_glb(bytes, path)?
    } else {
        (bytes, None)
    };
    let mut root: ::gltf::json::Root =
        ::gltf::json::deserialize::from_slice(json).map_err(|e| json_error(&e, path, glb))?;
    // Required extensions are judged before validation, which would report those it
    // does not know among other findings (and cut the list short).
    for ext in &root.extensions_required {
        if let Some(e) = compression::refused(ext, path) {
            return Err(e);
        }
        if !HARMLESS.contains(&ext.as_str()) && !compression::READ.contains(&ext.as_str()) {
            return Err(LoadError::Unsupported {
                at: Location::file(path),
                what: format!("required extension {ext}"),
            });
        }
    }
    root.extensions_required.clear();
    let fallbacks: Vec<String> = root
        .extensions_used
        .iter()
        .filter_map(|ext| compression::fallback_warning(ext, path))
        .collect();
    let meshopt = if root
        .extensions_used
        .iter()
        .any(|e| e == "EXT_meshopt_compression")
    {
        Some(compression::Meshopt::read(json, path)?)
    } else {
        None
    };
    check_position_accessors(&root, path)?;
    let draco = if root.extensions_used.iter().any(|e| e == draco::NAME) {
        draco::read(json, path)?
    } else {
        Vec::new()
    };
    let invalid = |e: ::gltf::Error| LoadError::Invalid {
        at: Location::file(path),
        message: validation_message(&e),
    };
    let mut files = Vec::new();
    let fallback = meshopt.as_ref().map_or(&[][..], |m| &m.fallback[..]);
    let mut read_buffers = |doc: &Document| {
        let mut buffers = data::buffers(doc, blob, path, opts, fallback, &mut files)?;
        if let Some(m) = &meshopt {
            m.decode(&mut buffers, path)?;
        }
        Ok::<_, LoadError>(buffers)
    };
    let (doc, buffers) = if draco.is_empty() {
        let doc = Document::from_json(root).map_err(invalid)?;
        let buffers = read_buffers(&doc)?;
        (doc, buffers)
    } else {
        // Draco primitives' accessors have no data until decoded: the buffers are read
        // first (through a document of the buffers alone), the primitives decoded into
        // accessors, and the whole document made after.
        let only = ::gltf::json::Root {
            buffers: root.buffers.clone(),
            ..Default::default()
        };
        let mut buffers = read_buffers(&Document::from_json(only).map_err(invalid)?)?;
        let decoded = draco::decode(&draco, &mut root, &buffers, path)?;
        buffers.push(Cow::Owned(decoded));
        (Document::from_json(root).map_err(invalid)?, buffers)
    };
    textures::check_images(&doc, path)?;
    let mut b = Builder {
        path,
        opts,
        images: HashMap::new(),
        buffers: &buffers,
        scene: Scene {
            files,
            warnings: fallbacks,
            ..Scene::default()
        },
        materials: HashMap::new(),
        skipped_modes: 0,
        triangles: 0,
        vertex_alpha_warned: false,
        camera_tried: false,
        masked: Default::default(),
        alpha_textures: HashMap::new(),
        wraps: Default::default(),
    };
    b.walk(&doc)?;
    for (m, faces) in &b.masked {
        b.scene.warnings.push(format!(
            "{} (material {}): alphaMode MASK with a base colour alpha below alphaCutoff: \
             its {faces} faces are cut away, as the file asks, and not drawn",
            b.path.display(),
            m.map_or("default".to_string(), |i| i.to_string())
        ));
    }
    for (&material, &(sampler, wrap)) in &b.wraps {
        if let Err(e) = limn_scene::wrap_material_texture(&mut b.scene, material, wrap) {
            b.scene.warnings.push(format!(
                "{} (sampler {}): {e}; drawn as REPEAT",
                b.path.display(),
                sampler.map_or("default".to_string(), |i| i.to_string())
            ));
        }
    }
    if b.skipped_modes > 0 {
        b.scene.warnings.push(format!(
            "{}: {} point or line primitives skipped",
            path.display(),
            b.skipped_modes
        ));
    }
    if b.scene.faces.is_empty() {
        b.scene
            .warnings
            .push(format!("{}: no faces", path.display()));
    }
    Ok(b.scene)
}

/// `gltf-json` 1.4 reads the accessor of every primitive's `POSITION` attribute while
/// validating, without checking that it exists (and panics when it does not): refuse
/// such a reference before validation.
fn check_position_accessors(root: &::gltf::json::Root, path: &Path) -> Result<(), LoadError> {
    use ::gltf::json::mesh::Semantic;
    use ::gltf::json::validation::Checked;
    for (m, mesh) in root.meshes.iter().enumerate() {
        for (p, prim) in mesh.primitives.iter().enumerate() {
            let Some(i) = prim.attributes.get(&Checked::Valid(Semantic::Positions)) else {
                continue;
            };
            if i.value() >= root.accessors.len() {
                return Err(LoadError::Invalid {
                    at: Location::file(path),
                    message: format!(
                        "invalid glTF: meshes[{m}].primitives[{p}].attributes.POSITION: \
                         accessor {} does not exist ({} accessors)",
                        i.value(),
                        root.accessors.len()
                    ),
                });
            }
        }
    }
    Ok(())
}

fn json_error(e: &::gltf::json::Error, path: &Path, glb: bool) -> LoadError {
    let at = if glb {
        Location::record(path, format!("JSON chunk line {}", e.line()))
    } else {
        Location::line(path, e.line() as u64)
    };
    if e.is_eof() {
        LoadError::Truncated {
            at,
            detail: e.to_string(),
        }
    } else {
        LoadError::Syntax {
            at,
            message: format!("glTF JSON: {e}"),
        }
    }
}

fn validation_message(e: &::gltf::Error) -> String {
    match e {
        ::gltf::Error::Validation(list) => {
            let shown: Vec<String> = list
                .iter()
                .take(5)
                .map(|(p, err)| format!("{p}: {err}"))
                .collect();
            let more = list.len().saturating_sub(5);
            let mut m = format!("invalid glTF: {}", shown.join("; "));
            if more > 0 {
                m.push_str(&format!(" (and {more} more)"));
            }
            m
        }
        other => format!("invalid glTF: {other}"),
    }
}

struct Builder<'a, 'b> {
    path: &'a Path,
    opts: &'a LoadOptions,
    /// Decoded images by glTF image index (each is read once).
    images: HashMap<usize, Arc<Texture>>,
    buffers: &'a [std::borrow::Cow<'b, [u8]>],
    scene: Scene,
    /// glTF material index (`None`: the default) → scene material.
    materials: HashMap<Option<usize>, u32>,
    skipped_modes: usize,
    triangles: usize,
    /// Whether the warning of [`Builder::vertex_alpha`] was given.
    vertex_alpha_warned: bool,
    /// Whether a camera was looked at for the default view.
    camera_tried: bool,
    /// Per glTF material cut away by `MASK`: the faces not drawn.
    masked: std::collections::BTreeMap<Option<usize>, usize>,
    /// Textures with their alpha drawn as a material's `alphaMode` says, by glTF image
    /// and material (made once).
    alpha_textures: HashMap<(usize, Option<usize>), Arc<Texture>>,
    /// Scene materials whose texture is sampled other than by repetition: the sampler
    /// and its wrap modes (drawn once every primitive is read, see
    /// [`limn_scene::texture_wrap`]).
    wraps: std::collections::BTreeMap<u32, (Option<usize>, [Wrap; 2])>,
}

impl Builder<'_, '_> {
    fn walk(&mut self, doc: &Document) -> Result<(), LoadError> {
        let roots: Vec<::gltf::Node> = match doc.default_scene().or_else(|| doc.scenes().next()) {
            Some(s) => s.nodes().collect(),
            None => {
                let mut has_parent = vec![false; doc.nodes().len()];
                for n in doc.nodes() {
                    for c in n.children() {
                        has_parent[c.index()] = true;
                    }
                }
                doc.nodes().filter(|n| !has_parent[n.index()]).collect()
            }
        };
        let mut visited = vec![false; doc.nodes().len()];
        let mut stack: Vec<(::gltf::Node, DMat4)> = roots
            .into_iter()
            .rev()
            .map(|n| (n, DMat4::IDENTITY))
            .collect();
        while let Some((node, parent)) = stack.pop() {
            let at = || Location::record(self.path, format!("node {}", node.index()));
            if std::mem::replace(&mut visited[node.index()], true) {
                return Err(LoadError::Invalid {
                    at: at(),
                    message: "reached twice: nodes must form disjoint trees".into(),
                });
            }
            let local = node.transform().matrix().map(|c| c.map(|v| v as f64));
            let world = parent * DMat4::from_cols_array_2d(&local);
            if !transform::is_finite(&world) {
                return Err(LoadError::NonFinite {
                    at: at(),
                    what: "transform".into(),
                });
            }
            if let Some(cam) = node.camera() {
                if self.scene.default_camera.is_none() && !self.camera_tried {
                    self.camera_tried = true;
                    match camera::placed(&cam, &world) {
                        Ok(c) => self.scene.default_camera = Some(c),
                        Err(why) => {
                            let w = camera::unusable(self.path, &cam, &why);
                            self.scene.warnings.push(w);
                        }
                    }
                }
            }
            if let Some(mesh) = node.mesh() {
                let name = node
                    .name()
                    .or(mesh.name())
                    .map(str::to_string)
                    .unwrap_or_else(|| format!("node {}", node.index()));
                // One object for the double-sided primitives, one for the others.
                let mut objects: [Option<u32>; 2] = [None, None];
                for prim in mesh.primitives() {
                    let single = !prim.material().double_sided();
                    let object = match objects[usize::from(single)] {
                        Some(o) => o,
                        None => {
                            check_u32(self.scene.objects.len(), "objects", self.path)?;
                            let o = self.scene.add_object(&name);
                            self.scene.objects[o as usize].single_sided = single;
                            objects[usize::from(single)] = Some(o);
                            o
                        }
                    };
                    self.primitive(&mesh, &prim, object, &world)?;
                }
            }
            let children: Vec<_> = node.children().collect();
            stack.extend(children.into_iter().rev().map(|c| (c, world)));
        }
        Ok(())
    }

    fn primitive(
        &mut self,
        mesh: &::gltf::Mesh,
        prim: &::gltf::Primitive,
        object: u32,
        world: &DMat4,
    ) -> Result<(), LoadError> {
        let at = || {
            Location::record(
                self.path,
                format!("mesh {} primitive {}", mesh.index(), prim.index()),
            )
        };
        let mode = prim.mode();
        if !matches!(
            mode,
            Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
        ) {
            self.skipped_modes += 1;
            return Ok(());
        }
        let pos = prim
            .get(&::gltf::Semantic::Positions)
            .ok_or_else(|| LoadError::Invalid {
                at: at(),
                message: "no POSITION attribute".into(),
            })?;
        let positions = data::read_vec3(
            &pos,
            self.buffers,
            data::POSITION_TYPES,
            "position",
            self.path,
        )?;
        let normals = match prim.get(&::gltf::Semantic::Normals) {
            Some(acc) if acc.count() == positions.len() => Some(data::read_vec3(
                &acc,
                self.buffers,
                data::NORMAL_TYPES,
                "normal",
                self.path,
            )?),
            _ => None,
        };
        let colors = match prim.get(&::gltf::Semantic::Colors(0)) {
            Some(acc) if acc.count() == positions.len() => {
                Some(data::read_colors(&acc, self.buffers, self.path)?)
            }
            Some(acc) => {
                return Err(LoadError::Invalid {
                    at: Location::record(self.path, format!("accessor {}", acc.index())),
                    message: format!("{} colours for {} positions", acc.count(), positions.len()),
                })
            }
            None => None,
        };
        let indices = match prim.indices() {
            Some(acc) => data::read_indices(&acc, self.buffers, self.path)?,
            None => (0..positions.len() as u32).collect(),
        };
        if let Some(&bad) = indices.iter().find(|&&i| i as usize >= positions.len()) {
            return Err(LoadError::IndexOutOfRange {
                at: at(),
                what: "vertex",
                index: bad as i64,
                count: positions.len() as u64,
            });
        }
        let tris = triangles(mode, &indices).ok_or_else(|| LoadError::Invalid {
            at: at(),
            message: format!("{} indices do not make whole triangles", indices.len()),
        })?;
        self.triangles = self.triangles.saturating_add(tris.len());
        if self.triangles > MAX_TRIANGLES {
            return Err(LoadError::TooLarge {
                at: Location::file(self.path),
                what: "triangles after instancing",
                limit: MAX_TRIANGLES as u64,
            });
        }
        let gm = prim.material();
        if gm.alpha_mode() == AlphaMode::Mask
            && gm.pbr_metallic_roughness().base_color_factor()[3] < gm.alpha_cutoff().unwrap_or(0.5)
        {
            *self.masked.entry(gm.index()).or_default() += tris.len();
            return Ok(());
        }
        let material = self.material(prim.material());
        let texcoords = self.texcoords(prim, material, positions.len())?;
        let (v0, n0, f0) = (
            self.scene.vertices.len(),
            self.scene.normals.len(),
            self.scene.faces.len(),
        );
        let c0 = self.scene.colors.len();
        if let Some(cs) = &colors {
            check_u32(c0 + cs.len(), "vertex colours", self.path)?;
            self.vertex_alpha(prim, cs);
            self.scene
                .colors
                .extend(cs.iter().map(|&[r, g, b, _]| [r, g, b]));
        }
        let t0 = self.scene.texcoords.len();
        if let Some(ts) = &texcoords {
            check_u32(t0 + ts.len(), "texture coordinates", self.path)?;
            self.scene.texcoords.extend_from_slice(ts);
        }
        check_u32(v0 + positions.len(), "vertices", self.path)?;
        check_u32(f0 + tris.len(), "faces", self.path)?;
        self.scene.vertices.extend_from_slice(&positions);
        if let Some(ns) = &normals {
            self.scene.normals.extend_from_slice(ns);
        }
        for t in tris {
            let vertices = t.map(|i| v0 as u32 + i).to_vec();
            let normals = normals.as_ref().map(|_| t.map(|i| n0 as u32 + i).to_vec());
            let texcoords = texcoords
                .as_ref()
                .map(|_| t.map(|i| t0 as u32 + i).to_vec());
            let colors = colors.as_ref().map(|_| t.map(|i| c0 as u32 + i).to_vec());
            self.scene.faces.push(Face {
                vertices: vertices.into(),
                normals: normals.map(Into::into),
                texcoords: texcoords.map(Into::into),
                colors: colors.map(Into::into),
                material,
                object,
            });
        }
        transform::apply(&mut self.scene, world, v0, n0, f0);
        if !transform::vertices_finite(&self.scene, v0) {
            return Err(LoadError::NonFinite {
                at: at(),
                what: "vertex after the node transforms".into(),
            });
        }
        Ok(())
    }

    /// Warns (once per file) when a primitive's `COLOR_0` alpha would show: below 1
    /// under a `BLEND` or `MASK` material (vertex colours are drawn as RGB; the
    /// material's own alpha rule stays).
    fn vertex_alpha(&mut self, prim: &::gltf::Primitive, colors: &[[f64; 4]]) {
        let mode = prim.material().alpha_mode();
        if self.vertex_alpha_warned
            || mode == AlphaMode::Opaque
            || colors.iter().all(|c| c[3] >= 1.0)
        {
            return;
        }
        self.vertex_alpha_warned = true;
        self.scene.warnings.push(format!(
            "{} (mesh primitive {}): COLOR_0 alpha under alphaMode {mode:?} is not drawn \
             (vertex colours are drawn opaque over the material's opacity)",
            self.path.display(),
            prim.index()
        ));
    }

    /// The texture coordinates of a primitive whose material has a base-colour texture
    /// (and that texture, read into scene material `material` when first needed);
    /// `None` when nothing is textured.
    fn texcoords(
        &mut self,
        prim: &::gltf::Primitive,
        material: u32,
        count: usize,
    ) -> Result<Option<Vec<[f64; 2]>>, LoadError> {
        let Some(info) = prim
            .material()
            .pbr_metallic_roughness()
            .base_color_texture()
        else {
            return Ok(None);
        };
        let transform = info.texture_transform();
        let coord = transform
            .as_ref()
            .and_then(|t| t.tex_coord())
            .unwrap_or(info.tex_coord());
        let set = ::gltf::Semantic::TexCoords(coord);
        let Some(acc) = prim.get(&set) else {
            self.scene.warnings.push(format!(
                "{} (mesh primitive {}): the base-colour texture's TEXCOORD_{} is missing; \
                 drawn untextured",
                self.path.display(),
                prim.index(),
                coord
            ));
            return Ok(None);
        };
        if acc.count() != count {
            return Err(LoadError::Invalid {
                at: Location::record(self.path, format!("accessor {}", acc.index())),
                message: format!("{} texture coordinates for {count} positions", acc.count()),
            });
        }
        let mut st = textures::read_vec2(&acc, self.buffers, self.path)?;
        if let Some(t) = &transform {
            textures::transform(&mut st, t);
        }
        let texture = info.texture();
        let image = texture.source().index();
        let t = match self.images.get(&image) {
            Some(t) => t.clone(),
            None => {
                let t = textures::read_image(
                    &texture,
                    self.buffers,
                    self.path,
                    self.opts,
                    &mut self.scene.files,
                )?;
                self.images.insert(image, t.clone());
                t
            }
        };
        let t = self.drawn_alpha(prim, image, t);
        let sampler = texture.sampler();
        let wrap = [sampler.wrap_s(), sampler.wrap_t()].map(|m| match m {
            WrappingMode::Repeat => Wrap::Repeat,
            WrappingMode::MirroredRepeat => Wrap::MirroredRepeat,
            WrappingMode::ClampToEdge => Wrap::ClampToEdge,
        });
        if wrap != [Wrap::Repeat; 2] {
            self.wraps.insert(material, (sampler.index(), wrap));
        }
        self.scene.materials[material as usize].texture = Some(t);
        Ok(Some(st))
    }

    /// Texture `t` (glTF image `image`) with its alpha drawn as the primitive's
    /// material's `alphaMode` says (see the module docs).
    fn drawn_alpha(
        &mut self,
        prim: &::gltf::Primitive,
        image: usize,
        t: Arc<Texture>,
    ) -> Arc<Texture> {
        let m = prim.material();
        let mode = m.alpha_mode();
        if mode == AlphaMode::Opaque || t.rgba().chunks_exact(4).all(|p| p[3] == 255) {
            return t;
        }
        self.alpha_textures
            .entry((image, m.index()))
            .or_insert_with(|| {
                let t = Texture::clone(&t);
                Arc::new(if mode == AlphaMode::Mask {
                    let factor = f64::from(m.pbr_metallic_roughness().base_color_factor()[3]);
                    let cutoff = f64::from(m.alpha_cutoff().unwrap_or(0.5));
                    t.masked(|a| factor * f64::from(a) / 255.0 >= cutoff)
                } else {
                    t.with_alpha(TextureAlpha::Blend)
                })
            })
            .clone()
    }

    fn material(&mut self, m: ::gltf::Material) -> u32 {
        if let Some(&i) = self.materials.get(&m.index()) {
            return i;
        }
        let mat = match m.index() {
            None => Material::default_grey(),
            Some(i) => {
                let [r, g, b, a] = m.pbr_metallic_roughness().base_color_factor();
                let kd = [r, g, b].map(|c| (c as f64).clamp(0.0, 1.0));
                let name = m
                    .name()
                    .map_or_else(|| format!("material {i}"), str::to_string);
                let mut mat = if m.unlit() {
                    Material::unlit(&name, kd)
                } else {
                    Material::diffuse(&name, kd)
                };
                if m.alpha_mode() == AlphaMode::Blend {
                    mat.opacity = (a as f64).clamp(0.0, 1.0);
                }
                mat
            }
        };
        let i = self.scene.add_material(mat);
        self.materials.insert(m.index(), i);
        i
    }
}

/// The triangles of a primitive, by index (strips and fans unrolled, strip triangles
/// with a repeated vertex, used to join strips, dropped). `None` when a triangle list's
/// length is not a multiple of three.
fn triangles(mode: Mode, idx: &[u32]) -> Option<Vec<[u32; 3]>> {
    Some(match mode {
        Mode::TriangleStrip => (0..idx.len().saturating_sub(2))
            .map(|i| {
                if i % 2 == 0 {
                    [idx[i], idx[i + 1], idx[i + 2]]
                } else {
                    [idx[i], idx[i + 2], idx[i + 1]]
                }
            })
            .filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
            .collect(),
        Mode::TriangleFan => (1..idx.len().saturating_sub(1))
            .map(|i| [idx[i], idx[i + 1], idx[0]])
            .collect(),
        _ => {
            if !idx.len().is_multiple_of(3) {
                return None;
            }
            idx.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect()
        }
    })
}
