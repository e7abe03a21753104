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
    for _ in 0..candidates.min(n) {
        let c = set[(ctx.next_random() % n as u64) as usize];
        let mut score = 0usize;
        for &q in &sample {
            if q != c && ctx.rel(q, c) == Rel::Span {
                score += 1;
                if score >= best_score {
                    break;
                }
            }
        }
        if score < best_score {
            best_score = score;
            best = c;
            if score == 0 {
                break;
            }
        }
    }
    best
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
