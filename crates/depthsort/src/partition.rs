//! Splitting a set of pieces by the plane of one of them (the BSP step), shared by the
//! BSP and adaptive orderings and by the sets split apart on every core.

use limn_kernel::Kernel;

use crate::occlusion::Rel;
use crate::pieces::Ctx;

/// How many pieces a splitter candidate is scored against, at most.
pub(crate) const SCORE_SAMPLE: usize = 512;

/// Picks a splitter among `candidates` random members of `set`: the one whose plane
/// crosses the fewest other members (scored on a deterministic sample of at most
/// [`SCORE_SAMPLE`] members), the first drawn of those on a tie, drawing no more once
/// one crosses none.
///
/// Each candidate is scored first by the classifications the kernel makes cheaply
/// ([`Ctx::rel_if_cheap`]), which bound its score from below and above; the members it
/// cannot place without exact evaluation (a corner within rounding of the plane: parts
/// of an assembly in contact, faces made coplanar and then moved by a transform) are
/// classified exactly only where the bounds cannot tell which candidate wins, so the
/// choice is the one exact scores make. Those exact evaluations were most of the
/// scoring's time on a CAD assembly (152,000 of its 932,000 classifications, a fifth of
/// the whole run's samples). A candidate drawn again (small sets) is not scored again.
///
/// When the sample is the whole set, the winner's classification of every member
/// comes back with it (in set order, `None` where it was not needed), for [`partition`]
/// to use instead of classifying again.
fn choose_splitter<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    set: &[u32],
    candidates: usize,
) -> (u32, Option<Vec<Option<Rel>>>) {
    let n = set.len();
    if n <= 2 || candidates <= 1 {
        return (set[(ctx.next_random() % n as u64) as usize], None);
    }
    let sample: Vec<u32> = if n <= SCORE_SAMPLE {
        set.to_vec()
    } else {
        (0..SCORE_SAMPLE)
            .map(|_| set[(ctx.next_random() % n as u64) as usize])
            .collect()
    };
    let whole = n <= SCORE_SAMPLE;
    let mut scored: Vec<Score> = Vec::with_capacity(candidates.min(n));
    let mut zero = None;
    for _ in 0..candidates.min(n) {
        let c = set[(ctx.next_random() % n as u64) as usize];
        // A candidate drawn again cannot beat the best, its own score or better.
        if scored.iter().any(|s| s.c == c) {
            continue;
        }
        let mut s = Score::cheap(ctx, &sample, c);
        // Whether it crosses none decides whether more are drawn.
        if s.lo == 0 && s.resolve(ctx, &sample, 1) {
            zero = Some(s);
            break;
        }
        scored.push(s);
    }
    let winner = match zero {
        Some(s) => s,
        None => {
            // A candidate whose least score exceeds another's greatest cannot win.
            let least_greatest = scored.iter().map(|s| s.lo + s.open).min();
            let least_greatest = least_greatest.unwrap_or(usize::MAX);
            scored.retain(|s| s.lo <= least_greatest);
            if scored.len() > 1 {
                let mut best = usize::MAX;
                let mut at = 0;
                for (k, s) in scored.iter_mut().enumerate() {
                    if s.lo < best && s.resolve(ctx, &sample, best) {
                        best = s.lo;
                        at = k;
                    }
                }
                scored.swap_remove(at)
            } else {
                scored.pop().expect("at least one candidate is drawn")
            }
        }
    };
    (winner.c, whole.then_some(winner.rels))
}

/// A splitter candidate's score on a sample: the members known to span its plane
/// (`lo`), and those not yet classified (`open`, their relations `None`).
struct Score {
    c: u32,
    rels: Vec<Option<Rel>>,
    lo: usize,
    open: usize,
}

impl Score {
    /// The classifications of `sample` against the plane of `c` that come cheaply
    /// (`c` itself coplanar).
    fn cheap<K: Kernel>(ctx: &Ctx<'_, K>, sample: &[u32], c: u32) -> Score {
        let rels: Vec<Option<Rel>> = sample
            .iter()
            .map(|&q| {
                if q == c {
                    Some(Rel::Coplanar)
                } else {
                    ctx.rel_if_cheap(q, c)
                }
            })
            .collect();
        let lo = rels.iter().filter(|r| **r == Some(Rel::Span)).count();
        let open = rels.iter().filter(|r| r.is_none()).count();
        Score { c, rels, lo, open }
    }

    /// Classifies the open members exactly, in sample order, while the count of
    /// spanning members stays below `bound`: whether it did to the end (then `lo` is
    /// the exact score).
    fn resolve<K: Kernel>(&mut self, ctx: &Ctx<'_, K>, sample: &[u32], bound: usize) -> bool {
        for (r, &q) in self.rels.iter_mut().zip(sample) {
            if self.lo >= bound {
                return false;
            }
            if r.is_none() {
                let rel = ctx.rel(q, self.c);
                *r = Some(rel);
                self.open -= 1;
                if rel == Rel::Span {
                    self.lo += 1;
                }
            }
        }
        self.lo < bound
    }
}

/// Splits `set` by the plane of a splitter chosen among `candidates` of its members
/// ([`choose_splitter`], then [`partition`]): the parts on the far side, in the plane,
/// and on the eye's side.
pub(crate) fn split_set<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    set: &[u32],
    candidates: usize,
) -> (Vec<u32>, Vec<u32>, Vec<u32>) {
    let (splitter, rels) = choose_splitter(ctx, set, candidates);
    partition(ctx, set, splitter, rels.as_deref())
}

/// Splits every member of `set` by the plane of `splitter` and returns the parts on the
/// far side, in the plane (sorted by face id: later faces win), and on the eye's side.
/// `rels`, when given, are the members' relations to that plane, in set order (`None`
/// where not known yet).
fn partition<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    set: &[u32],
    splitter: u32,
    rels: Option<&[Option<Rel>]>,
) -> (Vec<u32>, Vec<u32>, Vec<u32>) {
    let mut far = Vec::new();
    let mut cop = vec![splitter];
    let mut near = Vec::new();
    for (i, &q) in set.iter().enumerate() {
        if q == splitter {
            continue;
        }
        let rel = match rels.and_then(|r| r[i]) {
            Some(rel) => rel,
            None => ctx.rel(q, splitter),
        };
        match rel {
            Rel::Eye => near.push(q),
            Rel::Far => far.push(q),
            Rel::Coplanar => cop.push(q),
            Rel::Span => {
                let (e, f) = ctx.split_by(q, splitter);
                near.extend(e);
                far.extend(f);
            }
        }
    }
    cop.sort_by_key(|&p| (ctx.pieces[p as usize].face, p));
    (far, cop, near)
}
