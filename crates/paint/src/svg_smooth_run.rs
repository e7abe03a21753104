//! A run of smooth fragments of one face in SVG, painted without seams.
//!
//! Viewers anti-alias each path on its own, so where two paths meet, the pixels of their
//! shared edge are covered only in part by each and what lies under both shows through
//! (coverage conflation). A smooth fragment is drawn as pieces (`svg_smooth.rs`), so a
//! run has seams between its pieces and, along edges shared with faces painted later,
//! with those. Both are closed by overdraw inside one fill, never by moving an edge:
//!
//! - A seam flap of the run (see [`crate::seam_flaps`]: a polygon inside a fragment of
//!   another face painted later, carrying this face's colours along the shared edge)
//!   becomes a subpath of the piece that has the flap's shared edge as an edge of its
//!   own, in that piece's paint; piece and flap are then one fill with no edge between
//!   them, and the later fragment covers the flap exactly.
//! - Each piece gets a flap of its own into every piece of the run painted after it
//!   that shares one of its edges (end points equal): the part of the later piece within
//!   [`PIECE_FLAP_PX`] of the edge, kept only where exact orientation tests show the
//!   later piece fills all of it (`seams::flap`), as a subpath in the piece's paint.
//! - A run of two pieces or more is first filled whole (fragments and the flaps no
//!   piece took) in the mean colour, as one path: pixels of a seam that no flap closes
//!   (T-junctions between pieces split to different depths) show that colour, not what
//!   lies under the face.
//!
//! Every subpath of a path turns the same way, so the non-zero rule fills their union.
//! A translucent run of two pieces or more is drawn opaque inside a group with
//! `opacity`: the viewer composites the group once, so its seams are closed inside it
//! like an opaque run's and the face is blended once everywhere (a translucent face has
//! no seam flaps, so the group covers exactly its fragments).

use std::collections::BTreeMap;

use crate::merge;
use crate::number::{push_hex_color, push_milli, push_num, push_uint, rgb_u8};
use crate::runs::Frag;
use crate::seams::{edge_key, flap, EdgeKey};
use crate::svg_smooth::{self, Piece};
use crate::{wide_color, VertexColor};

/// Width in pixels of the flap a piece gets into a later piece of its run: a whole
/// pixel, so that the earlier piece and its flap cover every pixel of the shared edge.
const PIECE_FLAP_PX: f64 = 1.0;

/// Writes `run` (fragments with vertex colours and their seam flaps, all with opacity
/// `alpha` in thousandths; the fragments' interiors disjoint) with pieces within
/// `tolerance`, coordinates with `d` decimals and gradients numbered from
/// `*gradients`. Returns the number of paths.
///
/// With `merge` ([`crate::Picture::merge_pieces`]), a run whose fragments one paint
/// (flat or one gradient) shows within the tolerance is written as one path, the union
/// of its fragments and flaps (see `merge.rs`), in that paint: one outline, no seams
/// between its pieces, nothing to close.
pub(crate) fn write(
    b: &mut Vec<u8>,
    run: &[Frag<'_>],
    alpha: u16,
    tolerance: f64,
    d: u8,
    gradients: &mut u64,
    merge: bool,
) -> usize {
    // With `merge`, fragments and flaps that fill no point once written are left out.
    let kept: Vec<Frag<'_>>;
    let run = if merge {
        kept = run
            .iter()
            .filter(|f| !merge::fills_nothing(&f.points, d, |p| p))
            .cloned()
            .collect();
        &kept[..]
    } else {
        run
    };
    let (mut body, mut flaps): (Vec<&Frag<'_>>, Vec<&Frag<'_>>) =
        run.iter().partition(|f| !f.src.flap);
    if body.is_empty() {
        // Flaps with nothing to join: painted as fragments.
        std::mem::swap(&mut body, &mut flaps);
    }
    let body: Vec<(&Frag<'_>, &[VertexColor])> = body
        .into_iter()
        .filter_map(|f| f.colors.as_deref().map(|cs| (f, cs)))
        .collect();
    if body.is_empty() {
        return 0;
    }
    if merge && run.len() > 1 {
        let merged = common_paint(&body, tolerance)
            .and_then(|paint| Some((paint, merge::union(run, d, |p| p)?)));
        if let Some((paint, shapes)) = merged {
            if shapes.is_empty() {
                return 0;
            }
            write_flat_or_gradient(b, &paint, alpha, d, gradients, |b| {
                merge::push_svg_rings(b, shapes.iter().flatten(), d);
            });
            return 1;
        }
    }
    // Each fragment with its flaps: the run's seam flaps it holds an edge of, and its
    // own into the later fragments it shares an edge with.
    let outlines: Vec<&[[f64; 2]]> = body.iter().map(|(f, _)| &*f.points).collect();
    let edges = Edges::new(&outlines);
    let mut frag_extras: Vec<Vec<Vec<[f64; 2]>>> = vec![Vec::new(); body.len()];
    for f in &flaps {
        let k = edges.holder(&f.points).unwrap_or(0);
        frag_extras[k].push(f.points.to_vec());
    }
    let order: Vec<usize> = (0..body.len()).collect();
    edges.flaps(&outlines, &order, &mut frag_extras);
    // Each fragment is filled whole with its flaps in one paint, the pieces of those
    // drawn as two pieces or more then on top, each with its flaps into later pieces.
    let mut firsts = Vec::with_capacity(body.len());
    let mut pieces: Vec<Piece> = Vec::new();
    for (f, cs) in &body {
        let own = svg_smooth::pieces(&f.points, cs, tolerance);
        if own.len() == 1 {
            firsts.push(own[0]);
        } else {
            firsts.push(svg_smooth::fit(&f.points, cs));
            pieces.extend(own);
        }
    }
    let mut extras: Vec<Vec<Vec<[f64; 2]>>> = vec![Vec::new(); pieces.len()];
    if pieces.len() > 1 {
        let tris: Vec<[[f64; 2]; 3]> = pieces.iter().map(corners).collect();
        let outlines: Vec<&[[f64; 2]]> = tris.iter().map(|t| &t[..]).collect();
        Edges::new(&outlines).flaps(&outlines, &ranks(&pieces), &mut extras);
    }
    let mut paths = 0;
    let grouped = alpha < 1000 && (body.len() > 1 || !pieces.is_empty());
    if grouped {
        b.extend_from_slice(b"<g opacity=\"");
        push_milli(b, alpha);
        b.extend_from_slice(b"\">\n");
    }
    // Inside a group the fills are opaque: the group carries the opacity.
    let fill_alpha = if grouped { 1000 } else { alpha };
    for (k, (paint, (f, _))) in firsts.iter().zip(&body).enumerate() {
        let mut polygons: Vec<&[[f64; 2]]> = vec![&f.points];
        polygons.extend(frag_extras[k].iter().map(|e| &e[..]));
        write_path(b, paint, &polygons, fill_alpha, d, gradients);
        paths += 1;
    }
    paths += write_pieces(b, &pieces, &extras, fill_alpha, d, gradients);
    if grouped {
        b.extend_from_slice(b"</g>\n");
    }
    paths
}

/// The paint of the first fragment of `body`, when it is one piece (flat or one
/// gradient) and shows every other fragment within the tolerance of its pieces: at every
/// corner, and where its edges cross the ends of the gradient's ramp (between those the
/// difference of the padded ramp and a fragment's linear colours is linear, so it is
/// largest at those points).
fn common_paint(body: &[(&Frag<'_>, &[VertexColor])], tolerance: f64) -> Option<Piece> {
    let budget = 0.5 * tolerance;
    let (first, colors) = body[0];
    let own = svg_smooth::pieces(&first.points, colors, tolerance);
    let [paint] = own[..] else {
        return None;
    };
    if matches!(paint, Piece::Channels { .. }) {
        return None;
    }
    // The paint's colour at a point, and where the point lies along the ramp (unclamped).
    let at = |q: [f64; 2]| -> ([f64; 3], f64) {
        match paint {
            Piece::Flat { rgb, .. } => (rgb, 0.5),
            Piece::Gradient {
                from, to, c0, c1, ..
            } => {
                let v = [to[0] - from[0], to[1] - from[1]];
                let t = ((q[0] - from[0]) * v[0] + (q[1] - from[1]) * v[1])
                    / (v[0] * v[0] + v[1] * v[1]);
                let u = t.clamp(0.0, 1.0);
                ([0, 1, 2].map(|k| c0[k] + u * (c1[k] - c0[k])), t)
            }
            Piece::Channels { .. } => unreachable!("not a common paint"),
        }
    };
    let close = |q: [f64; 2], c: [f64; 3]| {
        let (p, _) = at(q);
        (0..3).all(|k| (p[k] - c[k].clamp(0.0, 1.0)).abs() <= budget)
    };
    for (f, cs) in &body[1..] {
        let n = f.points.len();
        for i in 0..n {
            let (a, ca) = (f.points[i], wide_color(cs[i]));
            if !close(a, [ca[0], ca[1], ca[2]]) {
                return None;
            }
            // Where edge a→b crosses an end of the ramp, its linear colour there.
            let (b, cb) = (f.points[(i + 1) % n], wide_color(cs[(i + 1) % n]));
            let (ta, tb) = (at(a).1, at(b).1);
            for end in [0.0, 1.0] {
                if (ta - end) * (tb - end) < 0.0 {
                    let s = (end - ta) / (tb - ta);
                    let q = [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])];
                    let c = [0, 1, 2].map(|k| ca[k] + s * (cb[k] - ca[k]));
                    if !close(q, c) {
                        return None;
                    }
                }
            }
        }
    }
    Some(paint)
}

/// The corners of a piece.
fn corners(p: &Piece) -> [[f64; 2]; 3] {
    p.tri()
}

/// The edges of polygons painted in order, sorted by key: the polygons that share an
/// edge are neighbours.
struct Edges {
    /// (edge key, polygon, edge index in the polygon), by key then polygon.
    sorted: Vec<(EdgeKey, u32, u32)>,
}

impl Edges {
    fn new(polygons: &[&[[f64; 2]]]) -> Self {
        let mut sorted = Vec::with_capacity(3 * polygons.len());
        for (i, p) in polygons.iter().enumerate() {
            let n = p.len();
            for e in 0..n {
                sorted.push((edge_key(p[e], p[(e + 1) % n]), i as u32, e as u32));
            }
        }
        sorted.sort_unstable();
        Edges { sorted }
    }

    /// The polygons having edge `k`, in order.
    fn with(&self, k: &EdgeKey) -> &[(EdgeKey, u32, u32)] {
        let lo = self.sorted.partition_point(|e| e.0 < *k);
        let hi = lo + self.sorted[lo..].partition_point(|e| e.0 == *k);
        &self.sorted[lo..hi]
    }

    /// The polygon one of whose edges is an edge of polygon `q` (the last, when several
    /// are).
    fn holder(&self, q: &[[f64; 2]]) -> Option<usize> {
        let m = q.len();
        (0..m)
            .filter_map(|k| self.with(&edge_key(q[k], q[(k + 1) % m])).last())
            .map(|e| e.1 as usize)
            .max()
    }

    /// Adds to `extras[i]` the flap of polygon `i` into the polygon sharing each of its
    /// edges that is painted next after it (of the least higher rank).
    fn flaps(&self, polygons: &[&[[f64; 2]]], rank: &[usize], extras: &mut [Vec<Vec<[f64; 2]>>]) {
        for group in self.sorted.chunk_by(|x, y| x.0 == y.0) {
            for &(_, i, e) in group {
                let later = group
                    .iter()
                    .filter(|x| rank[x.1 as usize] > rank[i as usize])
                    .min_by_key(|x| rank[x.1 as usize]);
                let Some(&(_, j, _)) = later else {
                    continue;
                };
                let p = polygons[i as usize];
                let (a, b) = (p[e as usize], p[(e as usize + 1) % p.len()]);
                if let Some(f) = flap(polygons[j as usize], a, b, PIECE_FLAP_PX) {
                    extras[i as usize].push(f);
                }
            }
        }
    }
}

/// Where each piece is painted, as [`write_pieces`] paints them: the gradients in
/// order, then one path per flat colour (pieces of one rank are one fill).
fn ranks(pieces: &[Piece]) -> Vec<usize> {
    let gradients = pieces
        .iter()
        .filter(|p| !matches!(p, Piece::Flat { .. }))
        .count();
    let colours: BTreeMap<[u8; 3], usize> = pieces
        .iter()
        .filter_map(|p| match *p {
            Piece::Flat { rgb, .. } => Some((rgb_u8(rgb), 0)),
            Piece::Gradient { .. } | Piece::Channels { .. } => None,
        })
        .collect();
    let colours: BTreeMap<[u8; 3], usize> = colours
        .into_keys()
        .enumerate()
        .map(|(k, c)| (c, gradients + k))
        .collect();
    let mut next = 0;
    pieces
        .iter()
        .map(|p| match *p {
            Piece::Flat { rgb, .. } => colours[&rgb_u8(rgb)],
            Piece::Gradient { .. } | Piece::Channels { .. } => {
                next += 1;
                next - 1
            }
        })
        .collect()
}

/// Writes the pieces, each with its flaps (`extras`) as subpaths: gradients in order,
/// then flat ones grouped by written colour into one path each (they tile their
/// fragments, so the order among them does not matter; a flap lies in a piece painted
/// later, which covers it). Returns the number of paths.
fn write_pieces(
    b: &mut Vec<u8>,
    pieces: &[Piece],
    extras: &[Vec<Vec<[f64; 2]>>],
    alpha: u16,
    d: u8,
    gradients: &mut u64,
) -> usize {
    let mut flat: BTreeMap<[u8; 3], Vec<usize>> = BTreeMap::new();
    let mut paths = 0;
    let tris: Vec<[[f64; 2]; 3]> = pieces.iter().map(corners).collect();
    let polygons = |i: usize| {
        let mut p: Vec<&[[f64; 2]]> = vec![&tris[i][..]];
        p.extend(extras[i].iter().map(|e| &e[..]));
        p
    };
    for (i, p) in pieces.iter().enumerate() {
        match *p {
            Piece::Flat { rgb, .. } => flat.entry(rgb_u8(rgb)).or_default().push(i),
            Piece::Gradient { .. } | Piece::Channels { .. } => {
                write_path(b, p, &polygons(i), alpha, d, gradients);
                paths += 1;
            }
        }
    }
    for members in flat.values() {
        let all: Vec<&[[f64; 2]]> = members.iter().flat_map(|&i| polygons(i)).collect();
        write_path(b, &pieces[members[0]], &all, alpha, d, gradients);
        paths += 1;
    }
    paths
}

/// Writes one path of `polygons` filled with `paint` (its triangle is not written; a
/// gradient is defined just before).
fn write_path(
    b: &mut Vec<u8>,
    paint: &Piece,
    polygons: &[&[[f64; 2]]],
    alpha: u16,
    d: u8,
    gradients: &mut u64,
) {
    if let Piece::Channels { ramps, .. } = *paint {
        write_channels(b, &ramps, polygons, alpha, d, gradients);
        return;
    }
    write_flat_or_gradient(b, paint, alpha, d, gradients, |b| {
        for p in polygons {
            push_polygon(b, p, d);
        }
    });
}

/// Writes one path filled with `paint` (flat or a gradient, written just before it),
/// its subpaths appended by `subpaths`.
fn write_flat_or_gradient(
    b: &mut Vec<u8>,
    paint: &Piece,
    alpha: u16,
    d: u8,
    gradients: &mut u64,
    subpaths: impl FnOnce(&mut Vec<u8>),
) {
    // A gradient whose two stops are written as one colour fills with that colour: it
    // is written as that flat fill (the same picture, without a gradient for the viewer
    // to set up; about a tenth of a Phong sphere's pieces).
    let flat;
    let paint = match *paint {
        Piece::Gradient { tri, c0, c1, .. } if rgb_u8(c0) == rgb_u8(c1) => {
            flat = Piece::Flat { tri, rgb: c0 };
            &flat
        }
        _ => paint,
    };
    if let Piece::Gradient {
        from, to, c0, c1, ..
    } = *paint
    {
        b.extend_from_slice(b"<linearGradient id=\"s");
        push_uint(b, *gradients);
        b.extend_from_slice(b"\" gradientUnits=\"userSpaceOnUse\" x1=\"");
        push_num(b, from[0], d + 1);
        b.extend_from_slice(b"\" y1=\"");
        push_num(b, from[1], d + 1);
        b.extend_from_slice(b"\" x2=\"");
        push_num(b, to[0], d + 1);
        b.extend_from_slice(b"\" y2=\"");
        push_num(b, to[1], d + 1);
        b.extend_from_slice(b"\"><stop stop-color=\"");
        push_hex_color(b, rgb_u8(c0));
        b.extend_from_slice(b"\"/><stop offset=\"1\" stop-color=\"");
        push_hex_color(b, rgb_u8(c1));
        b.extend_from_slice(b"\"/></linearGradient>\n");
    }
    b.extend_from_slice(b"<path d=\"");
    subpaths(b);
    match *paint {
        Piece::Gradient { .. } => {
            b.extend_from_slice(b"\" fill=\"url(#s");
            push_uint(b, *gradients);
            b.extend_from_slice(b")\"");
            *gradients += 1;
        }
        Piece::Flat { rgb, .. } => {
            b.extend_from_slice(b"\" fill=\"");
            push_hex_color(b, rgb_u8(rgb));
            b.push(b'"');
        }
        Piece::Channels { .. } => unreachable!("written by write_channels"),
    }
    opacity(b, alpha);
    b.extend_from_slice(b"/>\n");
}

/// Writes `polygons` filled with the sum of three channel ramps (see
/// [`crate::svg_smooth`]): an isolated group, clipped to the polygons (with the opacity,
/// when below 1), of one rectangle three times, the red ramp, then the green and blue
/// ones blended with `lighten`. The ramps fill a rectangle a pixel wider than the
/// polygons, so inside the clip every pixel is fully covered by all three and only the
/// clip is anti-aliased: three anti-aliased fills of the polygons themselves would each
/// blend their partial coverage at the edges, darkening them (a dark line along every
/// edge such a piece shares with another).
fn write_channels(
    b: &mut Vec<u8>,
    ramps: &[svg_smooth::Ramp; 3],
    polygons: &[&[[f64; 2]]],
    alpha: u16,
    d: u8,
    gradients: &mut u64,
) {
    let clip = *gradients;
    b.extend_from_slice(b"<clipPath id=\"c");
    push_uint(b, clip);
    b.extend_from_slice(b"\"><path d=\"");
    for p in polygons {
        push_polygon(b, p, d);
    }
    b.extend_from_slice(b"\"/></clipPath>\n<g clip-path=\"url(#c");
    push_uint(b, clip);
    b.extend_from_slice(b")\"");
    if alpha < 1000 {
        b.extend_from_slice(b" opacity=\"");
        push_milli(b, alpha);
        b.push(b'"');
    }
    b.extend_from_slice(b"><g style=\"isolation:isolate\">\n");
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for q in polygons.iter().flat_map(|p| p.iter()) {
        for k in 0..2 {
            lo[k] = lo[k].min(q[k]);
            hi[k] = hi[k].max(q[k]);
        }
    }
    let (x0, y0) = ((lo[0] - 1.0).floor(), (lo[1] - 1.0).floor());
    let (x1, y1) = ((hi[0] + 1.0).ceil(), (hi[1] + 1.0).ceil());
    for (k, r) in ramps.iter().enumerate() {
        let colour = |v: f64| {
            let mut c = [0.0; 3];
            c[k] = v;
            rgb_u8(c)
        };
        b.extend_from_slice(b"<linearGradient id=\"s");
        push_uint(b, *gradients);
        b.extend_from_slice(b"\" gradientUnits=\"userSpaceOnUse\" x1=\"");
        push_num(b, r.from[0], d + 1);
        b.extend_from_slice(b"\" y1=\"");
        push_num(b, r.from[1], d + 1);
        b.extend_from_slice(b"\" x2=\"");
        push_num(b, r.to[0], d + 1);
        b.extend_from_slice(b"\" y2=\"");
        push_num(b, r.to[1], d + 1);
        b.extend_from_slice(b"\"><stop stop-color=\"");
        push_hex_color(b, colour(r.v0));
        b.extend_from_slice(b"\"/><stop offset=\"1\" stop-color=\"");
        push_hex_color(b, colour(r.v1));
        b.extend_from_slice(b"\"/></linearGradient>\n<rect x=\"");
        push_num(b, x0, 0);
        b.extend_from_slice(b"\" y=\"");
        push_num(b, y0, 0);
        b.extend_from_slice(b"\" width=\"");
        push_num(b, x1 - x0, 0);
        b.extend_from_slice(b"\" height=\"");
        push_num(b, y1 - y0, 0);
        b.extend_from_slice(b"\" fill=\"url(#s");
        push_uint(b, *gradients);
        b.extend_from_slice(b")\"");
        if k > 0 {
            b.extend_from_slice(b" style=\"mix-blend-mode:lighten\"");
        }
        b.extend_from_slice(b"/>\n");
        *gradients += 1;
    }
    b.extend_from_slice(b"</g></g>\n");
}

/// ` fill-opacity="a"` when the opacity is below 1.
fn opacity(b: &mut Vec<u8>, milli: u16) {
    if milli < 1000 {
        b.extend_from_slice(b" fill-opacity=\"");
        push_milli(b, milli);
        b.push(b'"');
    }
}

/// Writes polygon `p` as a closed subpath turning clockwise on screen (so that every
/// subpath of a path turns the same way and the non-zero rule fills their union).
fn push_polygon(b: &mut Vec<u8>, p: &[[f64; 2]], d: u8) {
    let n = p.len();
    let area2: f64 = (0..n)
        .map(|i| {
            let (a, c) = (p[i], p[(i + 1) % n]);
            a[0] * c[1] - c[0] * a[1]
        })
        .sum();
    let reverse = area2 < 0.0;
    for k in 0..n {
        let q = p[if reverse { n - 1 - k } else { k }];
        b.push(match k {
            0 => b'M',
            1 => b'L',
            _ => b' ',
        });
        push_num(b, q[0], d);
        b.push(b' ');
        push_num(b, q[1], d);
    }
    b.push(b'Z');
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::runs::{check, walk};
    use crate::{narrow_color, PaintFragment, Picture};

    fn smooth(points: Vec<[f64; 2]>, colors: Vec<[f64; 4]>) -> PaintFragment {
        let mut f = PaintFragment::new(points, [0.5, 0.5, 0.5, 1.0]);
        f.vertex_colors = Some(colors.into_iter().map(narrow_color).collect());
        f
    }

    /// The SVG text of `fragments` as one run.
    fn written(fragments: Vec<PaintFragment>, alpha: u16) -> (String, usize) {
        let mut p = Picture::new(100, 100);
        p.fragments = fragments;
        let guard = check(&p).unwrap().guard;
        let mut out = (Vec::new(), 0);
        walk(
            &p,
            &guard,
            |_| (),
            |run, _| {
                let mut g = 0;
                out.1 += write(&mut out.0, run, alpha, 1.0 / 255.0, 2, &mut g, false);
                Ok(())
            },
        )
        .unwrap();
        (String::from_utf8(out.0).unwrap(), out.1)
    }

    const RAMP: [[f64; 4]; 3] = [
        [0.2, 0.2, 0.2, 1.0],
        [0.8, 0.8, 0.8, 1.0],
        [0.5, 0.5, 0.5, 1.0],
    ];

    /// Off one line by less than `CHANNELS_FROM`, more than the tolerance.
    const NEAR_RAMP: [[f64; 4]; 3] = [
        [0.2, 0.2, 0.2, 1.0],
        [0.8, 0.8, 0.8, 1.0],
        [0.5, 0.52, 0.5, 1.0],
    ];

    #[test]
    fn unrelated_colours_are_three_ramps_added_in_an_isolated_group() {
        let c = vec![
            [1.0, 0.0, 0.0, 0.5],
            [0.0, 1.0, 0.0, 0.5],
            [0.0, 0.0, 1.0, 0.5],
        ];
        let mut f = smooth(vec![[0.0, 0.0], [60.0, 0.0], [0.0, 60.0]], c);
        f.fill[3] = 0.5;
        let (svg, paths) = written(vec![f], 500);
        assert_eq!(paths, 1);
        // Clipped to the triangle, then the three ramps on one rectangle a pixel wider.
        assert!(svg.starts_with("<clipPath id=\"c0\"><path d=\"M"), "{svg}");
        assert!(
            svg.contains(
                "<g clip-path=\"url(#c0)\" opacity=\"0.5\"><g style=\"isolation:isolate\">\n"
            ),
            "{svg}"
        );
        assert_eq!(svg.matches("<path").count(), 1);
        assert_eq!(
            svg.matches("<rect x=\"-1\" y=\"-1\" width=\"62\" height=\"62\"")
                .count(),
            3,
            "{svg}"
        );
        assert_eq!(svg.matches("mix-blend-mode:lighten").count(), 2);
        // Red runs from the first corner (full) to the opposite edge (none).
        assert!(svg.contains("x1=\"30\" y1=\"30\" x2=\"0\" y2=\"0\"><stop stop-color=\"#000000\"/><stop offset=\"1\" stop-color=\"#ff0000\"/>"), "{svg}");
        assert!(!svg.contains("fill-opacity"));
    }

    #[test]
    fn a_flap_joins_a_single_gradient_in_one_path() {
        let tri = smooth(vec![[0.0, 0.0], [50.0, 0.0], [0.0, 50.0]], RAMP.to_vec());
        let mut fl = smooth(
            vec![[50.0, 0.0], [0.0, 50.0], [0.0, 50.5], [50.5, 0.0]],
            vec![RAMP[1], RAMP[2], RAMP[2], RAMP[1]],
        );
        fl.flap = true;
        let (svg, paths) = written(vec![tri, fl], 1000);
        assert_eq!(paths, 1, "{svg}");
        assert_eq!(svg.matches("<path").count(), 1);
        assert_eq!(svg.matches('M').count(), 2, "{svg}");
    }

    #[test]
    fn pieces_flap_into_later_pieces_turning_one_way() {
        // Corner colours a little off one line in RGB: split into pieces.
        let c = NEAR_RAMP.to_vec();
        let f = smooth(vec![[0.0, 0.0], [60.0, 0.0], [0.0, 60.0]], c);
        let pieces = svg_smooth::pieces(&f.points, f.vertex_colors.as_ref().unwrap(), 1.0 / 255.0);
        assert!(pieces.len() > 1);
        let mut extras = vec![Vec::new(); pieces.len()];
        let rank = ranks(&pieces);
        let tris: Vec<[[f64; 2]; 3]> = pieces.iter().map(corners).collect();
        let outlines: Vec<&[[f64; 2]]> = tris.iter().map(|t| &t[..]).collect();
        Edges::new(&outlines).flaps(&outlines, &rank, &mut extras);
        assert!(extras.iter().any(|e| !e.is_empty()));
        // Every flap lies in a piece painted later, so those painted last have none.
        let last = *rank.iter().max().unwrap();
        for (r, e) in rank.iter().zip(&extras) {
            assert!(*r < last || e.is_empty());
        }
        let (svg, paths) = written(vec![f], 1000);
        // The whole fragment first, in one gradient, then the pieces.
        assert!(
            svg.starts_with("<linearGradient id=\"s0\""),
            "{}",
            &svg[..80]
        );
        assert!(svg.contains("<path d=\"M0 0L60 0 0 60Z\" fill=\"url(#s0)\"/>"));
        assert_eq!(svg.matches("<path").count(), paths);
    }

    #[test]
    fn fragments_flap_into_later_fragments() {
        let a = smooth(vec![[0.0, 0.0], [50.0, 0.0], [0.0, 50.0]], RAMP.to_vec());
        let b = smooth(vec![[50.0, 0.0], [50.0, 50.0], [0.0, 50.0]], RAMP.to_vec());
        let (svg, paths) = written(vec![a, b], 1000);
        assert_eq!(paths, 2);
        // The first fragment and its flap into the second; the second alone.
        let fills: Vec<&str> = svg.lines().filter(|l| l.starts_with("<path")).collect();
        assert_eq!(fills[0].matches('M').count(), 2, "{svg}");
        assert_eq!(fills[1].matches('M').count(), 1, "{svg}");
    }

    #[test]
    fn a_translucent_run_of_pieces_is_one_group() {
        let c = NEAR_RAMP.map(|[r, g, b, _]| [r, g, b, 0.5]).to_vec();
        let mut f = smooth(vec![[0.0, 0.0], [60.0, 0.0], [0.0, 60.0]], c);
        f.fill[3] = 0.5;
        let (svg, _) = written(vec![f], 500);
        assert!(svg.starts_with("<g opacity=\"0.5\">\n"), "{}", &svg[..40]);
        assert!(svg.ends_with("</g>\n"));
        assert!(!svg.contains("fill-opacity"));
        // One gradient, translucent: no group.
        let mut g = smooth(vec![[0.0, 0.0], [50.0, 0.0], [0.0, 50.0]], RAMP.to_vec());
        g.fill[3] = 0.5;
        let (svg, paths) = written(vec![g], 500);
        assert_eq!(paths, 1);
        assert!(svg.contains("fill-opacity=\"0.5\"") && !svg.contains("<g"));
    }
}
