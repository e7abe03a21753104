//! Splitting a set of pieces by the plane of one of them (the BSP step), shared by the
//! BSP and adaptive orderings and by the sets split apart on every core.

use limn_kernel::Kernel;

use crate::occlusion::Rel;
use crate::pieces::Ctx;

/// How many pieces a splitter candidate is scored against, at most.
pub(crate) const SCORE_SAMPLE: usize = 512;

/// Picks a splitter among `candidates` random members of `set`: the one whose plane
/// crosses the fewest other members (scored on a deterministic sample of at most
/// [`SCORE_SAMPLE`] members).
///
/// A candidate is scored first by the classifications the kernel makes cheaply
/// ([`Ctx::rel_if_cheap`]); the members it cannot place without exact evaluation (a
/// corner within rounding of the plane: parts of an assembly in contact, faces made
/// coplanar and then moved by a transform) are classified exactly only while the
/// candidate can still beat the best one, so the choice is the one a score of exact
/// classifications in sample order makes. Those exact evaluations were most of the
/// scoring's time on a CAD assembly (152,000 of its 932,000 classifications, a fifth of
/// the whole run's samples).
pub(crate) fn choose_splitter<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    set: &[u32],
    candidates: usize,
) -> u32 {
    let n = set.len();
    if n <= 2 || candidates <= 1 {
        return set[(ctx.next_random() % n as u64) as usize];
    }
    let sample: Vec<u32> = if n <= SCORE_SAMPLE {
        set.to_vec()
    } else {
        (0..SCORE_SAMPLE)
            .map(|_| set[(ctx.next_random() % n as u64) as usize])
            .collect()
    };
    let mut best = set[0];
    let mut best_score = usize::MAX;
    let mut open = Vec::new();
    for _ in 0..candidates.min(n) {
        let c = set[(ctx.next_random() % n as u64) as usize];
        if let Some(score) = score_below(ctx, &sample, c, best_score, &mut open) {
            best_score = score;
            best = c;
            if score == 0 {
                break;
            }
        }
    }
    best
}

/// How many members of `sample` other than `c` span its plane, when fewer than `bound`
/// (`None` otherwise): the cheap classifications first, then the exact ones of the rest
/// until the count reaches `bound`. `open` is working space.
fn score_below<K: Kernel>(
    ctx: &Ctx<'_, K>,
    sample: &[u32],
    c: u32,
    bound: usize,
    open: &mut Vec<u32>,
) -> Option<usize> {
    open.clear();
    let mut score = 0usize;
    for &q in sample {
        if q == c {
            continue;
        }
        match ctx.rel_if_cheap(q, c) {
            Some(Rel::Span) => {
                score += 1;
                if score >= bound {
                    return None;
                }
            }
            Some(_) => {}
            None => open.push(q),
        }
    }
    for &q in open.iter() {
        if ctx.rel(q, c) == Rel::Span {
            score += 1;
            if score >= bound {
                return None;
            }
        }
    }
    Some(score)
}

/// Splits every member of `set` by the plane of `splitter` and returns the parts on the
/// far side, in the plane (sorted by face id: later faces win), and on the eye's side.
pub(crate) fn partition<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    set: &[u32],
    splitter: u32,
) -> (Vec<u32>, Vec<u32>, Vec<u32>) {
    let mut far = Vec::new();
    let mut cop = vec![splitter];
    let mut near = Vec::new();
    for &q in set {
        if q == splitter {
            continue;
        }
        match ctx.rel(q, splitter) {
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
