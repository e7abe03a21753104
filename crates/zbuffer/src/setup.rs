//! From a scene to screen-space triangles: culling, triangulation, clipping in
//! homogeneous clip space, projection.
//!
//! Clipping happens before the perspective divide against `w ≥ near` (for any camera but
//! a perspective one, against `−w ≤ z ≤ w` as OpenGL clips; the near plane of
//! `gluPerspective`: clip-space `w` is the distance in front of the eye along the view
//! axis), `w ≤ far`, and a guard band `|x|, |y| ≤ GUARD · w` (`GUARD` screen half-widths
//! around the picture), so nothing is ever projected through the eye and projected
//! coordinates stay moderate. A vertex created on an edge is computed from the edge's
//! endpoints in a canonical order, so two triangles sharing an edge get bit-identical
//! new vertices and stay watertight.

use glam::{DMat4, DVec3, DVec4};
use limn_scene::{polygon_normal, Camera, Scene, Viewpoint};

use crate::{RenderOptions, ZError, MAX_COORD};

/// Guard band half-size in units of the picture's half-size (NDC).
pub(crate) const GUARD: f64 = 64.0;

/// The camera and the planes actually used for a rendering.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Frame {
    pub camera: Camera,
    pub near: f64,
    pub far: f64,
    pub vp: DMat4,
    pub width: u32,
    pub height: u32,
    /// Near and far clipping by clip w (perspective); by clip z otherwise
    /// (`−w ≤ z ≤ w`, as OpenGL clips).
    pub depth_by_w: bool,
    /// The eye as the back-face test sees it.
    pub viewpoint: Viewpoint,
}

impl Frame {
    /// Validates the inputs and fixes the near and far planes.
    pub fn new(scene: &Scene, camera: &Camera, opts: &RenderOptions) -> Result<Frame, ZError> {
        camera.validate()?;
        if camera.width as u64 * camera.height as u64 > crate::MAX_PIXELS {
            return Err(ZError::TooManyPixels(camera.width, camera.height));
        }
        scene.validate()?;
        for (what, p) in [("eye", camera.eye), ("target", camera.target)] {
            check_coord(what, p)?;
        }
        for &v in &scene.vertices {
            check_coord("vertex", v)?;
        }
        let (near, far) = match opts.near_far {
            Some(nf) => nf,
            None => camera.near_far(scene),
        };
        if !(near > 0.0 && near < far && far.is_finite()) {
            return Err(ZError::BadDepthRange { near, far });
        }
        Ok(Frame {
            camera: *camera,
            near,
            far,
            vp: camera.view_projection(near, far),
            width: camera.width,
            height: camera.height,
            depth_by_w: camera.is_perspective(),
            viewpoint: camera.viewpoint()?,
        })
    }

    /// Clip coordinates of a world point (the product `project_with` uses).
    #[inline]
    pub fn clip(&self, p: DVec3) -> DVec4 {
        self.vp * p.extend(1.0)
    }

    /// Pixel coordinates and window depth of a clip-space point with `w > 0`, computed
    /// exactly as `Camera::project_with` does.
    #[inline]
    pub fn project(&self, c: DVec4) -> ScreenVert {
        let inv_w = 1.0 / c.w;
        let nx = c.x * inv_w;
        let ny = c.y * inv_w;
        ScreenVert {
            x: (nx + 1.0) * 0.5 * self.width as f64,
            y: (1.0 - ny) * 0.5 * self.height as f64,
            d: (c.z * inv_w + 1.0) * 0.5,
        }
    }

    /// Clip-plane outcode of a clip-space point (bit set = outside that plane).
    #[inline]
    fn outcode(&self, c: DVec4) -> u8 {
        let mut o = 0;
        for (k, plane) in PLANES.iter().enumerate() {
            let d = self.plane_dist(*plane, c);
            if d.is_nan() || d < 0.0 {
                o |= 1 << k;
            }
        }
        o
    }

    #[inline]
    fn plane_dist(&self, plane: Plane, c: DVec4) -> f64 {
        match plane {
            Plane::Near if self.depth_by_w => c.w - self.near,
            Plane::Far if self.depth_by_w => self.far - c.w,
            Plane::Near => c.w + c.z,
            Plane::Far => c.w - c.z,
            Plane::Left => c.x + GUARD * c.w,
            Plane::Right => GUARD * c.w - c.x,
            Plane::Bottom => c.y + GUARD * c.w,
            Plane::Top => GUARD * c.w - c.y,
        }
    }
}

fn check_coord(what: &'static str, p: DVec3) -> Result<(), ZError> {
    for v in p.to_array() {
        if v.is_nan() || v.abs() > MAX_COORD {
            return Err(ZError::OutOfRange { what, value: v });
        }
    }
    Ok(())
}

#[derive(Debug, Clone, Copy)]
enum Plane {
    Near,
    Far,
    Left,
    Right,
    Bottom,
    Top,
}

const PLANES: [Plane; 6] = [
    Plane::Near,
    Plane::Far,
    Plane::Left,
    Plane::Right,
    Plane::Bottom,
    Plane::Top,
];

/// A projected vertex: pixel coordinates (y down) and window depth in [0, 1].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ScreenVert {
    pub x: f64,
    pub y: f64,
    pub d: f64,
}

/// Screen-space triangles in face order (a face's triangles are consecutive).
#[derive(Debug, Default)]
pub(crate) struct Prepared {
    pub verts: Vec<ScreenVert>,
    pub tris: Vec<[u32; 3]>,
    /// Face id of each triangle.
    pub faces: Vec<u32>,
    /// Faces removed as back faces.
    pub culled_faces: usize,
    /// Triangles that needed clipping.
    pub clipped_tris: usize,
}

/// Kind of a polygon edge, kept through clipping for the edge band.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum EdgeKind {
    /// A diagonal added by triangulation (inside the face).
    Diagonal,
    /// Part of the face's outline.
    Boundary,
    /// Created by a clip plane.
    Clip,
}

/// Which back faces a method drops: those of every object, of none, of the objects a
/// [`crate::RenderOptions::cull_objects`] marks, or the faces a
/// [`crate::RenderOptions::cull_faces`] marks.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Culling<'a> {
    all: bool,
    objects: Option<&'a [bool]>,
    faces: Option<&'a [bool]>,
}

impl<'a> Culling<'a> {
    /// Nothing culled.
    pub(crate) const NONE: Culling<'static> = Culling {
        all: false,
        objects: None,
        faces: None,
    };

    /// What `opts` asks for.
    pub(crate) fn of(opts: &'a crate::RenderOptions) -> Culling<'a> {
        Culling {
            all: opts.cull_back_faces,
            objects: opts.cull_objects.as_deref(),
            faces: opts.cull_faces.as_deref(),
        }
    }

    /// Whether face `f` is dropped: its object's back faces are culled and it is one.
    pub(crate) fn drops(&self, scene: &Scene, f: usize, eye: Viewpoint) -> bool {
        let culls = match (self.faces, self.objects) {
            (Some(c), _) => c.get(f).copied().unwrap_or(false),
            (None, Some(c)) => c
                .get(scene.faces[f].object as usize)
                .copied()
                .unwrap_or(false),
            (None, None) => self.all,
        };
        culls && is_back_face(scene, f, eye)
    }
}

/// Whether the eye lies strictly behind the plane of face `f` (exact `orient3d` for
/// triangles; the sign of the Newell normal against the centroid for larger faces; for
/// an eye at infinity, the sign of the Newell normal dotted with its direction).
pub(crate) fn is_back_face(scene: &Scene, f: usize, eye: Viewpoint) -> bool {
    let vs = &scene.faces[f].vertices;
    let p = |k: usize| scene.vertices[vs[k] as usize];
    let eye = match eye {
        Viewpoint::At(e) => e,
        Viewpoint::Toward(d) => {
            let pts: Vec<DVec3> = (0..vs.len()).map(p).collect();
            return polygon_normal(&pts).dot(d) < 0.0;
        }
    };
    if vs.len() == 3 {
        // Positive when the eye is below the plane, i.e. on the side from which the
        // corners appear clockwise: behind the face (exact for every finite value).
        return crate::exact::orient3d_sign(p(0), p(1), p(2), eye) > 0;
    }
    let pts: Vec<DVec3> = (0..vs.len()).map(p).collect();
    let n = polygon_normal(&pts);
    let centre = pts.iter().copied().sum::<DVec3>() / pts.len() as f64;
    n.dot(eye - centre) < 0.0
}

/// The triangles of face `f` as scene vertex indices, with the kind of each edge
/// (edge `k` runs from corner `k` to corner `k + 1`): the kernel's triangles of the face
/// ([`limn_kernel::face_triangles`]), whose edges of the outline it names (corners
/// repeated in a row are skipped there, so adjacency in the corner list would not tell).
pub(crate) fn face_triangles(
    scene: &Scene,
    f: usize,
    scratch: &mut Vec<DVec3>,
    out: &mut Vec<([u32; 3], [EdgeKind; 3])>,
) {
    let vs = &scene.faces[f].vertices;
    if vs.len() == 3 {
        out.push(([vs[0], vs[1], vs[2]], [EdgeKind::Boundary; 3]));
        return;
    }
    scratch.clear();
    scratch.extend(vs.iter().map(|&v| scene.vertices[v as usize]));
    let Ok(tris) = limn_kernel::face_triangles(scratch) else {
        return;
    };
    let kind = |outline: bool| {
        if outline {
            EdgeKind::Boundary
        } else {
            EdgeKind::Diagonal
        }
    };
    for t in tris {
        out.push((t.corners.map(|i| vs[i]), t.outline.map(kind)));
    }
}

/// Clips a polygon of clip-space points (with the kind of the edge leaving each point)
/// against the planes in `mask`, Sutherland–Hodgman style.
fn clip_polygon(frame: &Frame, mask: u8, poly: &mut Vec<(DVec4, EdgeKind)>) {
    let mut next = Vec::with_capacity(poly.len() + 4);
    for (k, plane) in PLANES.iter().enumerate() {
        if mask & (1 << k) == 0 || poly.is_empty() {
            continue;
        }
        next.clear();
        let m = poly.len();
        for i in 0..m {
            let (s, ks) = poly[(i + m - 1) % m];
            let (e, ke) = poly[i];
            let ds = frame.plane_dist(*plane, s);
            let de = frame.plane_dist(*plane, e);
            if de >= 0.0 {
                if ds.is_nan() || ds < 0.0 {
                    next.push((intersect(s, ds, e, de), ks));
                }
                next.push((e, ke));
            } else if ds >= 0.0 {
                next.push((intersect(s, ds, e, de), EdgeKind::Clip));
            }
        }
        std::mem::swap(poly, &mut next);
    }
}

/// The point where the segment crosses the plane, computed from the endpoints in a
/// canonical order (so it does not depend on the direction the segment is walked).
fn intersect(a: DVec4, da: f64, b: DVec4, db: f64) -> DVec4 {
    let key = |v: DVec4| v.to_array().map(f64::to_bits);
    let (a, da, b, db) = if key(a) <= key(b) {
        (a, da, b, db)
    } else {
        (b, db, a, da)
    };
    let t = da / (da - db);
    a + (b - a) * t
}

/// What to collect while preparing.
pub(crate) enum Collect<'a> {
    /// Screen triangles.
    Triangles(&'a mut Prepared),
    /// Projected outline and clip edges, with their face.
    Edges(&'a mut Vec<(ScreenVert, ScreenVert, u32)>),
}

/// Culls, triangulates, clips and projects every face.
pub(crate) fn prepare(scene: &Scene, frame: &Frame, cull: Culling<'_>, mut collect: Collect<'_>) {
    let clip: Vec<DVec4> = scene.vertices.iter().map(|&p| frame.clip(p)).collect();
    let codes: Vec<u8> = clip.iter().map(|&c| frame.outcode(c)).collect();
    let mut projected: Vec<u32> = vec![u32::MAX; clip.len()];
    let mut scratch = Vec::new();
    let mut tris = Vec::new();
    let mut poly = Vec::new();
    for f in 0..scene.faces.len() {
        if cull.drops(scene, f, frame.viewpoint) {
            if let Collect::Triangles(p) = &mut collect {
                p.culled_faces += 1;
            }
            continue;
        }
        tris.clear();
        face_triangles(scene, f, &mut scratch, &mut tris);
        for &(t, kinds) in &tris {
            let c = t.map(|v| codes[v as usize]);
            if c[0] & c[1] & c[2] != 0 {
                continue; // entirely outside one plane
            }
            let mask = c[0] | c[1] | c[2];
            match &mut collect {
                Collect::Triangles(p) if mask == 0 => {
                    let idx = t.map(|v| {
                        let slot = &mut projected[v as usize];
                        if *slot == u32::MAX {
                            *slot = p.verts.len() as u32;
                            p.verts.push(frame.project(clip[v as usize]));
                        }
                        *slot
                    });
                    p.tris.push(idx);
                    p.faces.push(f as u32);
                }
                _ => {
                    poly.clear();
                    poly.extend((0..3).map(|k| (clip[t[k] as usize], kinds[k])));
                    clip_polygon(frame, mask, &mut poly);
                    emit(frame, f as u32, &poly, &mut collect);
                }
            }
        }
    }
}

fn emit(frame: &Frame, face: u32, poly: &[(DVec4, EdgeKind)], collect: &mut Collect<'_>) {
    if poly.len() < 3 || poly.iter().any(|(c, _)| !c.is_finite() || c.w <= 0.0) {
        return;
    }
    match collect {
        Collect::Triangles(p) => {
            p.clipped_tris += 1;
            let base = p.verts.len() as u32;
            p.verts.extend(poly.iter().map(|&(c, _)| frame.project(c)));
            for k in 1..poly.len() as u32 - 1 {
                p.tris.push([base, base + k, base + k + 1]);
                p.faces.push(face);
            }
        }
        Collect::Edges(out) => {
            let m = poly.len();
            for i in 0..m {
                if poly[i].1 != EdgeKind::Diagonal {
                    let a = frame.project(poly[i].0);
                    let b = frame.project(poly[(i + 1) % m].0);
                    out.push((a, b, face));
                }
            }
        }
    }
}
