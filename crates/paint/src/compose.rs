//! From ordered fragments to a paintable [`Picture`]: flat or Gouraud shading per face
//! (only the effects the scene asks for), opacity, object names, outlines, whole-face
//! covers and seam flaps.

use std::collections::HashMap;

use glam::DVec3;
use limn_scene::{shade_face, shade_face_in_shadow, FaceTexcoords, Scene, Shading};

use limn_depthsort::{Fragment, Ordered};
use rayon::prelude::*;

use crate::covers::{covers, repeats_of_covers};
use crate::face_outlines::translucent_outlines;
use crate::phong::DEFAULT_TOLERANCE;
use crate::seams::{seam_flaps_indexed, FlapJoin};
use crate::smooth::{FaceLight, View};
use crate::texturing::{FaceTexture, Projector, TextureTable};
use crate::{narrow_color, wide_color, Outline, PaintFragment, Picture};

/// How to turn an order into a picture.
#[derive(Debug, Clone, PartialEq)]
pub struct Style {
    /// Page background (RGBA); `None` = transparent. Default: `None`.
    pub background: Option<[f64; 4]>,
    /// Outline original model edges with this style; `None` = no outlines. Default:
    /// `None`.
    pub outline: Option<Outline>,
    /// Paint the first piece of a split opaque polygon as the whole polygon, so that the
    /// cuts leave no anti-aliasing seams (the picture is otherwise the same; see
    /// [`covers`]). Default: `true`.
    pub seamless: bool,
    /// Smooth shading for lit faces with vertex normals, as the scene asks
    /// ([`Scene::shading`], see [`Shading::of_face`]): Gouraud (colours computed at the
    /// fragment's vertices, normals interpolated over the input face, interpolated by
    /// the painter) or Phong (the fragment split into Gouraud triangles within
    /// [`Style::tolerance`] of per-point shading). `false` draws every face flat.
    /// Default: `true`.
    pub smooth: bool,
    /// Phong shading: the largest difference per channel (colours in [0, 1]) between
    /// the painted Gouraud triangles and per-point shading; must be > 0. Default 1/255.
    pub tolerance: f64,
    /// Width in pixels of the seam flaps (see [`crate::seam_flaps`]); 0 = none. Default:
    /// 1 px (a pixel the shared edge crosses reaches up to √2 px beyond it: flaps of
    /// 0.5 px left 0.5 % of a shaded sphere's pixels 12 levels or more too light in
    /// Chromium, flaps of 1 px 0.2 %, as wider ones).
    pub seams: f64,
}

impl Default for Style {
    fn default() -> Self {
        Style {
            background: None,
            outline: None,
            seamless: true,
            smooth: true,
            tolerance: DEFAULT_TOLERANCE,
            seams: 1.0,
        }
    }
}

impl Style {
    /// How seam flaps are painted: joined into their fragments' outlines, unless
    /// outline strokes need every original edge.
    pub fn flap_join(&self) -> FlapJoin {
        if self.outline.is_some() {
            FlapJoin::Separate
        } else {
            FlapJoin::Joined
        }
    }
}

/// Builds the picture of `ordered` (which must come from `scene`). Each face is shaded
/// once (flat, at its centroid, from the eye actually used); `illum 0` materials keep
/// exactly their `Kd`.
///
/// Textured faces (texture coordinates and a textured material) are shaded as the
/// others (flat, Gouraud or Phong, vertex colours as a tint) and their fragments carry a
/// [`crate::TextureMap`]: the texture's colour multiplies the lit colour at each point
/// (as OpenGL's modulate: for `illum 0` exactly `Kd` times the texture).
pub fn picture(scene: &Scene, ordered: &Ordered, style: &Style) -> Picture {
    let cam = &ordered.camera;
    let fills = face_fills(scene, ordered);
    let cover = covers(scene, ordered);
    let view = View {
        camera: cam,
        vp: cam.view_projection(ordered.near, ordered.far),
        tolerance: style.tolerance,
    };
    let fill_of = |f: &Fragment| match fills[f.face as usize] {
        Some(fill) if f.shadowed.is_empty() => fill,
        _ => {
            let c = shade_face_in_shadow(scene, f.face, cam.eye, f.shadowed);
            [c[0], c[1], c[2], opacity(scene, f.face)]
        }
    };
    // Textures cost nothing unless some material has one.
    let any_texture = scene.materials.iter().any(|m| m.texture.is_some());
    let mut textures = TextureTable::default();
    let fragments = if any_texture {
        // Texture indices are given in order of first use: one fragment after another.
        let mut fragments = Vec::with_capacity(ordered.fragments.len());
        let mut face_textures: HashMap<u32, Option<FaceTexture>> = HashMap::new();
        let projector = Projector {
            camera: cam,
            vp: view.vp,
        };
        for (f, cover) in ordered.fragments.iter().zip(&cover) {
            let fill = fill_of(f);
            let tex = face_textures.entry(f.face).or_insert_with(|| {
                let ft = FaceTexcoords::new(scene, f.face)?;
                Some(FaceTexture::new(&ft, &mut textures, &projector))
            });
            match tex {
                Some(tex) => {
                    let (frag, use_cover) = flat_fragment(scene, style, f, cover.as_ref(), fill);
                    let world = world_of(scene, f, use_cover);
                    if one_fill(scene, style, f.face) {
                        tex.apply(frag, &world, &projector, &mut |frag, _, _| {
                            fragments.push(frag)
                        });
                    } else {
                        // Lit smoothly (or vertex-coloured): each piece's lit colours,
                        // which the texture multiplies.
                        let light = FaceLight::new(scene, f.face).in_shadow_of(f.shadowed);
                        let shading = shading_of(scene, style, f.face);
                        tex.apply(frag, &world, &projector, &mut |frag, world, tint| {
                            let start = fragments.len();
                            shade_smooth(&light, shading, &view, frag, world, &mut fragments);
                            if tint != [1.0; 3] {
                                for p in &mut fragments[start..] {
                                    match &mut p.vertex_colors {
                                        Some(cs) => cs.iter_mut().for_each(|c| {
                                            let mut w = wide_color(*c);
                                            (0..3).for_each(|k| w[k] *= tint[k]);
                                            *c = narrow_color(w);
                                        }),
                                        None => (0..3).for_each(|k| p.fill[k] *= tint[k]),
                                    }
                                }
                            }
                        });
                    }
                }
                None => compose(scene, style, &view, f, cover.as_ref(), fill, &mut fragments),
            }
        }
        fragments
    } else {
        // Each fragment on its own, in parallel chunks joined in order. Pieces painted
        // again on their face's cover in the same flat opaque paint are left out (see
        // `repeats_of_covers`); with outlines they stay (their strokes are drawn over
        // the cover's).
        let repeat = repeats_of_covers(ordered, &cover);
        // Room for the seam flaps that stay fragments of their own, so that they are put
        // in without moving the fragments to fresh memory (see `seam_flaps_indexed`).
        let count = ordered.fragments.len();
        let mut fragments = Vec::with_capacity(count + count * FLAP_ROOM + 16);
        // A group of chunks at a time, each group's chunks moved into the picture before
        // the next is composed: the chunks of all the fragments held beside the picture
        // were a second copy of it in fresh pages.
        let group = FRAGMENTS_PER_TASK * CHUNKS_PER_GROUP;
        let mut done = 0;
        for ((frags, covers), repeats) in ordered
            .fragments
            .chunks(group)
            .zip(cover.chunks(group))
            .zip(repeat.chunks(group))
        {
            let chunks: Vec<Vec<PaintFragment>> = frags
                .par_chunks(FRAGMENTS_PER_TASK)
                .zip(covers.par_chunks(FRAGMENTS_PER_TASK))
                .zip(repeats.par_chunks(FRAGMENTS_PER_TASK))
                .map(|((frags, covers), repeats)| {
                    let mut out = Vec::with_capacity(frags.len());
                    for ((f, cover), &repeat) in frags.iter().zip(covers).zip(repeats) {
                        let fill = fill_of(f);
                        if repeat
                            && style.outline.is_none()
                            && style.seamless
                            && fill[3] >= 1.0
                            && one_fill(scene, style, f.face)
                        {
                            continue;
                        }
                        compose(scene, style, &view, f, cover.as_ref(), fill, &mut out);
                    }
                    out
                })
                .collect();
            // Where fragments compose to several (Phong pieces), room for as many more
            // as the fragments so far made, rather than doubling.
            done += frags.len();
            let made = fragments.len() + chunks.iter().map(Vec::len).sum::<usize>();
            let projected = made.saturating_mul(count) / done.max(1);
            let wanted = projected.max(made) + projected * FLAP_ROOM + 16;
            if wanted > fragments.capacity() {
                fragments.reserve_exact(wanted - fragments.len());
            }
            for chunk in chunks {
                fragments.extend(chunk);
            }
        }
        fragments
    };
    let fragments = if style.seams.is_finite() && style.seams > 0.0 {
        seam_flaps_indexed(fragments, style.seams, style.flap_join()).0
    } else {
        fragments
    };
    Picture {
        width: cam.width,
        height: cam.height,
        background: style.background,
        objects: scene.objects.iter().map(|o| o.name.clone()).collect(),
        fragments,
        outline: style.outline,
        seams: 0.0,
        marks: Vec::new(),
        textures: textures.list,
        // A face's pieces in one paint as one outline, in both orders.
        merge_pieces: true,
        face_outlines: translucent_outlines(scene, ordered),
        page_image: None,
    }
}

/// Places kept free per fragment for separate seam flaps, as many as their blocks make
/// room for (see `seam_flaps_indexed`; a smooth mesh has about one and a half per
/// triangle, the 300² height fields one per 1,500). Room never written is address space
/// only; one place per 64 fragments made a smooth mesh's flaps move the picture to a
/// new vector while the old one, the flaps and the new one were all held (the old one
/// was 62 MB of the peak on a million faces).
const FLAP_ROOM: usize = 2;

/// Parallel tasks composed before their fragments are moved into the picture.
const CHUNKS_PER_GROUP: usize = 64;

/// Fragments composed by one parallel task at least.
const FRAGMENTS_PER_TASK: usize = 1024;

/// A face's opacity, clamped to [0, 1].
fn opacity(scene: &Scene, face: u32) -> f64 {
    let face = &scene.faces[face as usize];
    scene.materials[face.material as usize]
        .opacity
        .clamp(0.0, 1.0)
}

/// Per face: its flat colour and opacity, shaded once (in parallel) for the faces that
/// have a fragment in no shadow; `None` for the others.
fn face_fills(scene: &Scene, ordered: &Ordered) -> Vec<Option<[f64; 4]>> {
    let mut wanted = vec![false; scene.faces.len()];
    for f in &ordered.fragments {
        if f.shadowed.is_empty() {
            wanted[f.face as usize] = true;
        }
    }
    let eye = ordered.camera.eye;
    wanted
        .par_iter()
        .enumerate()
        .with_min_len(FRAGMENTS_PER_TASK)
        .map(|(face, &wanted)| {
            wanted.then(|| {
                let c = shade_face(scene, face as u32, eye);
                [c[0], c[1], c[2], opacity(scene, face as u32)]
            })
        })
        .collect()
}

/// The flat paint fragment of `f` with `fill` (its whole face when it is an opaque
/// face's cover), and whether the cover was used.
fn flat_fragment(
    scene: &Scene,
    style: &Style,
    f: &Fragment,
    cover: Option<&Vec<[f64; 2]>>,
    fill: [f64; 4],
) -> (PaintFragment, bool) {
    let face = &scene.faces[f.face as usize];
    // An opaque face's first piece is painted as the whole polygon (see `covers`);
    // translucent faces (and those whose texture shows through) must not be painted
    // twice.
    let use_cover = fill[3] >= 1.0
        && scene.materials[face.material as usize].is_opaque()
        && style.seamless
        && cover.is_some();
    let (points, original_edges) = match cover {
        Some(c) if use_cover => (c.clone(), vec![true; c.len()]),
        _ => (f.points.clone(), f.original_edges.clone()),
    };
    let frag = PaintFragment {
        points,
        fill,
        vertex_colors: None,
        face: f.face,
        object: face.object,
        original_edges,
        texture: None,
        flap: false,
    };
    (frag, use_cover)
}

/// The world points of `f`'s paint fragment: its face's corners when painted as the
/// cover, else its own.
fn world_of(scene: &Scene, f: &Fragment, use_cover: bool) -> Vec<DVec3> {
    if use_cover {
        scene.faces[f.face as usize]
            .vertices
            .iter()
            .map(|&v| scene.vertices[v as usize])
            .collect()
    } else {
        f.world.clone()
    }
}

/// Pushes the paint fragments of `f` (not textured) onto `out`: one flat or Gouraud
/// fragment, or Phong's triangles.
/// How the fragments of `face` are shaded under `style`.
fn shading_of(scene: &Scene, style: &Style, face: u32) -> Shading {
    let face = &scene.faces[face as usize];
    if style.smooth {
        Shading::of_face(
            scene.shading,
            face,
            &scene.materials[face.material as usize],
        )
    } else {
        Shading::Flat
    }
}

/// Whether every fragment of `face` is painted in its one flat fill (flat shading and no
/// vertex colours).
fn one_fill(scene: &Scene, style: &Style, face: u32) -> bool {
    shading_of(scene, style, face) == Shading::Flat && scene.faces[face as usize].colors.is_none()
}

fn compose(
    scene: &Scene,
    style: &Style,
    view: &View<'_>,
    f: &Fragment,
    cover: Option<&Vec<[f64; 2]>>,
    fill: [f64; 4],
    out: &mut Vec<PaintFragment>,
) {
    let shading = shading_of(scene, style, f.face);
    let (frag, use_cover) = flat_fragment(scene, style, f, cover, fill);
    if one_fill(scene, style, f.face) {
        out.push(frag);
        return;
    }
    let world = world_of(scene, f, use_cover);
    let light = FaceLight::new(scene, f.face).in_shadow_of(f.shadowed);
    shade_smooth(&light, shading, view, frag, &world, out);
}

/// Pushes `frag` (with world corners `world`) lit by `light` under `shading` onto `out`:
/// one fragment with vertex colours (or one fill where they all agree), or Phong's
/// triangles; a texture map it carries stays on every part.
fn shade_smooth(
    light: &FaceLight<'_>,
    shading: Shading,
    view: &View<'_>,
    mut frag: PaintFragment,
    world: &[DVec3],
    out: &mut Vec<PaintFragment>,
) {
    let fill = frag.fill;
    if shading == Shading::Flat {
        // Vertex colours: the flat lighting times the colour at each corner.
        let colors = light.flat_vertex_colors(world, view.camera.eye, fill[3]);
        if colors.iter().all(|c| *c == colors[0]) {
            frag.fill = colors[0];
        } else {
            frag.vertex_colors = Some(colors.into_iter().map(narrow_color).collect());
        }
        out.push(frag);
        return;
    }
    if shading == Shading::Phong && world.len() == frag.points.len() {
        light.phong(&frag, world, view, out);
    } else {
        frag.vertex_colors = Some(light.vertex_colors(world, view.camera.eye, fill[3]));
        out.push(frag);
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;
    use limn_depthsort::{order, OrderOptions};
    use limn_scene::{shapes, Camera, Material, Scene, Shading};

    use super::*;

    /// An icosphere of 5,120 Gouraud-normalled triangles (a few translucent) beside a flat
    /// one, under `shading`.
    fn spheres(shading: Shading) -> Scene {
        let mut s = Scene::default();
        let m = s.add_material(Material::diffuse("lit", [0.7, 0.6, 0.5]));
        let mut glass = Material::diffuse("glass", [0.9, 0.9, 0.9]);
        glass.opacity = 0.5;
        let g = s.add_material(glass);
        let o = s.add_object("spheres");
        shapes::icosphere(&mut s, DVec3::ZERO, 1.0, 4, m, o).unwrap();
        shapes::icosphere(&mut s, DVec3::new(1.5, 0.2, 0.3), 0.6, 2, g, o).unwrap();
        for f in s.faces.iter_mut().step_by(3) {
            f.normals = None;
        }
        s.shading = Some(shading);
        s
    }

    #[test]
    fn a_split_flat_face_is_written_once_as_its_cover() {
        // An L-shaped hexagon (cut into two convex pieces) and, beside it, a square: the L's
        // pieces come one after another, the first painted as the whole L, the others
        // left out; with outlines every piece stays (its strokes go over the cover).
        let mut s = Scene::default();
        let m = s.add_material(Material::unlit("flat", [0.4, 0.5, 0.6]));
        let o = s.add_object("shapes");
        let l = [
            (0.0, 0.0),
            (2.0, 0.0),
            (2.0, 1.0),
            (1.0, 1.0),
            (1.0, 2.0),
            (0.0, 2.0),
        ];
        let corners: Vec<DVec3> = l.iter().map(|&(x, y)| DVec3::new(x, y, 0.0)).collect();
        s.add_polygon(&corners, m, o).unwrap();
        let square: Vec<DVec3> = [(3.0, 0.0), (4.0, 0.0), (4.0, 1.0), (3.0, 1.0)]
            .iter()
            .map(|&(x, y)| DVec3::new(x, y, 0.0))
            .collect();
        s.add_polygon(&square, m, o).unwrap();
        let camera = Camera::framing(&s, 320, 240).unwrap();
        let ordered = order(&s, &camera, &OrderOptions::default()).unwrap();
        let pieces = ordered.fragments.iter().filter(|f| f.face == 0).count();
        assert!(pieces > 1);
        let plain = Style {
            seams: 0.0,
            ..Style::default()
        };
        let of_l = |p: &Picture| {
            p.fragments
                .iter()
                .filter(|f| f.face == 0)
                .map(|f| f.points.len())
                .collect::<Vec<_>>()
        };
        assert_eq!(of_l(&picture(&s, &ordered, &plain)), vec![6]);
        let outlined = Style {
            outline: Some(crate::Outline {
                color: [0.0, 0.0, 0.0, 1.0],
                width: 1.0,
            }),
            ..plain
        };
        assert_eq!(of_l(&picture(&s, &ordered, &outlined)).len(), pieces);
    }

    #[test]
    fn the_picture_does_not_depend_on_the_number_of_threads() {
        for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
            let scene = spheres(shading);
            let camera = Camera::framing(&scene, 320, 240).unwrap();
            // Back faces kept: pieces enough for several parallel chunks.
            let opts = OrderOptions {
                cull: limn_depthsort::CullMode::Off,
                ..OrderOptions::default()
            };
            let ordered = order(&scene, &camera, &opts).unwrap();
            assert!(ordered.fragments.len() > 4 * FRAGMENTS_PER_TASK);
            let on = |threads: usize| {
                rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .unwrap()
                    .install(|| picture(&scene, &ordered, &Style::default()))
            };
            let one = on(1);
            assert!(one.fragments.len() >= ordered.fragments.len());
            assert_eq!(one, on(4), "{shading:?}");
        }
    }
}
