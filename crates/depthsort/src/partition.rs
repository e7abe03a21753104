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
///
/// When the sample is the whole set, the winner's classification of every member
/// comes back with it (in set order), for [`partition`] to use instead of classifying
/// again.
fn choose_splitter<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    set: &[u32],
    candidates: usize,
) -> (u32, Option<Vec<Rel>>) {
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
    let mut best = set[0];
    let mut best_score = usize::MAX;
    let mut open = Vec::new();
    let (mut rels, mut best_rels) = (Vec::new(), None);
    for _ in 0..candidates.min(n) {
        let c = set[(ctx.next_random() % n as u64) as usize];
        if let Some(score) = score_below(ctx, &sample, c, best_score, &mut open, &mut rels) {
            best_score = score;
            best = c;
            if whole {
                best_rels = Some(std::mem::take(&mut rels));
            }
            if score == 0 {
                break;
            }
        }
    }
    (best, best_rels)
}

/// How many members of `sample` other than `c` span its plane, when fewer than `bound`
/// (`None` otherwise): the cheap classifications first, then the exact ones of the rest
/// until the count reaches `bound`. With a score, `rels` holds every member's relation
/// to the plane (`c`'s own as coplanar). `open` is working space.
fn score_below<K: Kernel>(
    ctx: &Ctx<'_, K>,
    sample: &[u32],
    c: u32,
    bound: usize,
    open: &mut Vec<u32>,
    rels: &mut Vec<Rel>,
) -> Option<usize> {
    open.clear();
    rels.clear();
    let mut score = 0usize;
    for (i, &q) in sample.iter().enumerate() {
        let rel = if q == c {
            Some(Rel::Coplanar)
        } else {
            ctx.rel_if_cheap(q, c)
        };
        match rel {
            Some(Rel::Span) => {
                score += 1;
                if score >= bound {
                    return None;
                }
            }
            Some(_) => {}
            None => open.push(i as u32),
        }
        // An open member's place is filled below.
        rels.push(rel.unwrap_or(Rel::Coplanar));
    }
    for &i in open.iter() {
        let rel = ctx.rel(sample[i as usize], c);
        rels[i as usize] = rel;
        if rel == Rel::Span {
            score += 1;
            if score >= bound {
                return None;
            }
        }
    }
    Some(score)
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
/// `rels`, when given, are the members' relations to that plane, in set order.
fn partition<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    set: &[u32],
    splitter: u32,
    rels: Option<&[Rel]>,
) -> (Vec<u32>, Vec<u32>, Vec<u32>) {
    let mut far = Vec::new();
    let mut cop = vec![splitter];
    let mut near = Vec::new();
    for (i, &q) in set.iter().enumerate() {
        if q == splitter {
            continue;
        }
        let rel = match rels {
            Some(r) => r[i],
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
