//! Wavefront OBJ.
//!
//! Written here rather than with `tobj`: `tobj`'s errors carry neither the file nor the
//! line, it regroups faces by model (the input order of faces is the face id here), and
//! it resolves indices only after the whole file is read. This parser keeps n-gons
//! as they are, reports every problem with file and line, and resolves each index when
//! its face is read: a face may only use vertices defined above it (positive indices
//! count from the first vertex, negative ones back from the last one so far).
//!
//! Statements read: `v` (3 to 7 numbers: x y z, then an optional w, or a colour r g b
//! in [0, 1] as MeshLab and others write it: a vertex colour, see below; a seventh number
//! is ignored),
//! `vn`, `f`/`fo` (`v`, `v/vt`, `v//vn`, `v/vt/vn`), `l` (a polyline of at least two
//! vertices, `v` or `v/vt`), `p` (one point marker per vertex), `o` and `g` (each starts
//! an object; the same name again continues it), `usemtl` (one without a name, as Rhino
//! writes, selects the default grey, with a warning), `mtllib`. Lines and points
//! take the current material's `Kd` and `d` as their colour (black without a `usemtl`),
//! width 1 px and 4 px dots. A file of vertices alone (a point cloud) draws each vertex
//! as a black dot, with a warning. Texture coordinates (`vt u [v [w]]`, stored as
//! `(u, 1 − v)`: limn's `t` runs down the image) are used by faces whose every corner
//! names one and whose material has a `map_Kd`; the image is read then, once per file
//! (see [`crate::image`]). Vertex colours are used by faces whose every corner has one
//! ([`limn_scene::Face::colors`]): they multiply the material's `Kd`, and faces without
//! a `usemtl` get a white diffuse material named `vertex colours` rather than the grey
//! (channels outside [0, 1] are clamped, and a colour with a NaN channel is no colour,
//! each with a warning naming the first line). A face naming texture coordinates or
//! normals while the file has defined none of them (an exporter's quirk) is drawn
//! without them, with one warning naming the first such line; an index beyond those
//! defined is still an error. A
//! point cloud's dots take their vertices' colours. Smoothing groups and the free-form geometry statements are
//! accepted and ignored; any other statement is an error (so
//! binary garbage is reported, not silently dropped).
//!
//! A large MTL library is parsed on another thread while the lines below its `mtllib`
//! are read (see [`crate::library_loader`]); the scene, its warnings and the first error
//! are those of reading the library at its line.

use rustc_hash::FxHashMap as HashMap;
use std::borrow::Cow;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use glam::DVec3;

use super::library_loader::{LibraryLoader, PARALLEL_FROM};
use super::text::{lossy, number, parse_i64, strip_comment, tokens, Lines};
use super::{check_u32, refs, stem, LoadError, LoadOptions, Location};
use limn_scene::{Face, Material, PointMark, Polyline, Scene, Texture};

/// Statements accepted and ignored.
/// No scene material yet (in `Obj::scene_material`).
const NO_MATERIAL: u32 = u32::MAX;

const IGNORED: &[&[u8]] = &[
    b"vp",
    b"s",
    b"mg",
    b"maplib",
    b"usemap",
    b"lod",
    b"bevel",
    b"c_interp",
    b"d_interp",
    b"shadow_obj",
    b"trace_obj",
    b"ctech",
    b"stech",
    b"cstype",
    b"deg",
    b"bmat",
    b"step",
    b"curv",
    b"curv2",
    b"surf",
    b"parm",
    b"trim",
    b"hole",
    b"scrv",
    b"sp",
    b"end",
    b"con",
    b"call",
    b"csh",
];

/// A `map_Kd`'s `-s` (scale) and `-o` (offset) of `u` and `v`.
type UvTransform = ([f64; 2], [f64; 2]);

struct Obj<'a> {
    path: &'a Path,
    opts: &'a LoadOptions,
    scene: Scene,
    /// The `mtllib` libraries, possibly still being parsed on another thread.
    libraries: LibraryLoader,
    /// Object name → index, so that `g a … g b … g a` continues object `a`.
    objects: HashMap<String, u32>,
    object_name: String,
    object: Option<u32>,
    /// Library material index → index in the scene (added when first used; `NO_MATERIAL`
    /// before).
    scene_material: Vec<u32>,
    /// The library index of the last material found in the library (the next one is
    /// tried first).
    library_index: usize,
    /// Names no library defines → index in the scene (the default grey, once each).
    undefined: HashMap<String, u32>,
    /// The name the last `usemtl` gave, as its bytes (read as text only when it is
    /// not the library's next name).
    material_name: Option<Vec<u8>>,
    /// Line of the last `usemtl`.
    material_line: u64,
    /// The first `usemtl` without a name (line) and how many there are.
    unnamed: Option<(u64, u64)>,
    material: Option<u32>,
    /// Texture images read so far, by resolved path (each is read once).
    images: HashMap<PathBuf, Arc<Texture>>,
    /// Scene materials whose `map_Kd` has been looked at, with its coordinate transform
    /// when it moves coordinates (`-s`, `-o`).
    textured: HashMap<u32, Option<UvTransform>>,
    /// Transformed copies of texture coordinates: (index, material) → index.
    moved: HashMap<(u32, u32), u32>,
    /// Scene materials whose `map_Kd` is `-clamp on`, and where it was said.
    clamp_maps: Vec<(u32, Location)>,
    /// Per vertex, its colour's index in the scene ([`NO_COLOR`] for none); empty
    /// until the first vertex with a colour.
    vertex_color: Vec<u32>,
    /// The white material of faces with vertex colours and no `usemtl`.
    white: Option<u32>,
    /// The first line with a colour channel outside [0, 1], and how many there are.
    clamped: Option<(u64, u64)>,
    /// The first line with a colour channel that is not a number, and how many there are.
    no_colour: Option<(u64, u64)>,
    /// The first face line naming texture coordinates while the file had defined none,
    /// and how many faces did (they are drawn without them).
    undefined_texcoords: Option<(u64, u64)>,
    /// The same for normals.
    undefined_normals: Option<(u64, u64)>,
}

/// A vertex without a colour.
const NO_COLOR: u32 = u32::MAX;

/// Parses an OBJ file (and the MTL libraries it names, large ones on another thread
/// while the OBJ is read).
pub(crate) fn parse(bytes: &[u8], path: &Path, opts: &LoadOptions) -> Result<Scene, LoadError> {
    parse_with(bytes, path, opts, PARALLEL_FROM)
}

/// [`parse`], with libraries of `parallel_from` bytes or more parsed on another thread.
fn parse_with(
    bytes: &[u8],
    path: &Path,
    opts: &LoadOptions,
    parallel_from: usize,
) -> Result<Scene, LoadError> {
    let mut obj = Obj {
        path,
        opts,
        scene: Scene::default(),
        libraries: LibraryLoader::new(parallel_from),
        objects: HashMap::default(),
        object_name: stem(path),
        object: None,
        scene_material: Vec::new(),
        library_index: usize::MAX,
        undefined: HashMap::default(),
        material_name: None,
        material_line: 0,
        unnamed: None,
        material: None,
        images: HashMap::default(),
        textured: HashMap::default(),
        moved: HashMap::default(),
        clamp_maps: Vec::new(),
        vertex_color: Vec::new(),
        white: None,
        clamped: None,
        no_colour: None,
        undefined_texcoords: None,
        undefined_normals: None,
    };
    // Room for the faces and vertices the file's lines announce (a count of line starts,
    // a hint only): growing the vectors by doubling wrote every face again into fresh
    // pages, the largest part of the loader's time on a million faces.
    let lines_starting = |with: &[u8]| memchr::memmem::find_iter(bytes, with).count();
    obj.scene.faces.reserve_exact(lines_starting(b"\nf "));
    obj.scene.vertices.reserve_exact(lines_starting(b"\nv "));
    let read = obj.statements(bytes);
    // A library's error comes first: it was named above any line the OBJ failed at.
    obj.libraries.wait(&mut obj.scene.warnings)?;
    read?;
    for (material, at) in std::mem::take(&mut obj.clamp_maps) {
        let clamp = [limn_scene::Wrap::ClampToEdge; 2];
        if let Err(e) = limn_scene::wrap_material_texture(&mut obj.scene, material, clamp) {
            obj.scene
                .warnings
                .push(format!("{at}: map_Kd -clamp on: {e}; the texture repeats"));
        }
    }
    if let Some((line, count)) = obj.unnamed {
        let more = match count {
            1 => String::new(),
            2 => " (and 1 more)".to_string(),
            c => format!(" (and {} more)", c - 1),
        };
        obj.scene.warnings.push(format!(
            "{}:{line}: usemtl without a name{more}; its faces get the default grey",
            path.display()
        ));
    }
    if let Some((line, count)) = obj.clamped {
        obj.scene.warnings.push(format!(
            "{}:{line}: vertex colour channels outside [0, 1] clamped ({count} vertices)",
            path.display()
        ));
    }
    for (what, seen) in [
        ("texture coordinates", obj.undefined_texcoords),
        ("normals", obj.undefined_normals),
    ] {
        if let Some((line, count)) = seen {
            let faces = if count == 1 { "face" } else { "faces" };
            obj.scene.warnings.push(format!(
                "{}:{line}: faces name {what} the file had not defined ({count} {faces}): \
                 drawn without them",
                path.display()
            ));
        }
    }
    if let Some((line, count)) = obj.no_colour {
        obj.scene.warnings.push(format!(
            "{}:{line}: vertex colours with a channel that is not a number are not used \
             ({count} vertices; faces at them have no vertex colours)",
            path.display()
        ));
    }
    obj.scene.materials.shrink_to_fit();
    let s = &mut obj.scene;
    if s.faces.is_empty() && s.lines.is_empty() && s.points.is_empty() {
        if s.vertices.is_empty() {
            s.warnings.push(format!("{}: no faces", path.display()));
        } else {
            // A point cloud: every vertex a dot.
            let object = s.add_object(&obj.object_name);
            s.points.reserve(s.vertices.len());
            for i in 0..s.vertices.len() {
                let at = s.vertices[i];
                let mut point = PointMark {
                    object,
                    ..PointMark::new(at)
                };
                if let Some(&c) = obj.vertex_color.get(i).filter(|&&c| c != NO_COLOR) {
                    let [r, g, b] = s.colors[c as usize];
                    point.color = [r, g, b, 1.0];
                }
                s.points.push(point);
            }
            s.warnings.push(format!(
                "{}: no faces, lines or points; its {} vertices are drawn as points",
                path.display(),
                s.vertices.len()
            ));
        }
    }
    Ok(obj.scene)
}

impl Obj<'_> {
    fn statements(&mut self, bytes: &[u8]) -> Result<(), LoadError> {
        let mut lines = Lines::new(bytes, self.path, true);
        while let Some(next) = lines.next_line() {
            let (n, line) = next?;
            self.statement(n, strip_comment(&line))?;
        }
        Ok(())
    }

    fn statement(&mut self, n: u64, line: &[u8]) -> Result<(), LoadError> {
        let mut toks = tokens(line);
        let Some(key) = toks.next() else {
            return Ok(());
        };
        match key {
            b"v" => {
                let p = self.triple(n, &mut toks, "vertex")?;
                let mut extra = [None; 4];
                let mut count = 0;
                for t in toks {
                    if count == 4 {
                        return Err(LoadError::syntax(
                            self.path,
                            n,
                            "v has more than 7 numbers; at most 7 are allowed",
                        ));
                    }
                    extra[count] = Some(t);
                    count += 1;
                }
                check_u32(self.scene.vertices.len(), "vertices", self.path)?;
                self.scene.vertices.push(p);
                if count >= 3 {
                    let rgb = [0, 1, 2]
                        .map(|k| number(self.path, n, extra[k], "vertex colour"))
                        .into_iter()
                        .collect::<Result<Vec<f64>, _>>()?;
                    self.vertex_colour(n, [rgb[0], rgb[1], rgb[2]])?;
                } else if !self.vertex_color.is_empty() {
                    self.vertex_color.push(NO_COLOR);
                }
            }
            b"vn" => {
                let p = self.triple(n, &mut toks, "normal")?;
                check_u32(self.scene.normals.len(), "normals", self.path)?;
                self.scene.normals.push(p);
            }
            b"vt" => {
                let u = number(self.path, n, toks.next(), "texture u")?;
                let v = match toks.next() {
                    Some(t) => number(self.path, n, Some(t), "texture v")?,
                    None => 0.0,
                };
                if !u.is_finite() || !v.is_finite() {
                    return Err(LoadError::NonFinite {
                        at: Location::line(self.path, n),
                        what: "texture coordinate".into(),
                    });
                }
                check_u32(self.scene.texcoords.len(), "texture coordinates", self.path)?;
                self.scene.texcoords.push([u, 1.0 - v]);
            }
            b"f" | b"fo" => self.face(n, toks)?,
            b"o" | b"g" => {
                let name = lossy(toks.remainder());
                self.object_name = if name.is_empty() {
                    "default".to_string()
                } else {
                    name
                };
                self.object = None;
            }
            b"usemtl" => {
                let name = toks.remainder();
                if name.is_empty() {
                    // Rhino writes these: the default material, as without a usemtl.
                    self.unnamed.get_or_insert((n, 0)).1 += 1;
                }
                // The same name again keeps the material found (no lookup, no copy).
                if self.material_name.as_deref() != Some(name) {
                    // The name's buffer is reused: no allocation per `usemtl`.
                    let current = self.material_name.get_or_insert_with(Vec::new);
                    current.clear();
                    current.extend_from_slice(name);
                    self.material = None;
                }
                self.material_line = n;
            }
            b"mtllib" => self.mtllib(n, toks.remainder())?,
            b"l" => self.line(n, toks)?,
            b"p" => self.points(n, toks)?,
            k if IGNORED.contains(&k) => {}
            k => {
                return Err(LoadError::syntax(
                    self.path,
                    n,
                    format!("unknown statement {:?}", lossy(k)),
                ))
            }
        }
        Ok(())
    }

    fn triple<'t>(
        &self,
        n: u64,
        toks: &mut impl Iterator<Item = &'t [u8]>,
        what: &str,
    ) -> Result<DVec3, LoadError> {
        let names = if what == "vertex" {
            ["vertex x", "vertex y", "vertex z"]
        } else {
            ["normal x", "normal y", "normal z"]
        };
        let x = number(self.path, n, toks.next(), names[0])?;
        let y = number(self.path, n, toks.next(), names[1])?;
        let z = number(self.path, n, toks.next(), names[2])?;
        let p = DVec3::new(x, y, z);
        if !p.is_finite() {
            return Err(LoadError::NonFinite {
                at: Location::line(self.path, n),
                what: format!("{what} coordinate"),
            });
        }
        Ok(p)
    }

    fn face<'t>(&mut self, n: u64, toks: impl Iterator<Item = &'t [u8]>) -> Result<(), LoadError> {
        let mut vertices = Vec::with_capacity(4);
        // Allocated at the first normal index: most faces have none.
        let mut normals = Vec::new();
        let mut all_normals = true;
        // Allocated at the first texture coordinate index, like the normals.
        let mut texcoords = Vec::new();
        let mut all_texcoords = true;
        // Corners naming texture coordinates or normals while the file has defined none
        // (some exporters write `f 1/1/1` without any `vt`): the face is drawn without
        // them, with a warning.
        let (mut undefined_vt, mut undefined_vn) = (false, false);
        for t in toks {
            let mut parts = t.split(|&b| b == b'/');
            let v = parts.next().unwrap_or_default();
            let vt = parts.next();
            let vn = parts.next();
            if parts.next().is_some() {
                return Err(LoadError::syntax(
                    self.path,
                    n,
                    format!("bad face corner {:?}", lossy(t)),
                ));
            }
            let count = self.scene.vertices.len() as u64;
            vertices.push(self.index(n, v, count, "vertex")?);
            match vt.filter(|s| !s.is_empty()) {
                Some(_) if self.scene.texcoords.is_empty() => {
                    undefined_vt = true;
                    all_texcoords = false;
                }
                Some(vt) => {
                    let count = self.scene.texcoords.len() as u64;
                    texcoords.push(self.index(n, vt, count, "texture coordinate")?);
                }
                None => all_texcoords = false,
            }
            match vn.filter(|s| !s.is_empty()) {
                Some(_) if self.scene.normals.is_empty() => {
                    undefined_vn = true;
                    all_normals = false;
                }
                Some(vn) => {
                    let count = self.scene.normals.len() as u64;
                    normals.push(self.index(n, vn, count, "normal")?);
                }
                None => all_normals = false,
            }
        }
        if undefined_vt {
            self.undefined_texcoords.get_or_insert((n, 0)).1 += 1;
        }
        if undefined_vn {
            self.undefined_normals.get_or_insert((n, 0)).1 += 1;
        }
        if vertices.len() < 3 {
            return Err(LoadError::TooFewVertices {
                at: Location::line(self.path, n),
                count: vertices.len(),
            });
        }
        let object = self.current_object()?;
        let material = self.current_material()?;
        let colors = self.face_colors(&vertices);
        let material = match (colors.is_some(), &self.material_name) {
            (true, None) => self.white_material()?,
            _ => material,
        };
        let texcoords = if all_texcoords {
            self.face_texcoords(material, texcoords)?
        } else {
            None
        };
        check_u32(self.scene.faces.len(), "faces", self.path)?;
        self.scene.faces.push(Face {
            vertices: vertices.into(),
            normals: all_normals.then(|| normals.into()),
            texcoords: texcoords.map(Into::into),
            colors: colors.map(Into::into),
            material,
            object,
        });
        Ok(())
    }

    /// Records the colour of the vertex just added (clamped to [0, 1]; a colour with a
    /// NaN channel is no colour, as exporters write it for "none").
    fn vertex_colour(&mut self, n: u64, rgb: [f64; 3]) -> Result<(), LoadError> {
        if rgb.iter().any(|c| c.is_nan()) {
            self.no_colour.get_or_insert((n, 0)).1 += 1;
            if !self.vertex_color.is_empty() {
                self.vertex_color.push(NO_COLOR);
            }
            return Ok(());
        }
        if rgb.iter().any(|c| !(0.0..=1.0).contains(c)) {
            self.clamped.get_or_insert((n, 0)).1 += 1;
        }
        let v = self.scene.vertices.len() - 1;
        if self.vertex_color.len() < v {
            self.vertex_color.resize(v, NO_COLOR);
        }
        check_u32(self.scene.colors.len(), "vertex colours", self.path)?;
        self.vertex_color.push(self.scene.colors.len() as u32);
        self.scene.colors.push(rgb.map(|c| c.clamp(0.0, 1.0)));
        Ok(())
    }

    /// The colour indices of a face's corners, when every corner has a colour.
    fn face_colors(&self, vertices: &[u32]) -> Option<Vec<u32>> {
        if self.vertex_color.is_empty() {
            return None;
        }
        vertices
            .iter()
            .map(|&v| {
                self.vertex_color
                    .get(v as usize)
                    .copied()
                    .filter(|&c| c != NO_COLOR)
            })
            .collect()
    }

    /// The white diffuse material of faces with vertex colours and no `usemtl`.
    fn white_material(&mut self) -> Result<u32, LoadError> {
        if let Some(m) = self.white {
            return Ok(m);
        }
        check_u32(self.scene.materials.len(), "materials", self.path)?;
        let m = self
            .scene
            .add_material(Material::diffuse("vertex colours", [1.0; 3]));
        self.white = Some(m);
        Ok(m)
    }

    /// The texture coordinates a face keeps: `None` unless its material has a
    /// `map_Kd` (read now, when first needed), moved by the map's `-s` and `-o`.
    fn face_texcoords(
        &mut self,
        material: u32,
        texcoords: Vec<u32>,
    ) -> Result<Option<Vec<u32>>, LoadError> {
        let transform = match self.textured.get(&material) {
            Some(&t) => t,
            None => {
                let t = self.read_map(material)?;
                self.textured.insert(material, t);
                t
            }
        };
        if self.scene.materials[material as usize].texture.is_none() {
            return Ok(None);
        }
        let Some((scale, offset)) = transform else {
            return Ok(Some(texcoords));
        };
        let mut out = Vec::with_capacity(texcoords.len());
        for t in texcoords {
            let i = match self.moved.get(&(t, material)) {
                Some(&i) => i,
                None => {
                    let [s, tt] = self.scene.texcoords[t as usize];
                    let (u, v) = (s, 1.0 - tt);
                    let (u, v) = (scale[0] * u + offset[0], scale[1] * v + offset[1]);
                    check_u32(self.scene.texcoords.len(), "texture coordinates", self.path)?;
                    self.scene.texcoords.push([u, 1.0 - v]);
                    let i = (self.scene.texcoords.len() - 1) as u32;
                    self.moved.insert((t, material), i);
                    i
                }
            };
            out.push(i);
        }
        Ok(Some(out))
    }

    /// Reads the `map_Kd` image of scene material `material` (named by the current
    /// `usemtl`) into it, if it has one; returns the map's coordinate transform when it
    /// is not the identity.
    fn read_map(&mut self, material: u32) -> Result<Option<UvTransform>, LoadError> {
        let name = self.material_text().into_owned();
        let library = self.libraries.wait(&mut self.scene.warnings)?;
        let Some(map) = library.maps.get(&name).cloned() else {
            return Ok(None);
        };
        let file = refs::resolve(&map.file, &map.at, self.opts)?;
        let texture = match self.images.get(&file) {
            Some(t) => t.clone(),
            None => {
                let bytes = std::fs::read(&file).map_err(|e| LoadError::Image {
                    at: map.at.clone(),
                    image: map.file.clone(),
                    message: format!("cannot read {}: {e}", file.display()),
                })?;
                let t = crate::image::decode(&bytes, &map.file, &map.at)?;
                self.scene.files.push(file.clone());
                self.images.insert(file, t.clone());
                t
            }
        };
        self.scene.materials[material as usize].texture = Some(texture);
        if map.clamp {
            self.clamp_maps.push((material, map.at.clone()));
        }
        // Clamped maps move their coordinates once all faces are read: they get copies
        // of their own.
        let moves = map.scale != [1.0, 1.0] || map.offset != [0.0, 0.0] || map.clamp;
        Ok(moves.then_some((map.scale, map.offset)))
    }

    /// The vertex indices of an `l` or `p` element (`v` or `v/vt` each).
    fn element_vertices<'t>(
        &self,
        n: u64,
        toks: impl Iterator<Item = &'t [u8]>,
    ) -> Result<Vec<glam::DVec3>, LoadError> {
        let mut points = Vec::new();
        for t in toks {
            let mut parts = t.split(|&b| b == b'/');
            let v = parts.next().unwrap_or_default();
            let vt = parts.next();
            if parts.next().is_some() {
                return Err(LoadError::syntax(
                    self.path,
                    n,
                    format!("bad line or point vertex {:?}", lossy(t)),
                ));
            }
            let count = self.scene.vertices.len() as u64;
            let i = self.index(n, v, count, "vertex")?;
            if let Some(vt) = vt.filter(|s| !s.is_empty()) {
                let count = self.scene.texcoords.len() as u64;
                self.index(n, vt, count, "texture coordinate")?;
            }
            points.push(self.scene.vertices[i as usize]);
        }
        Ok(points)
    }

    /// The colour of lines and points: the current material's `Kd` and opacity, black
    /// when no `usemtl` is in effect.
    fn mark_color(&mut self) -> Result<[f64; 4], LoadError> {
        if self.material_name.is_none() {
            return Ok([0.0, 0.0, 0.0, 1.0]);
        }
        let i = self.current_material()? as usize;
        let m = &self.scene.materials[i];
        Ok([m.kd[0], m.kd[1], m.kd[2], m.opacity.clamp(0.0, 1.0)])
    }

    fn line<'t>(&mut self, n: u64, toks: impl Iterator<Item = &'t [u8]>) -> Result<(), LoadError> {
        let points = self.element_vertices(n, toks)?;
        if points.len() < 2 {
            return Err(LoadError::syntax(
                self.path,
                n,
                format!(
                    "a line has {} vertices; at least 2 are needed",
                    points.len()
                ),
            ));
        }
        let color = self.mark_color()?;
        let object = self.current_object()?;
        check_u32(self.scene.lines.len(), "lines", self.path)?;
        self.scene.lines.push(Polyline {
            color,
            object,
            ..Polyline::new(points)
        });
        Ok(())
    }

    fn points<'t>(
        &mut self,
        n: u64,
        toks: impl Iterator<Item = &'t [u8]>,
    ) -> Result<(), LoadError> {
        let points = self.element_vertices(n, toks)?;
        if points.is_empty() {
            return Err(LoadError::syntax(
                self.path,
                n,
                "a point element without vertices",
            ));
        }
        let color = self.mark_color()?;
        let object = self.current_object()?;
        for at in points {
            check_u32(self.scene.points.len(), "points", self.path)?;
            self.scene.points.push(PointMark {
                color,
                object,
                ..PointMark::new(at)
            });
        }
        Ok(())
    }

    /// Resolves a 1-based or negative index against `count` items defined so far.
    fn index(&self, n: u64, tok: &[u8], count: u64, what: &'static str) -> Result<u32, LoadError> {
        let at = || Location::line(self.path, n);
        let i = parse_i64(tok).ok_or_else(|| {
            let digits = tok.strip_prefix(b"-").unwrap_or(tok);
            let problem = if !digits.is_empty() && digits.iter().all(u8::is_ascii_digit) {
                "is too large"
            } else {
                "is not an integer"
            };
            LoadError::syntax(
                self.path,
                n,
                format!("{what} index {:?} {problem}", lossy(tok)),
            )
        })?;
        let out = || LoadError::IndexOutOfRange {
            at: at(),
            what,
            index: i,
            count,
        };
        let zero_based = match i {
            0 => return Err(LoadError::IndexZero { at: at(), what }),
            i if i > 0 => i as u64 - 1,
            i => count.checked_sub(i.unsigned_abs()).ok_or_else(out)?,
        };
        if zero_based >= count {
            return Err(out());
        }
        // count <= u32::MAX - 1, checked when items are added.
        Ok(zero_based as u32)
    }

    fn current_object(&mut self) -> Result<u32, LoadError> {
        if let Some(o) = self.object {
            return Ok(o);
        }
        let o = match self.objects.get(&self.object_name) {
            Some(&o) => o,
            None => {
                check_u32(self.scene.objects.len(), "objects", self.path)?;
                let o = self.scene.add_object(&self.object_name);
                self.objects.insert(self.object_name.clone(), o);
                o
            }
        };
        self.object = Some(o);
        Ok(o)
    }

    /// The current `usemtl` name as text (invalid UTF-8 replaced, as in the library's
    /// names); empty without one.
    fn material_text(&self) -> Cow<'_, str> {
        String::from_utf8_lossy(self.material_name.as_deref().unwrap_or(b""))
    }

    fn current_material(&mut self) -> Result<u32, LoadError> {
        if let Some(m) = self.material {
            return Ok(m);
        }
        let raw = self.material_name.as_deref().unwrap_or(b"");
        // The default grey is keyed by the empty name, which no usemtl can give.
        // A name first used while no library defined it stays the default grey.
        let library = self.libraries.wait(&mut self.scene.warnings)?;
        // Read as text only when some name is undefined (rarely; the library comes first
        // otherwise, by bytes).
        let undefined = if self.undefined.is_empty() {
            None
        } else {
            self.undefined.get(&*String::from_utf8_lossy(raw)).copied()
        };
        let m = if let Some(m) = undefined {
            m
        } else if let Some(i) = library.index_from(self.library_index.wrapping_add(1), raw) {
            self.library_index = i;
            if self.scene_material.len() <= i {
                self.scene_material.resize(i + 1, NO_MATERIAL);
            }
            match self.scene_material[i] {
                NO_MATERIAL => {
                    check_u32(self.scene.materials.len(), "materials", self.path)?;
                    // Room for the whole library at its first use (one allocation
                    // rather than a copy at each doubling); the rest is given back at
                    // the end of the file.
                    if self.scene.materials.capacity() == self.scene.materials.len() {
                        self.scene.materials.reserve(library.len());
                    }
                    let m = self.scene.add_material(library.take(i));
                    self.scene_material[i] = m;
                    m
                }
                m => m,
            }
        } else {
            let name = String::from_utf8_lossy(raw);
            if !name.is_empty() {
                self.scene.warnings.push(format!(
                    "{}:{}: material {name:?} is not defined; using the default grey",
                    self.path.display(),
                    self.material_line
                ));
            }
            check_u32(self.scene.materials.len(), "materials", self.path)?;
            let m = self.scene.add_material(Material::default_grey());
            self.undefined.insert(name.into_owned(), m);
            m
        };
        self.material = Some(m);
        Ok(m)
    }

    fn mtllib(&mut self, n: u64, rest: &[u8]) -> Result<(), LoadError> {
        if rest.is_empty() {
            return Err(LoadError::syntax(
                self.path,
                n,
                "mtllib without a file name",
            ));
        }
        let at = Location::line(self.path, n);
        let whole = lossy(rest);
        // A name may hold spaces; if the whole rest is no file, read it as a list.
        let names: Vec<String> = if refs::resolve(&whole, &at, self.opts)?.is_file() {
            vec![whole]
        } else {
            tokens(rest).map(lossy).collect()
        };
        for name in names {
            let file = refs::resolve(&name, &at, self.opts)?;
            // The libraries named before come first (their warnings too).
            self.libraries.wait(&mut self.scene.warnings)?;
            match std::fs::read(&file) {
                Ok(bytes) => {
                    self.scene.files.push(file.clone());
                    self.libraries.add(bytes, file, &mut self.scene.warnings)?
                }
                Err(e) => self.scene.warnings.push(format!(
                    "{}:{n}: cannot read material library {}: {e}; using default materials",
                    self.path.display(),
                    file.display()
                )),
            }
        }
        // Materials already resolved keep what they were; later faces see the new ones.
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Loads `obj` (written with `files` beside it) with every library parsed in
    /// line and with every library parsed on another thread; both must agree.
    fn both_ways(files: &[(&str, &str)], obj: &str) -> Result<Scene, String> {
        let dir = tempfile::tempdir().unwrap();
        for (name, text) in files {
            std::fs::write(dir.path().join(name), text).unwrap();
        }
        let path = dir.path().join("m.obj");
        let opts = LoadOptions::default();
        let run = |from| {
            parse_with(obj.as_bytes(), &path, &opts, from).map_err(|e| {
                // Messages name the temporary folder: keep the part after it.
                let msg = e.to_string();
                msg.rsplit('/').next().unwrap_or(&msg).to_string()
            })
        };
        let (here, threaded) = (run(usize::MAX), run(0));
        assert_eq!(here, threaded, "in line and on another thread differ");
        here
    }

    const A: &str =
        "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 1 2\nmap_Ks x.png\nnewmtl t\nmap_Kd t.png\n";
    const LATE: &str = "newmtl late\nKd 0 0 1\nnewmtl a\nKd 1 1 1\n";
    const TRI: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

    #[test]
    fn libraries_on_another_thread_give_the_same_scene() {
        let files = [("a.mtl", A), ("late.mtl", LATE)];
        let obj = format!(
            "mtllib a.mtl\n{TRI}usemtl b\nf 1 2 3\nusemtl a\nf 1 2 3\nusemtl late\nf 1 2 3\n\
             mtllib nowhere.mtl late.mtl\nusemtl late\nf 1 2 3\nusemtl a\nl 1 2\n\
             usemtl t\nf 1 2 3\nusemtl gone\np 3\n"
        );
        let s = both_ways(&files, &obj).unwrap();
        let names: Vec<&str> = s.materials.iter().map(|m| m.name.as_str()).collect();
        assert_eq!(names, ["b", "a", "default", "t", "default"]);
        assert_eq!(s.materials[1].kd, [1.0, 0.0, 0.0], "a as first defined");
        let w = s.warnings.join("\n");
        // In the sequential order: a.mtl's clamp and texture warnings, then the OBJ's.
        let order = [
            "a.mtl:4: colour",
            "a.mtl:5: texture",
            "m.obj:9: material \"late\"",
            "nowhere.mtl",
            "m.obj:18: material \"gone\"",
        ];
        let at: Vec<usize> = order
            .iter()
            .map(|o| w.find(o).unwrap_or(usize::MAX))
            .collect();
        assert!(at.windows(2).all(|p| p[0] < p[1]), "{w}");
        assert_eq!(s.warnings.len(), order.len(), "{w}");
        // The libraries stay among the files read.
        assert_eq!(s.files.len(), 2);
    }

    #[test]
    fn material_names_that_are_not_utf8_are_read_alike_in_obj_and_mtl() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(
            dir.path().join("n.mtl"),
            b"newmtl r\xff\nKd 1 0 0\nnewmtl \xe2\x82\nKd 0 1 0\n",
        )
        .unwrap();
        // Other invalid bytes in the same place read as the same name, defined or not.
        let obj = b"mtllib n.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl r\xff\nf 1 2 3\nusemtl \xe2\x82\nf 1 2 3\nusemtl r\nf 1 2 3\n\
                    usemtl r\xfe\nf 1 2 3\nusemtl q\xff\nf 1 2 3\nusemtl r\nf 1 2 3\nusemtl q\xfe\nf 1 2 3\n";
        let s = parse(obj, &dir.path().join("m.obj"), &LoadOptions::default()).unwrap();
        let kd: Vec<[f64; 3]> = s.materials.iter().map(|m| m.kd).collect();
        let grey = Material::default_grey().kd;
        assert_eq!(kd, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], grey, grey]);
        assert_eq!(s.materials[0].name, "r\u{fffd}");
        let used: Vec<u32> = s.faces.iter().map(|f| f.material).collect();
        assert_eq!(used, [0, 1, 2, 0, 3, 2, 3]);
        assert_eq!(s.warnings.len(), 2, "{:?}", s.warnings);
        assert!(s.warnings[1].contains("\"q\u{fffd}\""), "{:?}", s.warnings);
    }

    #[test]
    fn a_usemtl_without_a_name_is_the_default_grey_with_one_warning() {
        let obj = format!(
            "mtllib a.mtl\n{TRI}usemtl a\nf 1 2 3\nusemtl\nf 1 2 3\nusemtl a\nusemtl \nf 1 2 3\n"
        );
        let s = both_ways(&[("a.mtl", A)], &obj).unwrap();
        let used: Vec<&str> = s
            .faces
            .iter()
            .map(|f| s.materials[f.material as usize].name.as_str())
            .collect();
        assert_eq!(used, ["a", "default", "default"]);
        let w: Vec<&String> = s.warnings.iter().filter(|w| w.contains("usemtl")).collect();
        assert_eq!(w.len(), 1, "{:?}", s.warnings);
        assert!(
            w[0].ends_with(
                "m.obj:7: usemtl without a name (and 1 more); its faces get the default grey"
            ),
            "{w:?}"
        );
    }

    #[test]
    fn a_library_waited_for_only_at_the_end_still_warns() {
        let s = both_ways(&[("a.mtl", A)], &format!("mtllib a.mtl\n{TRI}f 1 2 3\n")).unwrap();
        assert_eq!(s.warnings.len(), 2, "{:?}", s.warnings);
        assert_eq!(s.materials, vec![Material::default_grey()]);
    }

    #[test]
    fn a_library_error_comes_before_later_errors_of_the_obj() {
        let bad = "newmtl a\nKd 1 0 0\nKd 1 x 0\n";
        let files = [("bad.mtl", bad), ("a.mtl", A)];
        // An OBJ error below the `mtllib`, before and after a `usemtl` would need it.
        for tail in [
            "f 1 2 9\n",
            "usemtl a\nf 1 2 3\nf 1 2 9\n",
            "mtllib a.mtl\nf 1 2 9\n",
            "",
        ] {
            let obj = format!("mtllib bad.mtl\n{TRI}{tail}");
            let e = both_ways(&files, &obj).unwrap_err();
            assert!(e.starts_with("bad.mtl:3:"), "{tail:?}: {e}");
        }
        // An OBJ error above the `mtllib` comes first.
        let e = both_ways(&files, &format!("{TRI}f 1 2 9\nmtllib bad.mtl\n")).unwrap_err();
        assert!(e.starts_with("m.obj:4:"), "{e}");
    }

    /// Statements an OBJ of the generated tests is made of: vertices, faces, marks,
    /// material names defined, redefined, undefined and used before their library, the
    /// libraries (one with warnings, one failing at its line 3, one missing), errors.
    const STATEMENTS: &[&str] = &[
        "v 0 0 0\nv 1 0 0\nv 0 1 0",
        "f 1 2 3",
        "f -1 -2 -3",
        "l 1 2",
        "p 1",
        "usemtl a",
        "usemtl b",
        "usemtl t",
        "usemtl late",
        "usemtl gone",
        "mtllib a.mtl",
        "mtllib late.mtl",
        "mtllib bad.mtl",
        "mtllib nowhere.mtl late.mtl",
        "f 1 2 99",
        "vt 0.5 0.5\nf 1/1 2/1 3/1",
    ];

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(200))]

        #[test]
        fn any_obj_loads_the_same_with_libraries_on_another_thread(
            picks in proptest::collection::vec(0..STATEMENTS.len(), 0..24)
        ) {
            let bad = "newmtl a\nKd 1 0 0\nKd 1 x 0\n";
            let files = [("a.mtl", A), ("late.mtl", LATE), ("bad.mtl", bad)];
            let mut obj = String::new();
            for i in picks {
                obj += STATEMENTS[i];
                obj.push('\n');
            }
            // `both_ways` asserts that both ways agree.
            let _ = both_ways(&files, &obj);
        }
    }
}
