//! A render by an image-space method: the scene per pixel, written as PNG.

use std::io::Write;
use std::path::Path;

use limn_depthsort::{CullMode, OrderOptions};
use limn_scene::{Camera, Scene};
use limn_zbuffer::{render_with_shadow_maps, Method, RenderOptions, ShadowMapOptions};

use crate::error::Error;
use crate::events::Events;
use crate::options::RenderOptions as Options;
use crate::output::{write_atomic, OutputError};

/// Renders `scene` with the image-space method of `o` and writes its colour image as PNG
/// to `out`, else to the file `output`.
pub fn raster(
    scene: &Scene,
    cam: &Camera,
    o: &Options,
    oo: &OrderOptions,
    output: &Path,
    out: Option<&mut dyn Write>,
    events: &mut dyn Events,
) -> Result<(), Error> {
    let Some(method) = o.method.raster() else {
        return Err(Error::Conflict(
            "the painter is not a raster method".to_string(),
        ));
    };
    let opts = RenderOptions {
        cull_back_faces: oo.cull == CullMode::On,
        ..RenderOptions::default()
    };
    if method == Method::ABuffer && !scene.shadow_lights().is_empty() {
        events.warning("the A-buffer draws no shadows (use zbuffer, scanline, warnock or raycast)");
    }
    let maps = ShadowMapOptions {
        size: o.shadow_map_size,
        bias: o.shadow_bias,
    };
    let r = render_with_shadow_maps(scene, cam, method, &opts, &maps)?;
    let png = r.color.encode_png()?;
    if let Some(w) = out {
        return w.write_all(&png).map_err(|source| {
            Error::from(OutputError::Write {
                path: output.to_path_buf(),
                source,
            })
        });
    }
    write_atomic(output, &scene.files, |w| {
        w.write_all(&png).map_err(|source| OutputError::Write {
            path: output.to_path_buf(),
            source,
        })?;
        Ok(())
    })
}
