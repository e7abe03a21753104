//! Translucent parts painted after every opaque piece, so that a translucent face's
//! parts come one after another in the picture.
//!
//! A viewer blends each path on its own, so where two parts of one translucent face
//! meet, the pixels along their shared edge are blended with the page under both
//! (coverage conflation); writers paint a run of disjoint translucent fragments opaque
//! in one group and blend the group once, which closes those seams, but only for
//! fragments that follow one another. In painter's order a translucent face cutting
//! into an opaque object is interleaved with that object's pieces (its parts behind
//! them first, the parts in front after), so its parts fall into several groups, and
//! the PDF viewers draw the boundaries between groups as lines.
//!
//! So the pieces of translucent faces are first split exactly along what the opaque
//! faces the painter draws hide from the eye (the visible map's cut, applied to them
//! only: [`crate::hiding`]), and their hidden parts are dropped. Every part left is then
//! in front of every opaque piece it overlaps on the page, so painting all opaque
//! pieces first (in their order) and then the translucent parts (in theirs) paints
//! each point of the page with the same colours in the same order as before: the
//! picture is the same, and the parts of a translucent face are consecutive unless
//! another translucent face lies between them.
//!
//! It applies when the order is exact (the exact kernel, and an ordering other than
//! the simple sort, whose order is not; with `visible`, every order: the cut alone
//! decides) and some opaque piece is painted after a translucent one (otherwise nothing
//! would move, and nothing is cut). Only the opaque faces with a piece painted after
//! the first translucent piece can hide a part of one, so only their volumes are built.
//! When an opaque polygon cut by the near plane inside the view hides nothing in the
//! cut (see [`crate::hiding`]), the translucent parts behind it stay in their places.

use limn_scene::Scene;

use crate::options::{Arith, OrderOptions, SortMode};

/// When the translucent pieces of `scene` (pieces of faces `faces`, painted in
/// `order`) are cut along what opaque faces hide and painted last under `opts`: per
/// face, whether it may hide a part of a translucent piece (an opaque face with a piece
/// painted after the first translucent one: in an exact order, a face painted wholly
/// before a piece lies nowhere in front of it). `None` when nothing would move (no
/// opaque piece is painted after a translucent one), the order is not exact, or
/// [`OrderOptions::translucent_last`] is off.
///
/// Under `visible` the occluders are every opaque face (the visible map cuts every
/// piece); then only whether something would move is asked.
pub(crate) fn occluders(
    scene: &Scene,
    opts: &OrderOptions,
    faces: impl Fn(u32) -> u32,
    order: &[u32],
) -> Option<Vec<bool>> {
    let exact = opts.arith == Arith::Exact && (opts.visible || opts.sort != SortMode::Simple);
    if !exact || !opts.translucent_last {
        return None;
    }
    let opaque = |face: u32| {
        let f = &scene.faces[face as usize];
        scene.materials[f.material as usize].is_opaque()
    };
    let first = order.iter().position(|&id| !opaque(faces(id)))?;
    let mut hides = vec![false; scene.faces.len()];
    let mut any = false;
    for &id in &order[first..] {
        let face = faces(id);
        if opaque(face) {
            hides[face as usize] = true;
            any = true;
        }
    }
    any.then_some(hides)
}

/// `items` (each a piece's face and what goes with it, in paint order) with those of
/// opaque faces first and those of translucent faces after, each in its order.
pub(crate) fn opaque_first<T>(scene: &Scene, items: &mut [(u32, T)]) {
    let opaque = |face: u32| {
        let f = &scene.faces[face as usize];
        scene.materials[f.material as usize].is_opaque()
    };
    // A stable sort: the order within each kind stays.
    items.sort_by_key(|(face, _)| !opaque(*face));
}
