//! Textured faces: the projective map from the page to each face's texture, and the
//! split of a fragment of a larger face along its fan triangles (each fan triangle maps
//! its texture affinely in world space, so with a map of its own on the page). A fan
//! triangle whose texture coordinates collapse to a point or a segment is drawn as one
//! colour or as a strip (see `texture_collapse.rs`), never under a singular map.

use std::collections::HashMap;
use std::sync::Arc;

use glam::{DMat3, DMat4, DVec3};
use limn_scene::{polygon_normal, Camera, FaceTexcoords, Texture, TextureAlpha};

use crate::texture_bake::{bake, worth_baking};
use crate::texture_collapse::{classify, linear_part, max_step, stretch, Collapse, Strips};
use crate::texture_levels::{factors, Levels};
use crate::texture_patches::{Patches, REACH_PX};
use crate::{PaintFragment, TextureMap};

/// The textures of a picture, each once (by identity of the shared image), with the
/// strips made for collapsed texture coordinates.
#[derive(Default)]
pub(crate) struct TextureTable {
    index: HashMap<*const Texture, u32>,
    pub list: Vec<Arc<Texture>>,
    /// Per texture: the largest step between neighbouring texels.
    steps: HashMap<*const Texture, f64>,
    strips: Strips,
    levels: Levels,
    patches: Patches,
}

impl TextureTable {
    /// The largest step between neighbouring texels of `t` (computed once).
    fn step_of(&mut self, t: &Arc<Texture>) -> f64 {
        *self
            .steps
            .entry(Arc::as_ptr(t))
            .or_insert_with(|| max_step(t))
    }

    /// The index of `t`, added when new.
    pub fn index_of(&mut self, t: &Arc<Texture>) -> u32 {
        let key = Arc::as_ptr(t);
        if let Some(&i) = self.index.get(&key) {
            return i;
        }
        self.list.push(t.clone());
        let i = (self.list.len() - 1) as u32;
        self.index.insert(key, i);
        i
    }
}

/// What one fan triangle of a textured face paints.
#[derive(Debug, Clone, Copy, PartialEq)]
enum FanPaint {
    /// A texture (the face's, or a strip of it) under a projective map.
    Map(TextureMap),
    /// One colour and alpha, multiplying the fill: the texture's at the point its
    /// coordinates collapse to.
    Flat([f64; 4]),
    /// The flat fill alone: the map is undefined (the face seen edge-on).
    Fill,
}

impl FanPaint {
    /// `f` painted this way, and the colour its lit colours are multiplied by (the
    /// collapsed texture's, already applied to the fill; white otherwise).
    fn paint(self, mut f: PaintFragment) -> (PaintFragment, [f64; 3]) {
        match self {
            FanPaint::Map(m) => f.texture = Some(Box::new(m)),
            FanPaint::Flat(c) => {
                f.texture = None;
                for (v, c) in f.fill.iter_mut().zip(c) {
                    *v *= c;
                }
                return (f, [c[0], c[1], c[2]]);
            }
            FanPaint::Fill => f.texture = None,
        }
        (f, [1.0; 3])
    }
}

/// What receives each part of a textured fragment: the part, its world corners and the
/// colour its lit colours are multiplied by.
pub(crate) type Emit<'e> = dyn FnMut(PaintFragment, &[DVec3], [f64; 3]) + 'e;

/// One textured face seen by one camera: a paint per fan triangle.
pub(crate) struct FaceTexture {
    corners: Vec<DVec3>,
    normal: DVec3,
    maps: Vec<FanPaint>,
}

/// What the page projection needs: the camera and its view-projection matrix.
pub(crate) struct Projector<'a> {
    pub camera: &'a Camera,
    pub vp: DMat4,
}

impl Projector<'_> {
    fn project(&self, p: DVec3) -> [f64; 2] {
        let q = self.camera.project_with(&self.vp, p);
        [q.x, q.y]
    }
}

impl FaceTexture {
    /// The paints of `face`, its textures (and strips) entered in `table`.
    pub fn new(
        face: &FaceTexcoords,
        table: &mut TextureTable,
        view: &Projector<'_>,
    ) -> FaceTexture {
        let c = face.corners();
        let st = face.st();
        let tex = face.texture();
        let step = table.step_of(tex);
        let size = (tex.width(), tex.height());
        let maps = (1..c.len().saturating_sub(1))
            .map(|i| {
                let w = [c[0], c[i], c[i + 1]];
                let st = [st[0], st[i], st[i + 1]];
                let page = w.map(|p| view.project(p));
                let mut baked = false;
                let (texture, st) = match classify(st, page, size, step) {
                    Collapse::Area => {
                        // The texture averaged to what the page shows (see
                        // `texture_levels.rs`): texels per page pixel along s and t.
                        let texel =
                            st.map(|p| [p[0] * f64::from(size.0), p[1] * f64::from(size.1)]);
                        let per_px = linear_part(page, texel)
                            .map_or([f64::INFINITY; 2], |[a, b, c, d]| [a.hypot(b), c.hypot(d)]);
                        // A cut-out keeps its texels: each shows wholly or not.
                        let by = match tex.alpha() {
                            TextureAlpha::Mask => [1, 1],
                            _ => factors(per_px, size),
                        };
                        let level = table.levels.level(tex, by);
                        // Texels per page pixel, at most, to know how far flaps read.
                        let (lw, lh) = (f64::from(level.width()), f64::from(level.height()));
                        let texel = st.map(|p| [p[0] * lw, p[1] * lh]);
                        let reach = REACH_PX * stretch(page, texel);
                        let magnified = stretch(texel, page) > 1.0;
                        let (image, st) = match table.patches.patch(&level, st, reach, magnified) {
                            Some(patch) => patch,
                            None => (level, st),
                        };
                        let texel = st.map(|p| {
                            [
                                p[0] * f64::from(image.width()),
                                p[1] * f64::from(image.height()),
                            ]
                        });
                        // Page samples would move a cut-out's boundary off its texels.
                        baked = tex.alpha() != TextureAlpha::Mask
                            && linear_part(texel, page).is_some_and(|to_page| {
                                worth_baking(
                                    page,
                                    (image.width(), image.height()),
                                    to_page,
                                    REACH_PX,
                                )
                            });
                        (image, st)
                    }
                    Collapse::Point(p) => return FanPaint::Flat(tex.sample_rgba(p)),
                    Collapse::Band(band) => {
                        let strip = table.strips.strip(tex, &band);
                        let st = strip.corner_st(&band);
                        (strip.texture, st)
                    }
                };
                let Some(screen_to_st) = page_to_texture(w, st, view) else {
                    return FanPaint::Fill;
                };
                let mut map = TextureMap {
                    texture: 0,
                    screen_to_st,
                    alpha: texture.alpha(),
                };
                let page_samples = baked
                    .then(|| bake(&texture, &map, page, REACH_PX))
                    .flatten();
                if let Some((image, to_image)) = page_samples {
                    map.texture = table.index_of(&Arc::new(image));
                    map.screen_to_st = to_image;
                } else {
                    map.texture = table.index_of(&texture);
                }
                FanPaint::Map(map)
            })
            .collect();
        FaceTexture {
            corners: c.to_vec(),
            normal: polygon_normal(c),
            maps,
        }
    }

    /// Hands `template` (a fragment of the face with world corners `world`) with its
    /// texture map to `emit`, with its world corners and the colour its lit colours are
    /// to be multiplied by (a collapsed texture's; white otherwise): whole when the face
    /// is a triangle or the fragment lies in one fan triangle, else cut along the fan's
    /// diagonals. Pieces whose map is undefined (a face seen edge-on) keep the flat
    /// fill.
    pub fn apply(
        &self,
        template: PaintFragment,
        world: &[DVec3],
        view: &Projector<'_>,
        emit: &mut Emit<'_>,
    ) {
        if self.maps.len() == 1 || world.len() != template.points.len() {
            let paint = self.maps.first().copied().unwrap_or(FanPaint::Fill);
            let (frag, tint) = paint.paint(template);
            emit(frag, world, tint);
            return;
        }
        let start: Vec<Corner> = (0..world.len())
            .map(|i| Corner {
                world: world[i],
                screen: template.points[i],
                edge: template.original_edges.get(i).copied().unwrap_or(false),
            })
            .collect();
        let c = &self.corners;
        let n = c.len();
        for (k, map) in self.maps.iter().enumerate() {
            let i = k + 1;
            let mut poly = start.clone();
            // The wedge of fan triangle (0, i, i + 1): beyond diagonal 0→i towards
            // corner i + 1, and before diagonal 0→(i + 1) towards corner i.
            if i > 1 {
                poly = self.clip(&poly, c[i], c[i + 1], view);
            }
            if i + 1 < n - 1 {
                poly = self.clip(&poly, c[i + 1], c[i], view);
            }
            if poly.len() < 3 {
                continue;
            }
            let (frag, tint) = map.paint(PaintFragment {
                points: poly.iter().map(|v| v.screen).collect(),
                original_edges: poly.iter().map(|v| v.edge).collect(),
                ..template.clone()
            });
            let world: Vec<DVec3> = poly.iter().map(|v| v.world).collect();
            emit(frag, &world, tint);
        }
    }

    /// Keeps the part of `poly` on the side of the line from corner 0 through `through`
    /// (in the face's plane) where `towards` lies.
    fn clip(
        &self,
        poly: &[Corner],
        through: DVec3,
        towards: DVec3,
        view: &Projector<'_>,
    ) -> Vec<Corner> {
        let o = self.corners[0];
        let axis = through - o;
        let sign = axis.cross(towards - o).dot(self.normal).signum();
        let side = |p: DVec3| axis.cross(p - o).dot(self.normal) * sign;
        let mut out = Vec::with_capacity(poly.len() + 1);
        for k in 0..poly.len() {
            let (p, q) = (&poly[k], &poly[(k + 1) % poly.len()]);
            let (dp, dq) = (side(p.world), side(q.world));
            if dp >= 0.0 {
                out.push(p.clone());
            }
            if (dp > 0.0 && dq < 0.0) || (dp < 0.0 && dq > 0.0) {
                let t = dp / (dp - dq);
                let w = p.world + (q.world - p.world) * t;
                out.push(Corner {
                    world: w,
                    screen: view.project(w),
                    // Entering: the next edge runs on along p→q; leaving: along the cut.
                    edge: dp < 0.0 && p.edge,
                });
            }
        }
        out
    }
}

#[derive(Clone)]
struct Corner {
    world: DVec3,
    screen: [f64; 2],
    /// Whether the edge from this corner to the next is an original model edge.
    edge: bool,
}

/// The projective map from the page to texture coordinates of the world triangle `w`
/// with texture coordinates `st`, as the rows of `H` (scaled so that its largest entry
/// is 1); `None` when the triangle's plane projects to a line or the triangle is
/// degenerate.
///
/// A point of the triangle's plane is `A + α(B − A) + β(C − A)`; the view-projection
/// takes `(α, β, 1)` linearly to clip space, and the viewport to homogeneous page
/// coordinates: a 3 × 3 matrix `K`. The texture coordinates are affine in `(α, β)`: a
/// matrix `T`. Then `H = T · K⁻¹`.
pub(crate) fn page_to_texture(
    w: [DVec3; 3],
    st: [[f64; 2]; 3],
    view: &Projector<'_>,
) -> Option<[[f64; 3]; 3]> {
    let vp = &view.vp;
    let (width, height) = (f64::from(view.camera.width), f64::from(view.camera.height));
    let page =
        |c: glam::DVec4| DVec3::new(0.5 * width * (c.x + c.w), 0.5 * height * (c.w - c.y), c.w);
    let k = DMat3::from_cols(
        page(*vp * (w[1] - w[0]).extend(0.0)),
        page(*vp * (w[2] - w[0]).extend(0.0)),
        page(*vp * w[0].extend(1.0)),
    );
    let det = k.determinant();
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let t = DMat3::from_cols(
        DVec3::new(st[1][0] - st[0][0], st[1][1] - st[0][1], 0.0),
        DVec3::new(st[2][0] - st[0][0], st[2][1] - st[0][1], 0.0),
        DVec3::new(st[0][0], st[0][1], 1.0),
    );
    let h = t * k.inverse();
    let rows = [h.row(0), h.row(1), h.row(2)].map(|r| r.to_array());
    let big = rows.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    if big == 0.0 || !big.is_finite() {
        return None;
    }
    Some(rows.map(|r| r.map(|v| v / big)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_map_sends_projected_corners_to_their_coordinates() {
        let cam = Camera::new(DVec3::new(0.3, -2.0, 4.0), DVec3::ZERO, 200, 100);
        let view = Projector {
            camera: &cam,
            vp: cam.view_projection(0.1, 100.0),
        };
        let w = [
            DVec3::new(-1.0, 0.0, 0.0),
            DVec3::new(1.0, 0.2, -0.5),
            DVec3::new(0.0, 1.0, 0.3),
        ];
        let st = [[0.0, 0.0], [2.0, 0.5], [0.25, 1.0]];
        let h = page_to_texture(w, st, &view).unwrap();
        let map = TextureMap {
            texture: 0,
            screen_to_st: h,
            alpha: TextureAlpha::Opaque,
        };
        for i in 0..3 {
            let got = map.st_at(view.project(w[i])).unwrap();
            assert!((got[0] - st[i][0]).abs() < 1e-9 && (got[1] - st[i][1]).abs() < 1e-9);
        }
        // A world point inside: its texture coordinates by world barycentrics.
        let p = w[0] * 0.2 + w[1] * 0.3 + w[2] * 0.5;
        let want = [0, 1].map(|k| st[0][k] * 0.2 + st[1][k] * 0.3 + st[2][k] * 0.5);
        let got = map.st_at(view.project(p)).unwrap();
        assert!((got[0] - want[0]).abs() < 1e-9 && (got[1] - want[1]).abs() < 1e-9);
        // The screen midpoint of an edge is not the world midpoint (perspective).
        let (a, b) = (view.project(w[0]), view.project(w[1]));
        let mid = map
            .st_at([(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0])
            .unwrap();
        assert!((mid[0] - 1.0).abs() > 1e-3, "{mid:?}");
    }
}
