//! The shadows of a painted order against an image-space reference: which lights each
//! pixel centre's point is hidden from, per pixel, outside the edge band (the band
//! follows every fragment edge, so it also follows every shadow boundary the painter
//! cut).

use limn_scene::{LightSet, Scene};
use limn_zbuffer::{
    compare, render_with_shadow_maps, Comparison, IdImage, Method, ShadowMapOptions, NO_FACE,
};

use crate::{CheckError, Painted};

/// A shadow set as an id (its bits; at most 32 lights are compared).
fn shadow_id(set: LightSet) -> u32 {
    set.bits() as u32
}

impl Painted {
    /// Which lights the last painted fragment at each pixel centre is in the shadow of
    /// (as [`LightSet::bits`]; [`NO_FACE`] where nothing is painted).
    pub fn shadow_ids(&self) -> IdImage {
        let polys: Vec<(Vec<[f64; 2]>, u32)> = self
            .ordered
            .fragments
            .iter()
            .map(|f| (f.points.clone(), shadow_id(f.shadowed)))
            .collect();
        let c = self.camera();
        // Paint the sets over a picture of the faces, so that background stays NO_FACE.
        let mut ids = limn_zbuffer::rasterize_ids(&polys, c.width, c.height);
        for (s, &face) in ids.ids.iter_mut().zip(&self.ids.ids) {
            if face == NO_FACE {
                *s = NO_FACE;
            }
        }
        ids
    }

    /// The reference's shadow sets per pixel (exact for [`Method::RayCast`], by shadow
    /// maps made as `maps` says for the z-buffer methods), [`NO_FACE`] where it shows no
    /// face. Every pixel is lit (0) when no light casts shadows.
    pub fn reference_shadows(
        &self,
        scene: &Scene,
        method: Method,
        maps: &ShadowMapOptions,
    ) -> Result<IdImage, CheckError> {
        let r = render_with_shadow_maps(scene, self.camera(), method, &self.ropts, maps)?;
        let mut ids = r.ids;
        for (i, id) in ids.ids.iter_mut().enumerate() {
            if *id != NO_FACE {
                *id = r.shadowed.as_ref().map_or(0, |s| shadow_id(s[i]));
            }
        }
        Ok(ids)
    }

    /// Compares the painter's shadow sets with `other` outside [`Painted::band`].
    pub fn compare_shadows(&self, other: &IdImage) -> Comparison {
        compare(&self.shadow_ids(), other, Some(&self.band))
    }
}
