//! Whole-face covers: the first painted fragment of a split opaque face is painted as
//! the whole face, so the cuts between its pieces never show.

use limn_depthsort::Ordered;
use limn_scene::Scene;
use rayon::prelude::*;

/// Per fragment of `ordered` (which must come from `scene`), the projected outline of its
/// whole input face when the fragment is the first painted of a face that takes part
/// whole ([`Ordered::whole_faces`]) and was split or triangulated into several fragments;
/// `None` otherwise.
///
/// Painting the cover instead of the fragment gives the same picture for an opaque face:
/// every later piece is painted again, on top, at its own place in the order, and
/// whatever comes in between and overlaps a later piece lies behind it. The cut edges of
/// the later pieces then fall on the face's own colour: no seam.
pub fn covers(scene: &Scene, ordered: &Ordered) -> Vec<Option<Vec<[f64; 2]>>> {
    let faces = scene.faces.len();
    let mut per_face = vec![0u32; faces];
    for f in &ordered.fragments {
        if let Some(c) = per_face.get_mut(f.face as usize) {
            *c += 1;
        }
    }
    let cam = &ordered.camera;
    let vp = cam.view_projection(ordered.near, ordered.far);
    // Which fragments are first of their face in one pass; the outlines projected in
    // parallel.
    let mut covered = vec![false; faces];
    let first: Vec<bool> = ordered
        .fragments
        .iter()
        .map(|frag| {
            let f = frag.face as usize;
            let whole = ordered.whole_faces.get(f).copied().unwrap_or(false);
            whole && per_face[f] > 1 && !std::mem::replace(&mut covered[f], true)
        })
        .collect();
    ordered
        .fragments
        .par_iter()
        .zip(first)
        .with_min_len(FRAGMENTS_PER_TASK)
        .map(|(frag, first)| {
            first.then(|| {
                scene.faces[frag.face as usize]
                    .vertices
                    .iter()
                    .map(|&v| {
                        let p = cam.project_with(&vp, scene.vertices[v as usize]);
                        [p.x, p.y]
                    })
                    .collect()
            })
        })
        .collect()
}

/// Per fragment of `ordered`, whether it comes right after its face's cover (`cover`, from
/// [`covers`]) or after such a fragment, in the same shadows: a piece of the face painted
/// again, on the cover, in the same paint, with nothing between. A flat opaque piece so
/// placed changes no pixel and need not be written at all (its outline edges lie on the
/// cover's).
pub(crate) fn repeats_of_covers(ordered: &Ordered, cover: &[Option<Vec<[f64; 2]>>]) -> Vec<bool> {
    let frags = &ordered.fragments;
    let mut repeat = vec![false; frags.len()];
    for i in 1..frags.len() {
        let (prev, f) = (&frags[i - 1], &frags[i]);
        repeat[i] = f.face == prev.face
            && f.shadowed == prev.shadowed
            && (cover[i - 1].is_some() || repeat[i - 1]);
    }
    repeat
}

/// Fragments per parallel task of [`covers`].
const FRAGMENTS_PER_TASK: usize = 4096;
