//! STL, binary and ASCII.
//!
//! Written here rather than with `stl_io`: its ASCII errors carry no line, it tells
//! binary from ASCII by the leading `solid` (which many binary exporters also write),
//! and its binary reader trusts the triangle count. Here a file is binary when its size
//! is exactly 84 + 50·n for the n in its header, ASCII when it starts with `solid` and
//! holds no NUL byte, and otherwise binary with a size that is checked against n
//! before anything is allocated.
//!
//! Each triangle becomes one face (ASCII loops with more than three vertices become
//! one polygon). Vertices with identical coordinates are shared, so closed meshes stay
//! closed. Facet normals are ignored (the winding defines the face's normal), as are
//! the binary attribute bytes. One object per `solid` (named after it, or after the file
//! stem when it has no name); binary files give one object named after the stem.

use std::path::Path;

use glam::DVec3;

use super::text::{lossy, parse_f64, position_key, tokens, BitsMap, Lines};
use super::{check_u32, stem, LoadError, Location};
use limn_scene::{Face, Material, Scene};

const HEADER: usize = 84;
const RECORD: usize = 50;

/// Parses an STL file (binary or ASCII, told apart by content).
pub(crate) fn parse(bytes: &[u8], path: &Path) -> Result<Scene, LoadError> {
    let claimed = (bytes.len() >= HEADER)
        .then(|| u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as u64);
    let exact_binary =
        claimed.is_some_and(|n| HEADER as u64 + RECORD as u64 * n == bytes.len() as u64);
    let starts_solid = bytes
        .trim_ascii_start()
        .get(..5)
        .is_some_and(|s| s.eq_ignore_ascii_case(b"solid"));
    if !exact_binary && starts_solid && !bytes.contains(&0) {
        return parse_ascii(bytes, path);
    }
    let Some(n) = claimed else {
        return Err(LoadError::Truncated {
            at: Location::file(path),
            detail: format!(
                "{} bytes, but a binary STL has an 84-byte header (and an ASCII one starts with \"solid\")",
                bytes.len()
            ),
        });
    };
    let room = ((bytes.len() - HEADER) / RECORD) as u64;
    if n > room {
        return Err(LoadError::CountTooLarge {
            at: Location::file(path),
            what: "triangles".into(),
            claimed: n,
            room,
        });
    }
    let mut b: Builder<[u32; 3]> = Builder::new(path, n as usize);
    let object = b.scene.add_object(&stem(path));
    if room > n {
        b.scene.warnings.push(format!(
            "{}: {} bytes after the last of the {n} triangles ignored",
            path.display(),
            bytes.len() - HEADER - RECORD * n as usize
        ));
    }
    for (i, rec) in bytes[HEADER..]
        .chunks_exact(RECORD)
        .take(n as usize)
        .enumerate()
    {
        let f = |k: usize| {
            let o = 12 + 4 * k;
            f32::from_le_bytes([rec[o], rec[o + 1], rec[o + 2], rec[o + 3]]) + 0.0
        };
        let corners = [0, 1, 2].map(|c| [f(3 * c), f(3 * c + 1), f(3 * c + 2)]);
        if corners.iter().flatten().any(|c| !c.is_finite()) {
            return Err(LoadError::NonFinite {
                at: Location::record(path, format!("triangle {}", i + 1)),
                what: "vertex coordinate".into(),
            });
        }
        // Keyed by the f32 bits (−0 folded into +0 above): half the key of an f64.
        let keyed = corners.map(|p| {
            (
                p.map(f32::to_bits),
                DVec3::new(p[0] as f64, p[1] as f64, p[2] as f64),
            )
        });
        b.face(&keyed, object)?;
    }
    Ok(b.scene)
}

/// Builds faces over shared vertices, found by a key made of their coordinates' bits.
struct Builder<'a, K> {
    path: &'a Path,
    scene: Scene,
    index: BitsMap<K, u32>,
    material: u32,
}

impl<'a, K: std::hash::Hash + Eq + Copy> Builder<'a, K> {
    fn new(path: &'a Path, faces: usize) -> Self {
        let mut scene = Scene::default();
        // `faces` was checked against the file size by the caller. A closed triangle
        // mesh has about half as many vertices as triangles.
        scene.faces.reserve(faces);
        scene.vertices.reserve(faces / 2 + 3);
        let material = scene.add_material(Material::default_grey());
        let mut index = BitsMap::default();
        index.reserve(faces / 2 + 3);
        Builder {
            path,
            scene,
            index,
            material,
        }
    }

    fn vertex(&mut self, key: K, p: DVec3) -> Result<u32, LoadError> {
        if let Some(&v) = self.index.get(&key) {
            return Ok(v);
        }
        check_u32(self.scene.vertices.len(), "vertices", self.path)?;
        let v = self.scene.add_vertex(p);
        self.index.insert(key, v);
        Ok(v)
    }

    fn face(&mut self, corners: &[(K, DVec3)], object: u32) -> Result<(), LoadError> {
        let vertices = corners
            .iter()
            .map(|&(k, p)| self.vertex(k, p))
            .collect::<Result<Vec<_>, _>>()?;
        check_u32(self.scene.faces.len(), "faces", self.path)?;
        self.scene.faces.push(Face {
            vertices: vertices.into(),
            normals: None,
            texcoords: None,
            colors: None,
            material: self.material,
            object,
        });
        Ok(())
    }
}

#[derive(PartialEq, Eq, Clone, Copy, Debug)]
enum Expect {
    Solid,
    FacetOrEnd,
    OuterLoop,
    VertexOrEndLoop,
    EndFacet,
}

fn parse_ascii(bytes: &[u8], path: &Path) -> Result<Scene, LoadError> {
    let mut b: Builder<[u64; 3]> = Builder::new(path, 0);
    let mut lines = Lines::new(bytes, path, false);
    let mut state = Expect::Solid;
    let mut object = 0;
    let mut corners: Vec<([u64; 3], DVec3)> = Vec::with_capacity(3);
    let mut last = 0;
    while let Some(next) = lines.next_line() {
        let (n, line) = next?;
        last = n;
        let mut toks = tokens(&line);
        let Some(key) = toks.next() else { continue };
        let key = key.to_ascii_lowercase();
        let bad = |what: &str| {
            LoadError::syntax(
                path,
                n,
                format!("expected {what}, found {:?}", lossy(&line).trim()),
            )
        };
        match (state, key.as_slice()) {
            (Expect::Solid, b"solid") => {
                let name = lossy(toks.remainder());
                let name = if name.is_empty() { stem(path) } else { name };
                check_u32(b.scene.objects.len(), "objects", path)?;
                object = b.scene.add_object(&name);
                state = Expect::FacetOrEnd;
            }
            (Expect::Solid, _) => return Err(bad("\"solid\"")),
            (Expect::FacetOrEnd, b"facet") => state = Expect::OuterLoop,
            (Expect::FacetOrEnd, b"endsolid") => state = Expect::Solid,
            (Expect::FacetOrEnd, _) => return Err(bad("\"facet\" or \"endsolid\"")),
            (Expect::OuterLoop, b"outer")
                if toks.next().map(|t| t.eq_ignore_ascii_case(b"loop")) == Some(true) =>
            {
                corners.clear();
                state = Expect::VertexOrEndLoop;
            }
            (Expect::OuterLoop, _) => return Err(bad("\"outer loop\"")),
            (Expect::VertexOrEndLoop, b"vertex") => {
                let mut c = [0.0; 3];
                for (k, v) in c.iter_mut().enumerate() {
                    let t = toks.next().ok_or_else(|| bad("three vertex coordinates"))?;
                    *v = parse_f64(t).ok_or_else(|| {
                        LoadError::syntax(
                            path,
                            n,
                            format!("vertex coordinate {k}: {:?} is not a number", lossy(t)),
                        )
                    })?;
                }
                let p = DVec3::from(c) + DVec3::ZERO;
                if !p.is_finite() {
                    return Err(LoadError::NonFinite {
                        at: Location::line(path, n),
                        what: "vertex coordinate".into(),
                    });
                }
                corners.push((position_key(c), p));
            }
            (Expect::VertexOrEndLoop, b"endloop") => {
                if corners.len() < 3 {
                    return Err(LoadError::TooFewVertices {
                        at: Location::line(path, n),
                        count: corners.len(),
                    });
                }
                b.face(&corners, object)?;
                state = Expect::EndFacet;
            }
            (Expect::VertexOrEndLoop, _) => return Err(bad("\"vertex\" or \"endloop\"")),
            (Expect::EndFacet, b"endfacet") => state = Expect::FacetOrEnd,
            (Expect::EndFacet, _) => return Err(bad("\"endfacet\"")),
        }
    }
    if state != Expect::Solid && state != Expect::FacetOrEnd {
        return Err(LoadError::Truncated {
            at: Location::line(path, last + 1),
            detail: "inside a facet".into(),
        });
    }
    if state == Expect::FacetOrEnd {
        b.scene.warnings.push(format!(
            "{}:{}: no \"endsolid\" at the end",
            path.display(),
            last
        ));
    }
    Ok(b.scene)
}
