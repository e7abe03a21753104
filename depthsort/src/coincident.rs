//! Faces drawn over by an identical later face: the same corners (bit for bit) in the
//! same cyclic order. By the coplanar rule the later face wins everywhere the two
//! overlap, which is everywhere, so when it is opaque and culled alike the earlier face
//! cannot show. Dropping such faces before ordering keeps many copies of one mesh linear
//! instead of quadratic in the number of copies (every pair of copies overlaps).

use std::collections::HashMap;

use limn_scene::Scene;

/// Canonical vertex ids: vertices at the same position (bit for bit) share the id of one
/// of them.
pub(crate) fn canonical_vertices(scene: &Scene) -> Vec<u32> {
    let key = |v: usize| {
        let p = scene.vertices[v];
        [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()]
    };
    let mut by_pos: Vec<u32> = (0..scene.vertices.len() as u32).collect();
    by_pos.sort_unstable_by_key(|&v| key(v as usize));
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
    let mut hidden = vec![false; scene.faces.len()];
    // Key: the canonical corner ids rotated to start at the smallest. Value: whether an
    // opaque later copy was seen, per culling flag.
    let mut later: HashMap<Vec<u32>, [bool; 2]> = HashMap::new();
    let mut key = Vec::new();
    for (i, f) in scene.faces.iter().enumerate().rev() {
        key.clear();
        key.extend(f.vertices.iter().map(|&v| canon[v as usize]));
        let start = (0..key.len()).min_by_key(|&k| key[k]).unwrap_or(0);
        key.rotate_left(start);
        let cull = culled_object[f.object as usize] as usize;
        let opaque = scene.materials[f.material as usize].is_opaque();
        match later.get_mut(&key) {
            Some(seen) => {
                hidden[i] = seen[cull];
                seen[cull] |= opaque;
            }
            None => {
                let mut seen = [false; 2];
                seen[cull] = opaque;
                later.insert(key.clone(), seen);
            }
        }
    }
    hidden
}
