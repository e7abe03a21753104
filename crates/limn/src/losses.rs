//! What the user gave that the picture does not show as given: one warning per kind,
//! printed on standard error and listed in `--stats`.

use limn_depthsort::Ordered;
use limn_paint::{Format, PaintStats};

/// The warnings of one painter's run, after ordering and writing.
///
/// `faces` is the scene's count of faces; `near_given` says whether the near plane came
/// from the user (flag or scene file): an automatic one gets advice to set `--near`.
pub fn losses(
    faces: usize,
    ordered: &Ordered,
    ps: &PaintStats,
    format: Format,
    near_given: bool,
) -> Vec<String> {
    let s = &ordered.stats;
    let mut out = Vec::new();
    if s.faces_near_clipped > 0 {
        let advice = if near_given {
            String::new()
        } else {
            format!(
                " (the automatic near plane at {:.6e} from the eye; set a smaller --near or \
                 move the eye)",
                ordered.near
            )
        };
        out.push(format!(
            "{} faces come closer to the eye than the near plane and are cut there{advice}",
            s.faces_near_clipped
        ));
    }
    if s.faces_degenerate > 0 {
        out.push(format!(
            "{} faces have zero area as given (fewer than three distinct corners, or all on one line) and are not drawn",
            s.faces_degenerate
        ));
    }
    if ps.approximated > 0 {
        let what = match format {
            Format::Eps => {
                "translucent fills or outlines, smoothly lit textured fragments, or \
                            fragments with a blended texture alpha: EPS has no opacity and \
                            no blend modes, so translucent ones are blended with the \
                            background instead, a lit texture is multiplied by its \
                            fragment's mean lit colour, and a texture's alpha (glTF \
                            alphaMode BLEND) is not drawn (cut-outs, MASK, are)"
            }
            Format::Tikz => {
                "smoothly shaded fragments: TikZ has no triangle-mesh shading, so each \
                            is filled with the mean of its corner colours"
            }
            Format::Svg | Format::Pdf => {
                "fragments the format can only approximate (textures reaching too many \
                            repetitions filled with their mean colour; translucent textured \
                            fragments; smoothly lit fragments whose texture shows what is \
                            behind, glTF alphaMode MASK or BLEND, drawn with their mean \
                            lit colour; in PDF, a blended texture's fill colour also \
                            multiplies what shows through it)"
            }
            _ => "fragments the format can only approximate",
        };
        out.push(format!("{} {what}", ps.approximated));
    }
    if ps.textures_flattened > 0 {
        out.push(format!(
            "{} textured fragments: {} draws no texture images, so each is filled with \
             its colour times the texture's mean colour (SVG, PDF and EPS draw the images)",
            ps.textures_flattened,
            match format {
                Format::Tikz => "TikZ",
                _ => "this format",
            }
        ));
    }
    if ps.skipped > 0 {
        out.push(format!(
            "{} fragments with invalid coordinates were not painted",
            ps.skipped
        ));
    }
    let marks_painted = ps.lines + ps.markers + ps.labels > 0;
    if ordered.stats.fragments_out == 0 && !(marks_painted && faces == 0) {
        let what = if marks_painted {
            "no face is drawn"
        } else {
            "the picture is empty"
        };
        out.push(format!(
            "{what}: of {} faces, {} are back faces or edge-on, {} degenerate, \
             {} outside the view or behind the near plane",
            faces, s.faces_culled, s.faces_degenerate, s.faces_clipped
        ));
    }
    out
}
