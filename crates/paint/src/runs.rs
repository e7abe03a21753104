//! What every backend does before writing: check the picture, validate and clip each
//! fragment, and group consecutive fragments into runs painted as one path.

use std::borrow::Cow;

use super::{
    narrow_color, wide_color, Mark, Outline, PaintError, PaintFragment, Picture, VertexColor,
};

/// A valid fragment, clipped to the guard box.
#[derive(Clone)]
pub(crate) struct Frag<'a> {
    /// The fragment as given (face, object, fill).
    pub src: &'a PaintFragment,
    /// Corners, at least 3, all finite and inside the guard box.
    pub points: Cow<'a, [[f64; 2]]>,
    /// Original-edge flags; shorter than `points` means "false" for the rest.
    edges: Cow<'a, [bool]>,
    /// Per-vertex colours, same length as `points`.
    pub colors: Option<Cow<'a, [VertexColor]>>,
}

impl Frag<'_> {
    /// Is edge `i` (points[i] → points[i + 1 mod n]) an original model edge?
    pub fn edge(&self, i: usize) -> bool {
        self.edges.get(i).copied().unwrap_or(false)
    }

    /// Opacity in [0, 1].
    pub fn alpha(&self) -> f64 {
        self.src.fill[3].clamp(0.0, 1.0)
    }

    /// The single colour that stands for the fragment: the fill, or the mean of the
    /// vertex colours for a Gouraud fragment.
    pub fn flat_rgb(&self) -> [f64; 3] {
        match &self.colors {
            None => [self.src.fill[0], self.src.fill[1], self.src.fill[2]],
            Some(cs) => {
                let mut sum = [0.0; 3];
                for c in cs.iter() {
                    for k in 0..3 {
                        sum[k] += f64::from(c[k]);
                    }
                }
                let n = cs.len() as f64;
                [sum[0] / n, sum[1] / n, sum[2] / n]
            }
        }
    }

    /// Twice the signed area (positive when clockwise on screen, y down).
    pub fn area2(&self) -> f64 {
        let p = &self.points;
        let n = p.len();
        let mut s = 0.0;
        for i in 0..n {
            let a = p[i];
            let b = p[(i + 1) % n];
            s += a[0] * b[1] - b[0] * a[1];
        }
        s
    }

    /// The corners, in reverse order when `reverse`.
    pub fn oriented(&self, reverse: bool) -> impl Iterator<Item = [f64; 2]> + '_ {
        let n = self.points.len();
        (0..n).map(move |k| self.points[if reverse { n - 1 - k } else { k }])
    }

    /// Does any edge need outlining?
    pub fn has_outline(&self) -> bool {
        (0..self.points.len()).any(|i| self.edge(i))
    }

    /// Calls `f(start, edges, closed)` for every maximal chain of consecutive original
    /// edges: the chain runs through points `start, start+1, …, start+edges` (indices mod
    /// n). When every edge is original there is one chain with `closed = true` and
    /// `edges = n`.
    pub fn polylines(&self, mut f: impl FnMut(usize, usize, bool)) {
        let n = self.points.len();
        if (0..n).all(|i| self.edge(i)) {
            f(0, n, true);
            return;
        }
        for s in 0..n {
            if self.edge(s) && !self.edge((s + n - 1) % n) {
                let mut len = 0;
                while self.edge((s + len) % n) {
                    len += 1;
                }
                f(s, len, false);
            }
        }
    }
}

/// For each fragment of a run: must its corners be reversed so that all subpaths of the
/// run turn the same way (and the non-zero rule fills their union)?
pub(crate) fn reversals<'r>(run: &'r [Frag<'_>]) -> impl Iterator<Item = bool> + 'r {
    let first = if run.len() > 1 { run[0].area2() } else { 0.0 };
    run.iter()
        .enumerate()
        .map(move |(i, f)| i > 0 && f.area2() * first < 0.0)
}

/// A picture that passed [`check`].
pub(crate) struct Checked {
    /// The outline style, `None` when off or invisible (width 0 or opacity 0).
    pub outline: Option<Outline>,
    /// The clip box for fragments.
    pub guard: Guard,
}

impl Checked {
    /// How vector writers form runs: grouped by face unless outlines are drawn (see
    /// [`Runs::GroupedByFace`]).
    pub(crate) fn runs(&self) -> Runs {
        match self.outline {
            None => Runs::GroupedByFace,
            Some(_) => Runs::Consecutive,
        }
    }
}

/// Checks the picture-wide values every backend relies on.
pub(crate) fn check(picture: &Picture) -> Result<Checked, PaintError> {
    if picture.width == 0 || picture.height == 0 {
        return Err(PaintError::Size {
            width: picture.width,
            height: picture.height,
            reason: "width and height must be at least 1",
        });
    }
    if let Some(bg) = picture.background {
        if !bg.iter().all(|c| c.is_finite()) {
            return Err(PaintError::Style {
                what: "background",
                reason: "colour components must be finite",
            });
        }
    }
    let mut outline = None;
    if let Some(o) = picture.outline {
        if !o.color.iter().all(|c| c.is_finite()) {
            return Err(PaintError::Style {
                what: "outline",
                reason: "colour components must be finite",
            });
        }
        if !(o.width.is_finite() && o.width >= 0.0) {
            return Err(PaintError::Style {
                what: "outline",
                reason: "width must be finite and not negative",
            });
        }
        if o.width > 0.0 && o.color[3] > 0.0 {
            outline = Some(o);
        }
    }
    for f in &picture.fragments {
        if let Some(t) = &f.texture {
            if t.texture as usize >= picture.textures.len() {
                return Err(PaintError::Style {
                    what: "texture",
                    reason: "a fragment names a texture the picture does not have",
                });
            }
            if !t.screen_to_st.iter().flatten().all(|v| v.is_finite()) {
                return Err(PaintError::Style {
                    what: "texture",
                    reason: "texture maps must be finite",
                });
            }
        }
    }
    Ok(Checked {
        outline,
        guard: Guard::of_page(picture.width, picture.height, outline),
    })
}

impl Checked {
    /// The checked picture drawn `scale` times larger (supersampled): the outline's width
    /// and the guard box grown as the page, and the guard scaling each fragment's corners
    /// as it clips them (see [`Guard::clip`]), so that the picture need not be copied.
    pub(crate) fn scaled(self, picture: &Picture, scale: u32) -> Checked {
        let k = f64::from(scale);
        let outline = self.outline.map(|o| Outline {
            width: o.width * k,
            ..o
        });
        let mut guard = Guard::of_page(picture.width * scale, picture.height * scale, outline);
        guard.scale = k;
        Checked { outline, guard }
    }
}

/// Is the fragment paintable at all (see the module docs for the rule)?
pub(crate) fn is_valid(f: &PaintFragment) -> bool {
    let finite = |p: &[f64]| p.iter().all(|v| v.is_finite());
    f.points.len() >= 3
        && f.points.iter().all(|p| finite(p))
        && finite(&f.fill)
        && f.vertex_colors.as_ref().is_none_or(|cs| {
            cs.len() == f.points.len() && cs.iter().flatten().all(|c| c.is_finite())
        })
}

/// The box fragments are clipped to.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Guard {
    min: [f64; 2],
    max: [f64; 2],
    /// What fragments' corners are multiplied by before they are clipped (1 but for a
    /// supersampled page).
    scale: f64,
}

/// The result of clipping one fragment.
pub(crate) enum Clipped<'a> {
    /// Entirely inside: borrowed as is.
    Inside(Frag<'a>),
    /// Partly inside: a new polygon.
    Cut(Frag<'a>),
    /// Nothing left.
    Outside,
    /// Clipping overflowed f64.
    Overflow,
}

#[derive(Clone, Copy)]
struct V {
    p: [f64; 2],
    c: [f64; 4],
    /// Is the edge leaving this vertex original?
    e: bool,
}

impl Guard {
    /// The box of a page `width` × `height` with `outline`: the page grown on every side
    /// by its larger side and twice the outline's width.
    fn of_page(width: u32, height: u32, outline: Option<Outline>) -> Guard {
        let w = f64::from(width);
        let h = f64::from(height);
        let margin = w.max(h) + 2.0 * outline.map_or(0.0, |o| o.width);
        Guard {
            min: [-margin, -margin],
            max: [w + margin, h + margin],
            scale: 1.0,
        }
    }

    /// The box as (min, max) corners.
    pub(crate) fn bounds(&self) -> ([f64; 2], [f64; 2]) {
        (self.min, self.max)
    }

    /// Whether `p` lies in the box.
    pub(crate) fn contains(&self, p: [f64; 2]) -> bool {
        p[0] >= self.min[0] && p[0] <= self.max[0] && p[1] >= self.min[1] && p[1] <= self.max[1]
    }

    /// Clips a valid fragment to the box (its corners scaled by the guard's scale).
    pub fn clip<'a>(&self, f: &'a PaintFragment) -> Clipped<'a> {
        let points: Cow<'a, [[f64; 2]]> = if self.scale == 1.0 {
            Cow::Borrowed(&f.points)
        } else {
            let k = self.scale;
            let scaled: Vec<[f64; 2]> = f.points.iter().map(|p| [p[0] * k, p[1] * k]).collect();
            if !scaled.iter().flatten().all(|v| v.is_finite()) {
                return Clipped::Overflow;
            }
            Cow::Owned(scaled)
        };
        if points.iter().all(|&p| self.contains(p)) {
            return Clipped::Inside(Frag {
                src: f,
                points,
                edges: Cow::Borrowed(&f.original_edges),
                colors: f.vertex_colors.as_deref().map(Cow::Borrowed),
            });
        }
        let mut poly: Vec<V> = (0..points.len())
            .map(|i| V {
                p: points[i],
                c: f.vertex_colors
                    .as_ref()
                    .map_or(f.fill, |cs| wide_color(cs[i])),
                e: f.original_edges.get(i).copied().unwrap_or(false),
            })
            .collect();
        for axis in 0..2 {
            poly = clip_half(&poly, axis, self.min[axis], false);
            poly = clip_half(&poly, axis, self.max[axis], true);
        }
        if poly.len() < 3 {
            return Clipped::Outside;
        }
        if !poly
            .iter()
            .all(|v| v.p.iter().chain(&v.c).all(|x| x.is_finite()))
        {
            return Clipped::Overflow;
        }
        Clipped::Cut(Frag {
            src: f,
            points: Cow::Owned(poly.iter().map(|v| v.p).collect()),
            edges: Cow::Owned(poly.iter().map(|v| v.e).collect()),
            colors: f
                .vertex_colors
                .as_ref()
                .map(|_| Cow::Owned(poly.iter().map(|v| narrow_color(v.c)).collect())),
        })
    }
}

/// One Sutherland–Hodgman step: keeps the part with `p[axis] <= bound` (`upper`) or
/// `p[axis] >= bound`. Edge flags follow the edges; edges along the bound are not original.
fn clip_half(poly: &[V], axis: usize, bound: f64, upper: bool) -> Vec<V> {
    let inside = |v: &V| {
        if upper {
            v.p[axis] <= bound
        } else {
            v.p[axis] >= bound
        }
    };
    let n = poly.len();
    let mut out = Vec::with_capacity(n + 2);
    for i in 0..n {
        let a = poly[i];
        let b = poly[(i + 1) % n];
        match (inside(&a), inside(&b)) {
            (true, true) => out.push(a),
            (true, false) => {
                out.push(a);
                out.push(V {
                    e: false,
                    ..crossing(&a, &b, axis, bound)
                });
            }
            (false, true) => out.push(V {
                e: a.e,
                ..crossing(&a, &b, axis, bound)
            }),
            (false, false) => {}
        }
    }
    out
}

/// The point where segment a→b crosses `p[axis] = bound` (a and b on opposite sides).
fn crossing(a: &V, b: &V, axis: usize, bound: f64) -> V {
    // Halved so that differences of huge values cannot overflow.
    let t = (bound * 0.5 - a.p[axis] * 0.5) / (b.p[axis] * 0.5 - a.p[axis] * 0.5);
    let t = t.clamp(0.0, 1.0);
    let lerp = |x: f64, y: f64| x * (1.0 - t) + y * t;
    let mut p = [lerp(a.p[0], b.p[0]), lerp(a.p[1], b.p[1])];
    p[axis] = bound;
    V {
        p,
        c: [
            lerp(a.c[0], b.c[0]),
            lerp(a.c[1], b.c[1]),
            lerp(a.c[2], b.c[2]),
            lerp(a.c[3], b.c[3]),
        ],
        e: a.e,
    }
}

/// Fragment counts gathered while walking.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct Counts {
    pub skipped: usize,
    pub clipped: usize,
}

/// Validates and clips the fragments in order and hands each run — consecutive fragments
/// with the same object, face and `key` — to `run`, with the run's key. Marks are not
/// visited: for writers of fragments only.
#[cfg_attr(not(test), allow(dead_code))]
pub(crate) fn walk<'a, K: PartialEq>(
    picture: &'a Picture,
    guard: &Guard,
    key: impl FnMut(&Frag<'a>) -> K,
    run: impl FnMut(&[Frag<'a>], &K) -> Result<(), PaintError>,
) -> Result<Counts, PaintError> {
    walk_with_marks(picture, guard, Runs::Consecutive, key, run, |_| Ok(()))
}

/// How [`walk_with_marks`] forms runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Runs {
    /// Consecutive fragments of one object and face with the same key.
    Consecutive,
    /// In each stretch of consecutive fragments of one object and face, all those with
    /// the same key, at the place of the first of them: a face's lit pieces in one path
    /// and its shadowed pieces in another, whatever their order, so that no edge between
    /// two pieces of one colour is drawn twice (viewers anti-alias each path on its own:
    /// such an edge would let what lies beneath show through as a hairline). The picture
    /// stays the same: the pieces of a face do not overlap (they partition it); its
    /// first piece may be the whole face (a cover, see `covers.rs`), which stays first;
    /// seam flaps lie inside fragments of other faces, painted after the stretch. Not
    /// for pictures with outlines, whose strokes are drawn after each run's fill and so
    /// would overlap the fills of other runs in another order.
    GroupedByFace,
}

/// [`walk`], with runs formed as `runs` says, and hands every mark of [`Picture::marks`]
/// to `mark` at its paint position (see [`Picture`]): a run never spans a mark.
pub(crate) fn walk_with_marks<'a, K: PartialEq>(
    picture: &'a Picture,
    guard: &Guard,
    runs: Runs,
    mut key: impl FnMut(&Frag<'a>) -> K,
    mut run: impl FnMut(&[Frag<'a>], &K) -> Result<(), PaintError>,
    mut mark: impl FnMut(&'a Mark) -> Result<(), PaintError>,
) -> Result<Counts, PaintError> {
    let mut counts = Counts::default();
    // The stretch of fragments (and their keys) of the current object and face.
    let mut stretch = Stretch::default();
    let mut marks = picture.marks.iter().peekable();
    for (i, f) in picture.fragments.iter().enumerate() {
        if marks.peek().is_some_and(|m| m.before <= i) {
            stretch.flush(runs, &mut run)?;
            while let Some(m) = marks.next_if(|m| m.before <= i) {
                mark(m)?;
            }
        }
        if !is_valid(f) {
            counts.skipped += 1;
            continue;
        }
        let frag = match guard.clip(f) {
            Clipped::Inside(frag) => frag,
            Clipped::Cut(frag) => {
                counts.clipped += 1;
                frag
            }
            Clipped::Outside => {
                counts.clipped += 1;
                continue;
            }
            Clipped::Overflow => {
                counts.skipped += 1;
                continue;
            }
        };
        let k = key(&frag);
        if stretch.of != Some((f.object, f.face)) {
            stretch.flush(runs, &mut run)?;
            stretch.of = Some((f.object, f.face));
        }
        stretch.frags.push(frag);
        stretch.keys.push(k);
    }
    stretch.flush(runs, &mut run)?;
    for m in marks {
        mark(m)?;
    }
    Ok(counts)
}

/// Consecutive fragments of one object and face, with their keys.
struct Stretch<'a, K> {
    of: Option<(u32, u32)>,
    frags: Vec<Frag<'a>>,
    keys: Vec<K>,
}

impl<K> Default for Stretch<'_, K> {
    fn default() -> Self {
        Stretch {
            of: None,
            frags: Vec::new(),
            keys: Vec::new(),
        }
    }
}

impl<'a, K: PartialEq> Stretch<'a, K> {
    /// Hands the stretch's runs to `run` (see [`Runs`]) and empties it.
    fn flush(
        &mut self,
        runs: Runs,
        run: &mut impl FnMut(&[Frag<'a>], &K) -> Result<(), PaintError>,
    ) -> Result<(), PaintError> {
        let n = self.frags.len();
        // Where each run of equal keys starts.
        let starts: Vec<usize> = (0..n)
            .filter(|&i| i == 0 || self.keys[i] != self.keys[i - 1])
            .collect();
        if runs == Runs::Consecutive || starts.len() <= 1 {
            for (s, &start) in starts.iter().enumerate() {
                let end = starts.get(s + 1).copied().unwrap_or(n);
                run(&self.frags[start..end], &self.keys[start])?;
            }
        } else {
            // Per run, the first run with its key (a stretch has few keys: a face's
            // colours in and out of shadows).
            let mut firsts: Vec<usize> = Vec::new();
            let mut group_of = Vec::with_capacity(starts.len());
            for &start in &starts {
                let k = &self.keys[start];
                let g = match firsts.iter().position(|&f| self.keys[f] == *k) {
                    Some(g) => g,
                    None => {
                        firsts.push(start);
                        firsts.len() - 1
                    }
                };
                group_of.push(g);
            }
            let mut group = Vec::new();
            for (g, &first) in firsts.iter().enumerate() {
                group.clear();
                for (s, &start) in starts.iter().enumerate() {
                    if group_of[s] == g {
                        let end = starts.get(s + 1).copied().unwrap_or(n);
                        group.extend_from_slice(&self.frags[start..end]);
                    }
                }
                run(&group, &self.keys[first])?;
            }
        }
        self.frags.clear();
        self.keys.clear();
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frag(points: Vec<[f64; 2]>) -> PaintFragment {
        PaintFragment::new(points, [1.0, 0.0, 0.0, 1.0])
    }

    fn guard() -> Guard {
        check(&Picture::new(100, 50)).unwrap().guard
    }

    #[test]
    fn validity() {
        assert!(is_valid(&frag(vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])));
        assert!(!is_valid(&frag(vec![[0.0, 0.0], [1.0, 0.0]])));
        assert!(!is_valid(&frag(vec![
            [0.0, 0.0],
            [f64::NAN, 0.0],
            [0.0, 1.0]
        ])));
        let mut f = frag(vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        f.fill[3] = f64::INFINITY;
        assert!(!is_valid(&f));
        f.fill[3] = 1.0;
        f.vertex_colors = Some(vec![[0.0; 4]; 2]);
        assert!(!is_valid(&f));
        f.vertex_colors = Some(vec![[0.0; 4]; 3]);
        assert!(is_valid(&f));
    }

    #[test]
    fn clipping_keeps_original_edges_only_on_the_model() {
        // Guard box is [-100, 200] × [-100, 150].
        let f = frag(vec![[0.0, 0.0], [1e300, 0.0], [0.0, 10.0]]);
        let Clipped::Cut(c) = guard().clip(&f) else {
            panic!("expected a cut")
        };
        assert_eq!(
            &*c.points,
            &[[0.0, 0.0], [200.0, 0.0], [200.0, 10.0], [0.0, 10.0]]
        );
        // (0,0)→(200,0) lies on an original edge, (200,0)→(200,10) on the box.
        assert_eq!(&*c.edges, &[true, false, true, true]);
    }

    #[test]
    fn clipping_interpolates_colours_and_drops_outside() {
        let mut f = frag(vec![[-300.0, 0.0], [100.0, 0.0], [100.0, 10.0]]);
        f.vertex_colors = Some(vec![[0.0; 4], [1.0; 4], [1.0; 4]]);
        let Clipped::Cut(c) = guard().clip(&f) else {
            panic!("expected a cut")
        };
        let cs = c.colors.unwrap();
        assert_eq!(c.points[0], [-100.0, 0.0]);
        assert_eq!(cs[0], [0.5; 4]);
        let far = frag(vec![[1000.0, 0.0], [1001.0, 0.0], [1000.0, 1.0]]);
        assert!(matches!(guard().clip(&far), Clipped::Outside));
    }

    #[test]
    fn polylines_follow_original_edges() {
        let mut f = frag(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
        f.original_edges = vec![true, false, true, true];
        let Clipped::Inside(c) = guard().clip(&f) else {
            panic!()
        };
        let mut got = Vec::new();
        c.polylines(|s, n, closed| got.push((s, n, closed)));
        assert_eq!(got, vec![(2, 3, false)]);
        f.original_edges = vec![true; 4];
        let Clipped::Inside(c) = guard().clip(&f) else {
            panic!()
        };
        got.clear();
        c.polylines(|s, n, closed| got.push((s, n, closed)));
        assert_eq!(got, vec![(0, 4, true)]);
        f.original_edges = vec![false, true];
        let Clipped::Inside(c) = guard().clip(&f) else {
            panic!()
        };
        got.clear();
        c.polylines(|s, n, closed| got.push((s, n, closed)));
        assert_eq!(got, vec![(1, 1, false)]);
    }

    #[test]
    fn runs_group_same_face_and_style() {
        let mut p = Picture::new(10, 10);
        let tri = vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        for (face, object) in [(1, 0), (1, 0), (2, 0), (2, 1), (2, 1)] {
            let mut f = frag(tri.clone());
            f.face = face;
            f.object = object;
            p.fragments.push(f);
        }
        p.fragments.insert(1, frag(vec![[0.0, 0.0]]));
        let mut sizes = Vec::new();
        let counts = walk(
            &p,
            &guard(),
            |_| (),
            |run, _| {
                sizes.push(run.len());
                Ok(())
            },
        )
        .unwrap();
        assert_eq!(sizes, vec![2, 1, 2]);
        assert_eq!(counts.skipped, 1);
    }

    #[test]
    fn grouped_runs_gather_a_faces_pieces_by_colour() {
        // Face 1: lit, shadowed, lit, shadowed, lit; then face 2 (lit), then face 1
        // again (a new stretch: not joined to the first).
        let mut p = Picture::new(10, 10);
        let tri = vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        let (lit, dark) = ([1.0, 1.0, 1.0, 1.0], [0.5, 0.5, 0.5, 1.0]);
        for (k, (face, fill)) in [
            (1, lit),
            (1, dark),
            (1, lit),
            (1, lit),
            (1, dark),
            (2, lit),
            (1, dark),
        ]
        .into_iter()
        .enumerate()
        {
            let mut f = PaintFragment::new(tri.clone(), fill);
            f.face = face;
            // Tells the fragments apart.
            f.points[0][0] = k as f64;
            p.fragments.push(f);
        }
        let runs_of = |runs: Runs| {
            let mut got = Vec::new();
            walk_with_marks(
                &p,
                &guard(),
                runs,
                |f| f.src.fill[0] == 1.0,
                |run, _| {
                    got.push(run.iter().map(|f| f.points[0][0] as usize).collect());
                    Ok(())
                },
                |_| Ok(()),
            )
            .unwrap();
            got
        };
        let consecutive: Vec<Vec<usize>> = runs_of(Runs::Consecutive);
        assert_eq!(
            consecutive,
            vec![vec![0], vec![1], vec![2, 3], vec![4], vec![5], vec![6]]
        );
        let grouped: Vec<Vec<usize>> = runs_of(Runs::GroupedByFace);
        assert_eq!(grouped, vec![vec![0, 2, 3], vec![1, 4], vec![5], vec![6]]);
    }

    #[test]
    fn reversal_matches_the_first_orientation() {
        let mut p = Picture::new(10, 10);
        p.fragments
            .push(frag(vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]));
        p.fragments
            .push(frag(vec![[1.0, 0.0], [0.0, 1.0], [1.0, 1.0]]));
        let mut got = Vec::new();
        walk(
            &p,
            &guard(),
            |_| (),
            |run, _| {
                got.extend(reversals(run));
                Ok(())
            },
        )
        .unwrap();
        assert_eq!(got, vec![false, true]);
    }
}
