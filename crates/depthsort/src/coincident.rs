//! Faces drawn over by an identical later face: the same corners (bit for bit) in the
//! same cyclic order. By the coplanar rule the later face wins everywhere the two
//! overlap, which is everywhere, so when it is opaque and culled alike the earlier face
//! cannot show. Dropping such faces before ordering keeps many copies of one mesh linear
//! instead of quadratic in the number of copies (every pair of copies overlaps).

use std::hash::BuildHasher;

use glam::DVec3;
use hashbrown::hash_table::{Entry, HashTable};
use limn_scene::Scene;
use rayon::prelude::*;
use rustc_hash::FxBuildHasher;

use crate::by_vertex::ByVertex;

/// Canonical vertex ids: vertices at the same position (bit for bit) share the id of the
/// first of them. The positions are hashed; the vertices are split by hash into shards,
/// each read in order into a table of its own (in parallel), so the answer does not
/// depend on the threads. A table holds vertex ids (four bytes each) and finds a
/// position through them: a table of the positions themselves (28 bytes each) was
/// slower in a whole `limn render` of a 10k soup than the sort it replaced, for the
/// fresh memory it touched.
pub(crate) fn canonical_vertices(scene: &Scene) -> Vec<u32> {
    let n = scene.vertices.len();
    let key = |p: &DVec3| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()];
    let hashes: Vec<u64> = scene
        .vertices
        .par_iter()
        .with_min_len(VERTICES_PER_TASK)
        .map(|p| FxBuildHasher.hash_one(key(p)))
        .collect();
    let shards = (n / VERTICES_PER_TASK).clamp(1, MAX_SHARDS);
    // A vertex's shard, from bits of its hash the table's own use leaves alone (it
    // takes the low bits for a place, the top seven to tell entries apart).
    let shard_of = |h: u64| ((((h >> 24) & 0xffff_ffff) * shards as u64) >> 32) as usize;
    let parts: Vec<Vec<(u32, u32)>> = (0..shards)
        .into_par_iter()
        .map(|s| {
            // The first vertex at each position of the shard, by id (four bytes each).
            let mut first: HashTable<u32> = HashTable::with_capacity(n / shards / 8 * 9 + 64);
            let mut out = Vec::new();
            for (v, &h) in hashes.iter().enumerate() {
                if shard_of(h) != s {
                    continue;
                }
                let at = key(&scene.vertices[v]);
                let same = |&u: &u32| key(&scene.vertices[u as usize]) == at;
                match first.entry(h, same, |&u| hashes[u as usize]) {
                    Entry::Occupied(e) => out.push((v as u32, *e.get())),
                    Entry::Vacant(e) => {
                        e.insert(v as u32);
                    }
                }
            }
            out
        })
        .collect();
    let mut canon: Vec<u32> = (0..n as u32).collect();
    for (v, c) in parts.into_iter().flatten() {
        canon[v as usize] = c;
    }
    canon
}

/// Vertices per parallel task of [`canonical_vertices`], about.
const VERTICES_PER_TASK: usize = 16384;

/// Shards of [`canonical_vertices`] at most.
const MAX_SHARDS: usize = 16;

/// Per face: whether a later face with the same corners in the same cyclic order, an
/// opaque material and the same culling (`culled_object`) draws over all of it.
pub(crate) fn hidden_by_later_copies(
    scene: &Scene,
    canon: &[u32],
    culled_object: &[bool],
) -> Vec<bool> {
    let n = scene.faces.len();
    // Key of a face: its canonical corner ids rotated to start at the smallest, stored
    // one after another in `keys` (face `i` at `at[i]..at[i + 1]`).
    let mut at = Vec::with_capacity(n + 1);
    at.push(0usize);
    let mut keys: Vec<u32> = Vec::with_capacity(scene.faces.iter().map(|f| f.vertices.len()).sum());
    for f in &scene.faces {
        let s = keys.len();
        keys.extend(f.vertices.iter().map(|&v| canon[v as usize]));
        let key = &mut keys[s..];
        let start = (0..key.len()).min_by_key(|&k| key[k]).unwrap_or(0);
        key.rotate_left(start);
        at.push(keys.len());
    }
    let key = |i: u32| &keys[at[i as usize]..at[i as usize + 1]];
    // Faces by the first id of their key (its smallest), each group in input order; a
    // face with no corners is nobody's copy.
    let mut by_first = ByVertex::new(scene.vertices.len(), |put| {
        for i in 0..n as u32 {
            if let Some(&first) = key(i).first() {
                put(first, i);
            }
        }
    });
    let copies = by_first.flat_map_groups(|group, hidden: &mut Vec<u32>| {
        if group.len() < 2 {
            return;
        }
        // Faces of one key together, in input order (a total order, so the result does
        // not depend on the sort or on threads).
        group.sort_unstable_by(|&a, &b| key(a).cmp(key(b)).then(a.cmp(&b)));
        for copies in group.chunk_by(|&a, &b| key(a) == key(b)) {
            // Whether an opaque later copy was seen, per culling flag.
            let mut seen = [false; 2];
            for &i in copies.iter().rev() {
                let f = &scene.faces[i as usize];
                let cull = culled_object[f.object as usize] as usize;
                if seen[cull] {
                    hidden.push(i);
                }
                seen[cull] |= scene.materials[f.material as usize].is_opaque();
            }
        }
    });
    let mut hidden = vec![false; n];
    for i in copies {
        hidden[i as usize] = true;
    }
    hidden
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first vertex at each position, found by comparing every vertex with the
    /// earlier ones' positions (kept in a map, by bits).
    fn first_at_each_position(scene: &Scene) -> Vec<u32> {
        let mut seen = std::collections::BTreeMap::new();
        (0..scene.vertices.len() as u32)
            .map(|v| {
                let p = scene.vertices[v as usize];
                *seen
                    .entry([p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
                    .or_insert(v)
            })
            .collect()
    }

    /// Sets small (one shard) and large (several), with repeated positions near and far
    /// apart in the list, signed zeros (different bits, so different positions) and NaN.
    #[test]
    fn canonical_ids_are_the_first_vertex_at_each_position() {
        let mut r = crate::rng::SplitMix::new(11);
        for n in [0, 1, 7, 1000, 70_000] {
            let mut s = Scene::default();
            let distinct = (n / 3).max(1);
            for _ in 0..n {
                let k = (r.next_u64() % distinct as u64) as f64;
                let p = match r.next_u64() % 50 {
                    0 => DVec3::new(0.0, -0.0, k),
                    1 => DVec3::new(-0.0, 0.0, k),
                    2 => DVec3::new(f64::NAN, 1.0, 2.0),
                    _ => DVec3::new(k, k * 0.5, -k),
                };
                s.vertices.push(p);
            }
            let got = canonical_vertices(&s);
            assert_eq!(got, first_at_each_position(&s), "{n} vertices");
            if n >= 1000 {
                assert!(
                    got.iter()
                        .enumerate()
                        .filter(|&(v, &c)| c != v as u32)
                        .count()
                        > n / 2
                );
            }
        }
    }

    /// Whether each face has a later copy (same canonical corners in the same cyclic
    /// order) that is opaque and culled alike: every later face compared.
    fn hidden_by_comparing_all(scene: &Scene, canon: &[u32], culled: &[bool]) -> Vec<bool> {
        let corners = |i: usize| -> Vec<u32> {
            scene.faces[i]
                .vertices
                .iter()
                .map(|&v| canon[v as usize])
                .collect()
        };
        let same_cycle = |a: &[u32], b: &[u32]| {
            a.len() == b.len()
                && (0..a.len()).any(|r| (0..a.len()).all(|k| a[(k + r) % a.len()] == b[k]))
        };
        (0..scene.faces.len())
            .map(|i| {
                let (fi, ci) = (&scene.faces[i], corners(i));
                (i + 1..scene.faces.len()).any(|j| {
                    let fj = &scene.faces[j];
                    culled[fi.object as usize] == culled[fj.object as usize]
                        && scene.materials[fj.material as usize].is_opaque()
                        && same_cycle(&corners(j), &ci)
                })
            })
            .collect()
    }

    /// Random faces over few positions (many copies, turned, reversed, of other objects
    /// and materials, some translucent), two vertices at each position.
    #[test]
    fn copies_are_found_as_by_comparing_every_pair() {
        use limn_scene::{Face, Material};
        let mut r = crate::rng::SplitMix::new(3);
        for round in 0..40 {
            let mut s = Scene::default();
            let mut glass = Material::diffuse("glass", [0.5; 3]);
            glass.opacity = 0.5;
            s.add_material(Material::diffuse("paint", [0.5; 3]));
            s.add_material(glass);
            s.add_object("a");
            s.add_object("b");
            let positions = 4 + round % 5;
            for k in 0..2 * positions {
                s.vertices
                    .push(DVec3::new((k % positions) as f64, 0.0, 1.0));
            }
            for _ in 0..60 {
                let m = 3 + (r.next_u64() % 2) as usize;
                // Distinct positions (a face through one position twice has no single
                // starting corner), either vertex at each.
                let mut vertices: Vec<u32> = Vec::new();
                while vertices.len() < m {
                    let p = (r.next_u64() % positions as u64) as u32;
                    if !vertices.iter().any(|&v| v % positions as u32 == p) {
                        vertices.push(p + positions as u32 * (r.next_u64() % 2) as u32);
                    }
                }
                s.faces.push(Face {
                    vertices: vertices.into(),
                    material: u32::from(r.next_u64().is_multiple_of(5)),
                    object: (r.next_u64() % 2) as u32,
                    normals: None,
                    texcoords: None,
                    colors: None,
                });
            }
            let canon = canonical_vertices(&s);
            for culled in [[false, false], [true, false], [true, true]] {
                let got = hidden_by_later_copies(&s, &canon, &culled);
                assert_eq!(
                    got,
                    hidden_by_comparing_all(&s, &canon, &culled),
                    "round {round}"
                );
                if round == 0 {
                    assert!(got.iter().any(|&h| h) && got.iter().any(|&h| !h));
                }
            }
        }
    }
}
