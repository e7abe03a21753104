//! glTF base-colour textures: the `TEXCOORD_n` accessor a material's
//! `baseColorTexture` names, and its image (in a buffer view, a `data:` URI or a file
//! beside the glTF file, under the same folder rule as buffers).
//!
//! Images are read only for primitives that draw them (a textured material on a
//! primitive with the texture coordinates), each at most once. Samplers: `wrapS` and
//! `wrapT` are drawn (`REPEAT`, `MIRRORED_REPEAT`, `CLAMP_TO_EDGE`, see
//! [`limn_scene::texture_wrap`]); filters are not read (limn samples bilinearly).
//! `KHR_texture_transform` (offset, rotation, scale, `texCoord`) moves the coordinates
//! as they are read.

use std::borrow::Cow;
use std::path::Path;
use std::sync::Arc;

use ::gltf::accessor::{DataType, Dimensions};
use ::gltf::image::Source;
use limn_scene::Texture;

use super::data;
use crate::{refs, LoadError, LoadOptions, Location};

/// Reads a texture coordinate accessor: float, or normalised unsigned byte or short
/// VEC2, and with `KHR_mesh_quantization` signed ones and unnormalised integers too,
/// each value finite.
pub(crate) fn read_vec2(
    acc: &::gltf::Accessor,
    buffers: &[Cow<[u8]>],
    path: &Path,
) -> Result<Vec<[f64; 2]>, LoadError> {
    const TYPES: &[(DataType, Option<bool>)] = &[
        (DataType::F32, Some(false)),
        (DataType::I8, None),
        (DataType::U8, None),
        (DataType::I16, None),
        (DataType::U16, None),
    ];
    data::read_components::<2>(
        acc,
        buffers,
        Dimensions::Vec2,
        TYPES,
        "texture coordinates",
        path,
    )
}

/// Applies a `KHR_texture_transform` to texture coordinates, as the extension defines
/// it: `translation · rotation · scale`, the rotation matrix's columns `(cos r, sin r)`
/// and `(−sin r, cos r)`.
pub(crate) fn transform(st: &mut [[f64; 2]], t: &::gltf::texture::TextureTransform) {
    let [ox, oy] = t.offset().map(f64::from);
    let [sx, sy] = t.scale().map(f64::from);
    let r = f64::from(t.rotation());
    let (sin, cos) = r.sin_cos();
    for p in st.iter_mut() {
        let (u, v) = (p[0] * sx, p[1] * sy);
        *p = [cos * u - sin * v + ox, sin * u + cos * v + oy];
    }
}

/// Refuses images with neither a `uri` nor a `bufferView` with a `mimeType` (the
/// `gltf` crate assumes one of them when asked for the image's source).
pub(crate) fn check_images(doc: &::gltf::Document, path: &Path) -> Result<(), LoadError> {
    for (i, json) in doc.as_json().images.iter().enumerate() {
        if json.uri.is_none() && (json.buffer_view.is_none() || json.mime_type.is_none()) {
            return Err(LoadError::Invalid {
                at: Location::record(path, format!("image {i}")),
                message: "an image needs a uri, or a bufferView and a mimeType".into(),
            });
        }
    }
    Ok(())
}

/// Decodes the image of `texture`.
pub(crate) fn read_image(
    texture: &::gltf::Texture,
    buffers: &[Cow<[u8]>],
    path: &Path,
    opts: &LoadOptions,
    files: &mut Vec<std::path::PathBuf>,
) -> Result<Arc<Texture>, LoadError> {
    let image = texture.source();
    let at = Location::record(path, format!("image {}", image.index()));
    let (bytes, name): (Cow<[u8]>, String) = match image.source() {
        Source::View { view, .. } => {
            let buf = buffers
                .get(view.buffer().index())
                .ok_or_else(|| LoadError::Invalid {
                    at: at.clone(),
                    message: "its buffer does not exist".into(),
                })?;
            let bytes = view
                .offset()
                .checked_add(view.length())
                .and_then(|end| buf.get(view.offset()..end))
                .ok_or_else(|| LoadError::Invalid {
                    at: at.clone(),
                    message: format!("buffer view {} reaches past its buffer", view.index()),
                })?;
            (
                Cow::Borrowed(bytes),
                format!("buffer view {}", view.index()),
            )
        }
        Source::Uri { uri, .. } => match uri.strip_prefix("data:") {
            Some(rest) => (Cow::Owned(data::data_uri(rest, &at)?), "data: URI".into()),
            None => {
                let name = urlencoding::decode(uri).map_err(|_| LoadError::Invalid {
                    at: at.clone(),
                    message: format!("uri {uri:?} is not valid percent-encoded UTF-8"),
                })?;
                if name.contains("://") {
                    return Err(LoadError::Unsupported {
                        at,
                        what: format!("remote image {uri:?}"),
                    });
                }
                let file = refs::resolve(&name, &at, opts)?;
                let bytes = std::fs::read(&file).map_err(|e| LoadError::Image {
                    at: at.clone(),
                    image: name.to_string(),
                    message: format!("cannot read {}: {e}", file.display()),
                })?;
                files.push(file);
                (Cow::Owned(bytes), name.into_owned())
            }
        },
    };
    crate::image::decode(&bytes, &name, &at)
}
