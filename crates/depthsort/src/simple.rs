//! The simple depth sort: one depth per polygon (the mean view depth of its vertices),
//! far to near. What matplotlib and pgfplots do; wrong on the hard cases, kept as a
//! baseline.

use limn_kernel::Kernel;

use crate::pieces::Ctx;

/// Sorts the pieces by decreasing mean depth; ties go by input order.
pub(crate) fn simple<K: Kernel>(ctx: &mut Ctx<'_, K>, mut items: Vec<u32>) -> Vec<u32> {
    items.sort_by(|&a, &b| {
        let (pa, pb) = (&ctx.pieces[a as usize], &ctx.pieces[b as usize]);
        pb.dmean.total_cmp(&pa.dmean).then(pa.face.cmp(&pb.face))
    });
    items
}
