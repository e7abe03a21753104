//! Faces drawn over by an identical later face: the same corners (bit for bit) in the
//! same cyclic order. By the coplanar rule the later face wins everywhere the two
//! overlap, which is everywhere, so when it is opaque and culled alike the earlier face
//! cannot show. Dropping such faces before ordering keeps many copies of one mesh linear
//! instead of quadratic in the number of copies (every pair of copies overlaps).

use limn_scene::Scene;
use rayon::prelude::*;

/// Canonical vertex ids: vertices at the same position (bit for bit) share the id of one
/// of them.
pub(crate) fn canonical_vertices(scene: &Scene) -> Vec<u32> {
    let key = |v: usize| {
        let p = scene.vertices[v];
        [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()]
    };
    let mut by_pos: Vec<u32> = (0..scene.vertices.len() as u32).collect();
    by_pos.par_sort_unstable_by_key(|&v| (key(v as usize), v));
    let mut canon = vec![0u32; scene.vertices.len()];
    for (i, &v) in by_pos.iter().enumerate() {
        canon[v as usize] = if i > 0 && key(by_pos[i - 1] as usize) == key(v as usize) {
            canon[by_pos[i - 1] as usize]
        } else {
            v
        };
    }
    canon
}

/// Per face: whether a later face with the same corners in the same cyclic order, an
/// opaque material and the same culling (`culled_object`) draws over all of it.
pub(crate) fn hidden_by_later_copies(
    scene: &Scene,
    canon: &[u32],
    culled_object: &[bool],
) -> Vec<bool> {
    let n = scene.faces.len();
    let mut hidden = vec![false; n];
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
    // Faces grouped by key, each group in input order (a total order, so the result
    // does not depend on the sort or on threads).
    let mut by_key: Vec<u32> = (0..n as u32).collect();
    by_key.par_sort_unstable_by(|&a, &b| key(a).cmp(key(b)).then(a.cmp(&b)));
    let mut g = 0;
    while g < n {
        let mut e = g + 1;
        while e < n && key(by_key[e]) == key(by_key[g]) {
            e += 1;
        }
        // Whether an opaque later copy was seen, per culling flag.
        let mut seen = [false; 2];
        for &i in by_key[g..e].iter().rev() {
            let f = &scene.faces[i as usize];
            let cull = culled_object[f.object as usize] as usize;
            hidden[i as usize] = seen[cull];
            seen[cull] |= scene.materials[f.material as usize].is_opaque();
        }
        g = e;
    }
    hidden
}
