//! Wavefront MTL material libraries.
//!
//! Read: `newmtl`, `Kd`, `Ka`, `Ks` (RGB triples), `Ns`, `d` (opacity, also with
//! `-halo`), `Tr` (transparency, = 1 − d; ignored when the material also has a `d`),
//! `illum` (0–10), `map_Kd` (the diffuse texture, see [`MapRef`]).
//!
//! Opacity: `d` decides when a material has one, wherever it stands; otherwise `Tr` as
//! 1 − Tr. A material left with opacity 0 would draw nothing, and that is never what a
//! file means: writers disagree on `Tr` (MeshLab writes `Tr 1.000000` for opaque
//! materials, the MTL definition reads it as fully transparent), so such a material is
//! drawn opaque, with a warning naming the file and the line that made it transparent. Other texture maps (`map_Ks`, `bump`, …) are not drawn, with one warning
//! per library naming the first; other statements (`Ke`, `Ni`, PBR extensions) are
//! ignored. A material starts from
//! [`Material::default_grey`] and the statements override its fields. Colours outside
//! [0, 1] are clamped with a warning; non-finite numbers are errors.
//!
//! `tobj` has an MTL parser, but its errors carry neither file nor line.

use rustc_hash::FxHashMap as HashMap;
use std::path::Path;

use super::name_table::NameTable;
use super::text::{lossy, number, strip_comment, tokens, Lines};
use super::{LoadError, Location};
use limn_scene::Material;

/// Materials by name, in the order of definition (later definitions replace earlier
/// ones of the same name). Kept in a vector with a [`NameTable`] beside it: an OBJ with
/// one material per face looks a name up for each, and such a lookup reads the table and
/// one buffer of names, not the material.
#[derive(Debug, Default)]
pub(crate) struct Library {
    materials: Vec<Material>,
    by_name: NameTable,
    /// The `map_Kd` of each material that has one, by material name. The image is read
    /// only when a face with texture coordinates uses the material.
    pub(crate) maps: HashMap<String, MapRef>,
}

/// At most this many materials are made room for at once by [`Library::reserve`]
/// (8 MB): a file of many `newmtl` of one name must not reserve for all of them.
const RESERVE_AT_MOST: usize = 1 << 16;

impl Library {
    /// Makes room for the materials MTL text `bytes` defines, counted by the word
    /// `newmtl` (a hint: comments and redefinitions count too, and at most
    /// [`RESERVE_AT_MOST`] are made room for). One allocation of the right size,
    /// rather than a copy at each doubling, and on the calling thread.
    pub(crate) fn reserve(&mut self, bytes: &[u8]) {
        let count = memchr::memmem::find_iter(bytes, b"newmtl")
            .take(RESERVE_AT_MOST)
            .count();
        self.materials.reserve(count);
        self.by_name.reserve(count);
    }

    /// Adds `m`, replacing a material of the same name.
    pub(crate) fn insert(&mut self, m: Material) {
        match self.by_name.get(&m.name) {
            Some(i) => self.materials[i] = m,
            None => {
                self.by_name.insert(&m.name, self.materials.len());
                self.materials.push(m);
            }
        }
    }

    /// The material named `name`.
    #[cfg(test)]
    pub(crate) fn get(&self, name: &str) -> Option<&Material> {
        self.index(name).map(|i| &self.materials[i])
    }

    /// The index of the material named `name` (it keeps its index when redefined).
    pub(crate) fn index(&self, name: &str) -> Option<usize> {
        self.by_name.get(name)
    }

    /// [`Library::index`] of the name `usemtl` gave as bytes (read as UTF-8, invalid
    /// sequences replaced as the library's names were), trying index `hint` first: a file
    /// that names materials in the library's order finds each by one comparison of bytes,
    /// without hashing or reading the name as text. Exact: the material at an index
    /// always has the name that leads to that index, or the empty name once taken, which
    /// no `usemtl` gives; bytes equal to a name are valid UTF-8 and read as that name.
    pub(crate) fn index_from(&self, hint: usize, name: &[u8]) -> Option<usize> {
        match self.materials.get(hint) {
            Some(m) if !name.is_empty() && m.name.as_bytes() == name => Some(hint),
            _ => self.index(&String::from_utf8_lossy(name)),
        }
    }

    /// The number of materials (each name once).
    pub(crate) fn len(&self) -> usize {
        self.materials.len()
    }

    /// Moves the material at `index` (from [`Library::index`]) out, leaving an unnamed
    /// placeholder: an OBJ takes each library material into its scene once, on first
    /// use, and never reads that index again (its scene material is remembered).
    pub(crate) fn take(&mut self, index: usize) -> Material {
        std::mem::replace(&mut self.materials[index], Material::unlit("", [0.0; 3]))
    }
}

/// A `map_Kd` statement: the image as named, where it was named, and the options that
/// move texture coordinates.
///
/// Options: `-s u v` (scale) and `-o u v` (offset) transform texture coordinates as
/// `(u, v) ↦ (s·u + o, …)` (a third number, for 3D textures, is read and ignored);
/// `-clamp on` extends the edge texels outside [0, 1] instead of repeating (see
/// [`limn_scene::texture_wrap`]); `-blendu`, `-blendv`, `-cc`, `-boost`, `-texres` and
/// `-bm` change nothing in limn's pictures and are read and ignored; `-mm`, `-t` and
/// `-imfchan` would change colours and are refused with the line.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct MapRef {
    /// The file as written.
    pub(crate) file: String,
    /// The MTL file and line of the statement (references resolve against its folder).
    pub(crate) at: Location,
    /// `-s`: scale of `u` and `v`.
    pub(crate) scale: [f64; 2],
    /// `-o`: offset of `u` and `v`.
    pub(crate) offset: [f64; 2],
    /// `-clamp on`: the edge texels extend outside [0, 1] (else the texture repeats).
    pub(crate) clamp: bool,
}

/// Parses MTL text into `lib`, appending warnings.
pub(crate) fn parse(
    bytes: &[u8],
    path: &Path,
    lib: &mut Library,
    warnings: &mut Vec<String>,
) -> Result<(), LoadError> {
    let mut lines = Lines::new(bytes, path, true);
    let mut current: Option<Material> = None;
    // The current material's `d` and `Tr` (line, value): the opacity is decided from
    // both when the material ends.
    let mut opacity = Opacity::default();
    // The first texture statement, reported once per library.
    let mut textures: Option<(u64, String)> = None;
    while let Some(next) = lines.next_line() {
        let (n, line) = next?;
        let line = strip_comment(&line);
        let mut toks = tokens(line);
        let Some(key) = toks.next() else { continue };
        if key == b"newmtl" {
            if let Some(mut m) = current.take() {
                opacity.decide(&mut m, path, warnings);
                lib.insert(m);
            }
            opacity = Opacity::default();
            let name = lossy(toks.remainder());
            if name.is_empty() {
                return Err(LoadError::syntax(path, n, "newmtl without a name"));
            }
            // A redefinition starts without the earlier definition's map.
            if !lib.maps.is_empty() {
                lib.maps.remove(&name);
            }
            let mut m = Material::default_grey();
            m.name = name;
            current = Some(m);
            continue;
        }
        let Some(m) = current.as_mut() else {
            if is_known(key) {
                return Err(LoadError::syntax(
                    path,
                    n,
                    format!("{} before any newmtl", lossy(key)),
                ));
            }
            continue;
        };
        match key {
            b"Kd" | b"Ka" | b"Ks" => {
                let first = toks.next();
                if matches!(first, Some(b"spectral") | Some(b"xyz")) {
                    warnings.push(format!(
                        "{}:{n}: {} {} is not supported; keeping the default",
                        path.display(),
                        lossy(key),
                        lossy(first.unwrap_or_default())
                    ));
                    continue;
                }
                let r = finite(path, n, number(path, n, first, "red")?)?;
                // "Kd r" alone means grey r.
                let g = match toks.next() {
                    Some(t) => finite(path, n, number(path, n, Some(t), "green")?)?,
                    None => r,
                };
                let b = match toks.next() {
                    Some(t) => finite(path, n, number(path, n, Some(t), "blue")?)?,
                    None => g,
                };
                let c = clamp_colour([r, g, b], path, n, warnings);
                match key {
                    b"Kd" => m.kd = c,
                    b"Ka" => m.ka = c,
                    _ => m.ks = c,
                }
            }
            b"Ns" => {
                let v = finite(path, n, number(path, n, toks.next(), "Ns value")?)?;
                m.ns = v.max(0.0);
            }
            b"d" => {
                let mut t = toks.next();
                if t == Some(b"-halo") {
                    t = toks.next();
                }
                let v = finite(path, n, number(path, n, t, "d value")?)?;
                opacity.d = Some((n, v));
            }
            b"Tr" => {
                let v = finite(path, n, number(path, n, toks.next(), "Tr value")?)?;
                opacity.tr = Some((n, v));
            }
            b"illum" => {
                let v = number(path, n, toks.next(), "illum model")?;
                if !(0.0..=10.0).contains(&v) || v.fract() != 0.0 {
                    return Err(LoadError::syntax(
                        path,
                        n,
                        format!("illum {v} is not a model number 0..10"),
                    ));
                }
                m.illum = v as u8;
            }
            b"map_Kd" => {
                let map = map_kd(path, n, toks.remainder())?;
                lib.maps.insert(m.name.clone(), map);
            }
            _ if is_texture(key) => {
                textures.get_or_insert((n, lossy(key)));
            }
            _ => {}
        }
    }
    if let Some(mut m) = current.take() {
        opacity.decide(&mut m, path, warnings);
        lib.insert(m);
    }
    if let Some((line, key)) = textures {
        warnings.push(format!(
            "{}:{line}: texture maps ({key} and any later ones) are not drawn; faces get \
             their material's Kd colour",
            path.display()
        ));
    }
    Ok(())
}

/// A material's `d` and `Tr` statements, each as (line, value), the last of each kind.
#[derive(Debug, Default)]
struct Opacity {
    d: Option<(u64, f64)>,
    tr: Option<(u64, f64)>,
}

impl Opacity {
    /// Sets `m.opacity`: from `d` when given, else 1 − `Tr`, clamped to [0, 1]; an
    /// opacity of 0 (nothing would be drawn) becomes 1, with a warning at the line that
    /// gave it.
    fn decide(&self, m: &mut Material, path: &Path, warnings: &mut Vec<String>) {
        let (line, opacity, said) = match (self.d, self.tr) {
            (Some((n, d)), _) => (n, d.clamp(0.0, 1.0), format!("d {d}")),
            (None, Some((n, tr))) => (n, (1.0 - tr).clamp(0.0, 1.0), format!("Tr {tr}")),
            (None, None) => return,
        };
        if opacity > 0.0 {
            m.opacity = opacity;
            return;
        }
        m.opacity = 1.0;
        let why = if self.d.is_some() {
            ""
        } else {
            "; some writers mean Tr as opacity"
        };
        warnings.push(format!(
            "{}:{line}: material {:?} would draw nothing ({said}{why}); drawn opaque",
            path.display(),
            m.name
        ));
    }
}

/// Reads the options and file name of a `map_Kd` statement (`rest` follows the key).
fn map_kd(path: &Path, n: u64, rest: &[u8]) -> Result<MapRef, LoadError> {
    let mut scale = [1.0, 1.0];
    let mut offset = [0.0, 0.0];
    let mut clamp = false;
    let toks: Vec<&[u8]> = tokens(rest).collect();
    let mut i = 0;
    // Up to `max` numbers after an option.
    let numbers = |i: &mut usize, max: usize| -> Result<Vec<f64>, LoadError> {
        let mut v = Vec::new();
        while v.len() < max {
            match toks.get(*i).and_then(|t| crate::text::parse_f64(t)) {
                Some(x) if x.is_finite() => v.push(x),
                Some(_) => {
                    return Err(LoadError::NonFinite {
                        at: Location::line(path, n),
                        what: "map_Kd option".into(),
                    })
                }
                None => break,
            }
            *i += 1;
        }
        Ok(v)
    };
    while let Some(&t) = toks.get(i) {
        if !t.starts_with(b"-") || t.len() < 2 {
            break;
        }
        i += 1;
        match t {
            b"-s" | b"-o" => {
                let v = numbers(&mut i, 3)?;
                if v.is_empty() {
                    return Err(LoadError::syntax(
                        path,
                        n,
                        format!("map_Kd {} needs numbers", lossy(t)),
                    ));
                }
                let uv = [
                    v[0],
                    v.get(1)
                        .copied()
                        .unwrap_or(if t == b"-s" { 1.0 } else { 0.0 }),
                ];
                if t == b"-s" {
                    scale = uv;
                } else {
                    offset = uv;
                }
            }
            b"-blendu" | b"-blendv" | b"-cc" | b"-clamp" => {
                let v = toks.get(i).copied().unwrap_or_default();
                if v != b"on" && v != b"off" {
                    return Err(LoadError::syntax(
                        path,
                        n,
                        format!("map_Kd {} needs on or off", lossy(t)),
                    ));
                }
                if t == b"-clamp" {
                    clamp = v == b"on";
                }
                i += 1;
            }
            b"-boost" | b"-texres" | b"-bm" => {
                numbers(&mut i, 1)?;
            }
            _ => {
                return Err(LoadError::Unsupported {
                    at: Location::line(path, n),
                    what: format!("map_Kd option {}", lossy(t)),
                })
            }
        }
    }
    let file = toks[i.min(toks.len())..]
        .iter()
        .map(|t| lossy(t))
        .collect::<Vec<_>>()
        .join(" ");
    if file.is_empty() {
        return Err(LoadError::syntax(path, n, "map_Kd without a file name"));
    }
    Ok(MapRef {
        file,
        at: Location::line(path, n),
        scale,
        offset,
        clamp,
    })
}

/// Texture and bump map statements.
fn is_texture(key: &[u8]) -> bool {
    key.starts_with(b"map_") || matches!(key, b"bump" | b"disp" | b"decal" | b"refl")
}

fn is_known(key: &[u8]) -> bool {
    matches!(key, b"Kd" | b"Ka" | b"Ks" | b"Ns" | b"d" | b"Tr" | b"illum")
}

fn finite(path: &Path, line: u64, v: f64) -> Result<f64, LoadError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(LoadError::NonFinite {
            at: Location::line(path, line),
            what: "material value".into(),
        })
    }
}

fn clamp_colour(c: [f64; 3], path: &Path, line: u64, warnings: &mut Vec<String>) -> [f64; 3] {
    if c.iter().any(|v| !(0.0..=1.0).contains(v)) {
        warnings.push(format!(
            "{}:{line}: colour {c:?} clamped to [0, 1]",
            path.display()
        ));
    }
    c.map(|v| v.clamp(0.0, 1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_later_definition_replaces_an_earlier_one() {
        let src = b"newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 1 0\nnewmtl a\nKd 0 0 1\n";
        let mut lib = Library::default();
        parse(src, Path::new("x.mtl"), &mut lib, &mut Vec::new()).unwrap();
        assert_eq!(lib.get("a").unwrap().kd, [0.0, 0.0, 1.0]);
        assert_eq!(lib.get("b").unwrap().kd, [0.0, 1.0, 0.0]);
        assert!(lib.get("c").is_none());
    }

    #[test]
    fn room_is_made_for_the_materials_defined_but_not_for_any_count() {
        let mut lib = Library::default();
        lib.reserve(b"newmtl a\nKd 1 0 0\nnewmtl b\n# newmtl c\n");
        assert!(lib.materials.capacity() >= 3);
        let many = "newmtl a\n".repeat(4 * RESERVE_AT_MOST);
        let mut lib = Library::default();
        lib.reserve(many.as_bytes());
        assert!(lib.materials.capacity() < 2 * RESERVE_AT_MOST);
        parse(
            many.as_bytes(),
            Path::new("a.mtl"),
            &mut lib,
            &mut Vec::new(),
        )
        .unwrap();
        assert_eq!(lib.len(), 1);
    }

    #[test]
    fn a_hint_finds_what_the_name_finds() {
        let mut lib = Library::default();
        let src = b"newmtl a\nnewmtl b\nnewmtl c\nnewmtl a\nKd 1 0 0\n";
        parse(src, Path::new("a.mtl"), &mut lib, &mut Vec::new()).unwrap();
        for name in ["a", "b", "c", "d", ""] {
            for hint in [0, 1, 2, 3, usize::MAX] {
                assert_eq!(
                    lib.index_from(hint, name.as_bytes()),
                    lib.index(name),
                    "{name} at {hint}"
                );
            }
        }
        // A material taken keeps its index; its place answers to no name.
        let b = lib.take(1);
        assert_eq!(b.name, "b");
        assert_eq!(lib.index_from(1, b"b"), Some(1));
        assert_eq!(lib.index_from(1, b""), None);
        assert_eq!(lib.index_from(0, b"a"), Some(0));
        assert_eq!(lib.get("a").unwrap().kd, [1.0, 0.0, 0.0]);
    }

    #[test]
    fn reads_the_fields_limn_uses() {
        let src = b"# c\nnewmtl red\nKd 1 0 0\nKs 0.5 0.5 0.5\nNs 20\nillum 2\nTr 0.25\n\
                    newmtl unlit glass\nKd 0.2\nd -halo 0.5\nillum 0\nmap_Ks x.png\n";
        let mut lib = Library::default();
        let mut w = Vec::new();
        parse(src, Path::new("a.mtl"), &mut lib, &mut w).unwrap();
        let red = lib.get("red").unwrap();
        assert_eq!(red.kd, [1.0, 0.0, 0.0]);
        assert_eq!(red.ks, [0.5; 3]);
        assert_eq!((red.ns, red.illum, red.opacity), (20.0, 2, 0.75));
        let g = lib.get("unlit glass").unwrap();
        assert_eq!((g.kd, g.opacity, g.illum), ([0.2; 3], 0.5, 0));
        // The texture map is the one thing not drawn: one warning at its line.
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(w[0].starts_with("a.mtl:12: texture maps (map_Ks"), "{w:?}");
    }

    #[test]
    fn d_decides_over_tr_and_a_fully_transparent_material_is_drawn_opaque() {
        // MeshLab's `Tr 1.000000` for an opaque material; `d` beside `Tr` in either
        // order; `Tr` alone as 1 − Tr; `d 0`.
        let src = b"newmtl meshlab\nKd 1 1 1\nTr 1.000000\nillum 2\n\
                    newmtl both\nTr 1\nd 0.5\nnewmtl both2\nd 1\nTr 0.75\n\
                    newmtl tr\nTr 0.25\nnewmtl gone\nd 0\nTr 0\nnewmtl plain\n";
        let mut lib = Library::default();
        let mut w = Vec::new();
        parse(src, Path::new("a.mtl"), &mut lib, &mut w).unwrap();
        let op = |n: &str| lib.get(n).unwrap().opacity;
        assert_eq!(op("meshlab"), 1.0);
        assert_eq!(op("both"), 0.5);
        assert_eq!(op("both2"), 1.0);
        assert_eq!(op("tr"), 0.75);
        assert_eq!(op("gone"), 1.0);
        assert_eq!(op("plain"), 1.0);
        // One warning per material drawn opaque, at the line that made it transparent.
        assert_eq!(w.len(), 2, "{w:?}");
        assert!(
            w[0].starts_with("a.mtl:3: material \"meshlab\" would draw nothing (Tr 1;"),
            "{w:?}"
        );
        assert!(w[0].ends_with("drawn opaque"), "{w:?}");
        assert!(
            w[1].starts_with("a.mtl:14: material \"gone\" would draw nothing (d 0)"),
            "{w:?}"
        );
    }

    #[test]
    fn map_kd_options_are_read_or_refused() {
        let src = b"newmtl a\nmap_Kd -s 2 3 1 -o 0.5 -blendu off -bm 1 my tex.png\n\
                    newmtl b\nmap_Kd -clamp on plain.jpg\n";
        let mut lib = Library::default();
        let mut w = Vec::new();
        parse(src, Path::new("a.mtl"), &mut lib, &mut w).unwrap();
        assert!(w.is_empty(), "{w:?}");
        let a = &lib.maps["a"];
        assert_eq!(a.file, "my tex.png");
        assert_eq!((a.scale, a.offset), ([2.0, 3.0], [0.5, 0.0]));
        assert_eq!(a.at, Location::line(Path::new("a.mtl"), 2));
        assert_eq!(lib.maps["b"].file, "plain.jpg");
        assert!(lib.maps["b"].clamp && !a.clamp);
        for (bad, what) in [
            ("map_Kd -clamp yes x.png", "-clamp needs on or off"),
            ("map_Kd -mm 0 1 x.png", "option -mm"),
            ("map_Kd -s x.png", "-s needs numbers"),
            ("map_Kd -s 1 nan x.png", "non-finite"),
            ("map_Kd -o 1", "without a file name"),
        ] {
            let src = format!("newmtl a\n\n{bad}\n");
            let e = parse(src.as_bytes(), Path::new("a.mtl"), &mut lib, &mut w).unwrap_err();
            let msg = e.to_string();
            assert!(
                msg.starts_with("a.mtl:3:") && msg.contains(what),
                "{bad}: {msg}"
            );
        }
    }

    #[test]
    fn errors_name_the_line() {
        let mut lib = Library::default();
        let mut w = Vec::new();
        let e = parse(
            b"newmtl a\nKd 1 x 0\n",
            Path::new("a.mtl"),
            &mut lib,
            &mut w,
        )
        .unwrap_err();
        assert!(e.to_string().starts_with("a.mtl:2:"), "{e}");
        let e = parse(
            b"newmtl a\nKd 1 nan 0\n",
            Path::new("a.mtl"),
            &mut lib,
            &mut w,
        )
        .unwrap_err();
        assert!(matches!(e, LoadError::NonFinite { .. }));
    }
}
