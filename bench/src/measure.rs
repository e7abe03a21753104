//! What the effect measurements share: median timings, the bytes a painter writes, and
//! the flat-only picture the effects machinery is measured against.

use std::time::Instant;

use limn_depthsort::Ordered;
use limn_paint::{covers, seam_flaps_indexed, PaintFragment, Painter, Picture, Style};
use limn_scene::{shade_face, Scene};

/// The median (upper middle) of `v`.
pub(crate) fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The median time of `runs` runs after one run to warm caches and the allocator.
pub(crate) fn time<T>(runs: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let _ = f();
    let mut times = Vec::with_capacity(runs);
    let mut last = None;
    for _ in 0..runs {
        let t = Instant::now();
        last = Some(f());
        times.push(t.elapsed().as_secs_f64() * 1e3);
    }
    (median(times), last.expect("at least one run"))
}

/// The bytes `painter` writes for `pic`.
pub(crate) fn write(painter: &dyn Painter, pic: &Picture) -> usize {
    let mut out = Vec::new();
    painter.paint(pic, &mut out).expect("in-memory writing");
    out.len()
}

/// The painter's flat-only picture as it was built before smooth effects: one flat
/// colour per face, covers, seam flaps. For an unlit scene it gives the same picture
/// as [`limn_paint::picture`]; the benchmark checks that.
pub(crate) fn flat_only_picture(scene: &Scene, ordered: &Ordered, style: &Style) -> Picture {
    let cam = &ordered.camera;
    let mut cache: Vec<Option<[f64; 4]>> = vec![None; scene.faces.len()];
    let cover = covers(scene, ordered);
    let mut fragments = Vec::with_capacity(ordered.fragments.len());
    for (f, cover) in ordered.fragments.iter().zip(&cover) {
        let face = &scene.faces[f.face as usize];
        let fill = *cache[f.face as usize].get_or_insert_with(|| {
            let m = &scene.materials[face.material as usize];
            let c = shade_face(scene, f.face, cam.eye);
            [c[0], c[1], c[2], m.opacity.clamp(0.0, 1.0)]
        });
        let use_cover = fill[3] >= 1.0 && style.seamless && cover.is_some();
        let (points, original_edges) = match cover {
            Some(c) if use_cover => (c.clone(), vec![true; c.len()]),
            _ => (f.points.clone(), f.original_edges.clone()),
        };
        fragments.push(PaintFragment {
            points,
            fill,
            vertex_colors: None,
            face: f.face,
            object: face.object,
            original_edges,
            texture: None,
            flap: false,
        });
    }
    Picture {
        width: cam.width,
        height: cam.height,
        background: style.background,
        objects: scene.objects.iter().map(|o| o.name.clone()).collect(),
        fragments: if style.seams.is_finite() && style.seams > 0.0 {
            seam_flaps_indexed(fragments, style.seams, style.flap_join()).0
        } else {
            fragments
        },
        outline: style.outline,
        seams: 0.0,
        marks: Vec::new(),
        textures: Vec::new(),
        // As `picture` composes it: a face's pieces in one paint as one outline.
        merge_pieces: true,
        // Translucent runs are layered by their fragments' own corners alone.
        face_outlines: Default::default(),
        page_image: None,
    }
}
