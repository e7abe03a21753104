//! How meshed each face is: the other faces it meets at its corners. A mesh's neighbours
//! touch, so their screen boxes meet without any gap to find between them; the adaptive
//! ordering discounts them when it judges how crowded a set is.

use limn_scene::Scene;
use rayon::prelude::*;

/// Per face of `scene`: the faces met at its corners, counted corner by corner (a
/// neighbour across an edge is met at both its ends, and so counted twice), through the
/// canonical vertex ids `canon` (one id per position); at most 255.
pub(crate) fn faces_met_at_corners(scene: &Scene, canon: &[u32]) -> Vec<u8> {
    // Corners at each position, every face's counted.
    let mut at = vec![0u32; scene.vertices.len()];
    for f in &scene.faces {
        for &v in &f.vertices {
            at[canon[v as usize] as usize] += 1;
        }
    }
    scene
        .faces
        .par_iter()
        .with_min_len(FACES_PER_TASK)
        .map(|f| {
            let others: u32 = f
                .vertices
                .iter()
                .map(|&v| at[canon[v as usize] as usize] - 1)
                .sum();
            others.min(u32::from(u8::MAX)) as u8
        })
        .collect()
}

/// Faces per parallel task of [`faces_met_at_corners`].
const FACES_PER_TASK: usize = 4096;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coincident::canonical_vertices;
    use glam::DVec3;
    use limn_scene::Material;

    #[test]
    fn a_grid_meets_its_neighbours_and_a_soup_nothing() {
        let mut s = Scene::default();
        let m = s.add_material(Material::diffuse("m", [0.5; 3]));
        let o = s.add_object("o");
        // A 3 × 3 grid of quads, each with corners of its own (shared by position only).
        for i in 0..3 {
            for j in 0..3 {
                let p = |a: usize, b: usize| DVec3::new(a as f64, b as f64, 0.0);
                let quad = [p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)];
                s.add_polygon(&quad, m, o).expect("a valid quad");
            }
        }
        let met = faces_met_at_corners(&s, &canonical_vertices(&s));
        // The middle quad meets 3 others at each corner; a corner quad 0, 1, 3 and 1.
        assert_eq!(met[4], 12);
        assert_eq!(met[0], 5);
        assert_eq!(
            met.iter().map(|&c| u32::from(c)).sum::<u32>(),
            4 * 5 + 4 * 8 + 12
        );
        let soup = crate::test_scenes::soup(50, 0.3, 3);
        let met = faces_met_at_corners(&soup, &canonical_vertices(&soup));
        assert!(met.iter().all(|&c| c == 0));
    }
}
