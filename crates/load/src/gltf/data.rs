//! glTF binary data: the GLB container, buffers (embedded, `data:` URIs, files) and
//! accessors, every offset and length checked.
//!
//! The `gltf` crate's own GLB splitter and accessor iterators are not used: they
//! compute offsets with unchecked arithmetic (a GLB whose header length is below 12,
//! or an accessor with count 0, overflows), and its importer cannot refuse buffer
//! files outside the model's folder.

use std::borrow::Cow;
use std::path::Path;

use ::gltf::accessor::{DataType, Dimensions};
use ::gltf::buffer::Source;
use ::gltf::Document;
use base64::Engine as _;
use glam::DVec3;

use super::super::{refs, LoadError, LoadOptions, Location};

fn u32_at(b: &[u8], at: usize) -> Option<u32> {
    Some(u32::from_le_bytes(
        b.get(at..at.checked_add(4)?)?.try_into().ok()?,
    ))
}

/// Splits a GLB file into its JSON chunk and optional BIN chunk.
pub(crate) fn split_glb<'a>(
    bytes: &'a [u8],
    path: &Path,
) -> Result<(&'a [u8], Option<&'a [u8]>), LoadError> {
    let at = || Location::record(path, "GLB header".into());
    let (Some(version), Some(length)) = (u32_at(bytes, 4), u32_at(bytes, 8)) else {
        return Err(LoadError::Truncated {
            at: at(),
            detail: "a GLB header has 12 bytes".into(),
        });
    };
    if version != 2 {
        return Err(LoadError::Unsupported {
            at: at(),
            what: format!("GLB version {version} (only 2 is read)"),
        });
    }
    let length = length as usize;
    if length > bytes.len() {
        return Err(LoadError::CountTooLarge {
            at: at(),
            what: "bytes".into(),
            claimed: length as u64,
            room: bytes.len() as u64,
        });
    }
    if length < 12 {
        return Err(LoadError::Invalid {
            at: at(),
            message: format!("GLB length {length} is shorter than its header"),
        });
    }
    let mut rest = &bytes[12..length];
    let mut json = None;
    let mut bin = None;
    let mut index = 0;
    while !rest.is_empty() {
        let at = || Location::record(path, format!("GLB chunk {index}"));
        let (Some(len), Some(kind)) = (u32_at(rest, 0), u32_at(rest, 4)) else {
            return Err(LoadError::Truncated {
                at: at(),
                detail: "a chunk header has 8 bytes".into(),
            });
        };
        let len = len as usize;
        let body = rest
            .get(8..8 + len)
            .ok_or_else(|| LoadError::CountTooLarge {
                at: at(),
                what: "bytes".into(),
                claimed: len as u64,
                room: rest.len() as u64 - 8,
            })?;
        match (&kind.to_le_bytes(), index) {
            (b"JSON", 0) => json = Some(body),
            (b"BIN\0", 1) => bin = Some(body),
            (_, 0) => {
                return Err(LoadError::Invalid {
                    at: at(),
                    message: "the first GLB chunk must be JSON".into(),
                })
            }
            _ => {} // other chunks are skipped, as the specification asks
        }
        rest = &rest[8 + len..];
        index += 1;
    }
    let json = json.ok_or_else(|| LoadError::Truncated {
        at: Location::record(path, "GLB".into()),
        detail: "no JSON chunk".into(),
    })?;
    Ok((json, bin))
}

/// Largest fallback buffer of `EXT_meshopt_compression` made to hold decoded views
/// (1 GiB).
const MAX_FALLBACK: usize = 1 << 30;

/// Loads every buffer of `doc`, each cut to its declared length, and records in `files`
/// every external file read. A buffer marked in `fallback` (an `EXT_meshopt_compression`
/// fallback) without a `uri` is made of zeros, for the decoded views to fill.
pub(crate) fn buffers<'a>(
    doc: &Document,
    blob: Option<&'a [u8]>,
    path: &Path,
    opts: &LoadOptions,
    fallback: &[bool],
    files: &mut Vec<std::path::PathBuf>,
) -> Result<Vec<Cow<'a, [u8]>>, LoadError> {
    let mut out = Vec::new();
    for buffer in doc.buffers() {
        let i = buffer.index();
        let at = Location::record(path, format!("buffer {i}"));
        let empty_fallback = fallback.get(i).copied().unwrap_or(false)
            && matches!(buffer.source(), Source::Bin)
            && (i > 0 || blob.is_none());
        if empty_fallback {
            if buffer.length() > MAX_FALLBACK {
                return Err(LoadError::TooLarge {
                    at,
                    what: "bytes in a meshopt fallback buffer",
                    limit: MAX_FALLBACK as u64,
                });
            }
            out.push(Cow::Owned(vec![0; buffer.length()]));
            continue;
        }
        let data: Cow<[u8]> = match buffer.source() {
            Source::Bin => Cow::Borrowed(blob.ok_or_else(|| LoadError::Invalid {
                at: at.clone(),
                message: "refers to the GLB BIN chunk, which is missing".into(),
            })?),
            Source::Uri(uri) => match uri.strip_prefix("data:") {
                Some(rest) => Cow::Owned(data_uri(rest, &at)?),
                None => {
                    let name = urlencoding::decode(uri).map_err(|_| LoadError::Invalid {
                        at: at.clone(),
                        message: format!("uri {uri:?} is not valid percent-encoded UTF-8"),
                    })?;
                    if name.contains("://") {
                        return Err(LoadError::Unsupported {
                            at,
                            what: format!("remote buffer {uri:?}"),
                        });
                    }
                    let file = refs::resolve(&name, &at, opts)?;
                    let bytes = refs::read(&file)?;
                    files.push(file);
                    Cow::Owned(bytes)
                }
            },
        };
        let want = buffer.length();
        if data.len() < want {
            return Err(LoadError::Truncated {
                at,
                detail: format!("declares {want} bytes but holds {}", data.len()),
            });
        }
        out.push(match data {
            Cow::Borrowed(b) => Cow::Borrowed(&b[..want]),
            Cow::Owned(mut v) => {
                v.truncate(want);
                Cow::Owned(v)
            }
        });
    }
    Ok(out)
}

/// Decodes the part of a `data:` URI after the scheme.
pub(crate) fn data_uri(rest: &str, at: &Location) -> Result<Vec<u8>, LoadError> {
    let bad = |m: &str| LoadError::Invalid {
        at: at.clone(),
        message: format!("bad data: URI: {m}"),
    };
    let (head, payload) = rest.split_once(',').ok_or_else(|| bad("no comma"))?;
    if head.ends_with(";base64") {
        let engine = base64::engine::GeneralPurpose::new(
            &base64::alphabet::STANDARD,
            base64::engine::GeneralPurposeConfig::new()
                .with_decode_padding_mode(base64::engine::DecodePaddingMode::Indifferent),
        );
        engine.decode(payload).map_err(|e| bad(&e.to_string()))
    } else {
        Ok(urlencoding::decode_binary(payload.as_bytes()).into_owned())
    }
}

/// Where accessor `acc`'s elements lie: (buffer bytes of its view, first byte, stride).
pub(crate) fn layout<'b>(
    acc: &::gltf::Accessor,
    buffers: &'b [Cow<[u8]>],
    elem: usize,
    path: &Path,
) -> Result<(&'b [u8], usize, usize), LoadError> {
    let at = || Location::record(path, format!("accessor {}", acc.index()));
    if acc.sparse().is_some() {
        return Err(LoadError::Unsupported {
            at: at(),
            what: "sparse accessors".into(),
        });
    }
    let view = acc.view().ok_or_else(|| LoadError::Unsupported {
        at: at(),
        what: "an accessor without a buffer view".into(),
    })?;
    let buf = buffers
        .get(view.buffer().index())
        .ok_or_else(|| LoadError::Invalid {
            at: at(),
            message: "its buffer does not exist".into(),
        })?;
    let data = view
        .offset()
        .checked_add(view.length())
        .and_then(|end| buf.get(view.offset()..end))
        .ok_or_else(|| LoadError::Invalid {
            at: at(),
            message: format!("buffer view {} reaches past its buffer", view.index()),
        })?;
    let stride = view.stride().unwrap_or(elem);
    if stride < elem {
        return Err(LoadError::Invalid {
            at: at(),
            message: format!("stride {stride} is shorter than an element ({elem} bytes)"),
        });
    }
    let count = acc.count();
    if count > 0 {
        let end = (count - 1)
            .checked_mul(stride)
            .and_then(|v| v.checked_add(elem))
            .and_then(|v| v.checked_add(acc.offset()));
        if end.is_none_or(|e| e > data.len()) {
            return Err(LoadError::CountTooLarge {
                at: at(),
                what: "elements".into(),
                claimed: count as u64,
                room: (data.len().saturating_sub(acc.offset()) / stride) as u64,
            });
        }
    }
    Ok((data, acc.offset(), stride))
}

/// The value of one component of type `t` at the start of `b`: floats as they are,
/// normalised integers scaled to [0, 1] (unsigned) or [-1, 1] (signed, as the
/// specification asks: the most negative value is -1 too), other integers as they are.
fn component(b: &[u8], t: DataType, normalized: bool) -> f64 {
    let (v, full) = match t {
        DataType::F32 => return f64::from(f32::from_le_bytes([b[0], b[1], b[2], b[3]])),
        DataType::I8 => (f64::from(b[0] as i8), 127.0),
        DataType::U8 => (f64::from(b[0]), 255.0),
        DataType::I16 => (f64::from(i16::from_le_bytes([b[0], b[1]])), 32767.0),
        DataType::U16 => (f64::from(u16::from_le_bytes([b[0], b[1]])), 65535.0),
        DataType::U32 => (
            f64::from(u32::from_le_bytes([b[0], b[1], b[2], b[3]])),
            4294967295.0,
        ),
    };
    if normalized {
        (v / full).max(-1.0)
    } else {
        v
    }
}

/// Reads an accessor of `N` components each (`dims`) whose component type is one of
/// `types` (with `normalized` flags as listed: `None` for either), every value finite.
/// `what` names the attribute in messages.
pub(crate) fn read_components<const N: usize>(
    acc: &::gltf::Accessor,
    buffers: &[Cow<[u8]>],
    dims: Dimensions,
    types: &[(DataType, Option<bool>)],
    what: &str,
    path: &Path,
) -> Result<Vec<[f64; N]>, LoadError> {
    let at = || Location::record(path, format!("accessor {}", acc.index()));
    let (t, normalized) = (acc.data_type(), acc.normalized());
    let known = types
        .iter()
        .any(|&(ty, n)| ty == t && n.is_none_or(|n| n == normalized));
    if acc.dimensions() != dims || !known {
        let list: Vec<String> = types
            .iter()
            .map(|(ty, n)| match n {
                Some(true) => format!("normalised {ty:?}"),
                _ => format!("{ty:?}"),
            })
            .collect();
        return Err(LoadError::Unsupported {
            at: at(),
            what: format!(
                "{what} of type {}{t:?} {:?} ({dims:?} of {} is read)",
                if normalized { "normalised " } else { "" },
                acc.dimensions(),
                list.join(", ")
            ),
        });
    }
    let size = t.size();
    let (data, start, stride) = layout(acc, buffers, N * size, path)?;
    let mut out = Vec::with_capacity(acc.count());
    for i in 0..acc.count() {
        let o = start + i * stride;
        let v: [f64; N] = std::array::from_fn(|k| component(&data[o + size * k..], t, normalized));
        if !v.iter().all(|c| c.is_finite()) {
            return Err(LoadError::NonFinite {
                at: Location::record(path, format!("accessor {} element {i}", acc.index())),
                what: what.to_string(),
            });
        }
        out.push(v);
    }
    Ok(out)
}

/// Component types of positions: float, and with `KHR_mesh_quantization` (signed or
/// unsigned) bytes and shorts, normalised or not.
pub(crate) const POSITION_TYPES: &[(DataType, Option<bool>)] = &[
    (DataType::F32, Some(false)),
    (DataType::I8, None),
    (DataType::U8, None),
    (DataType::I16, None),
    (DataType::U16, None),
];

/// Component types of normals: float, and with `KHR_mesh_quantization` normalised
/// signed bytes and shorts.
pub(crate) const NORMAL_TYPES: &[(DataType, Option<bool>)] = &[
    (DataType::F32, Some(false)),
    (DataType::I8, Some(true)),
    (DataType::I16, Some(true)),
];

/// Reads a VEC3 accessor of positions or normals (`types`: [`POSITION_TYPES`] or
/// [`NORMAL_TYPES`]), checking every value is finite.
pub(crate) fn read_vec3(
    acc: &::gltf::Accessor,
    buffers: &[Cow<[u8]>],
    types: &[(DataType, Option<bool>)],
    what: &str,
    path: &Path,
) -> Result<Vec<DVec3>, LoadError> {
    let v = read_components::<3>(acc, buffers, Dimensions::Vec3, types, what, path)?;
    Ok(v.into_iter().map(DVec3::from_array).collect())
}

/// Reads a `COLOR_n` accessor (float, normalised unsigned byte or short; VEC3 or VEC4)
/// as RGBA (alpha 1 for VEC3), each channel clamped to [0, 1].
pub(crate) fn read_colors(
    acc: &::gltf::Accessor,
    buffers: &[Cow<[u8]>],
    path: &Path,
) -> Result<Vec<[f64; 4]>, LoadError> {
    const TYPES: &[(DataType, Option<bool>)] = &[
        (DataType::F32, Some(false)),
        (DataType::U8, Some(true)),
        (DataType::U16, Some(true)),
    ];
    let rgba: Vec<[f64; 4]> = if acc.dimensions() == Dimensions::Vec3 {
        read_components::<3>(acc, buffers, Dimensions::Vec3, TYPES, "colour", path)?
            .into_iter()
            .map(|[r, g, b]| [r, g, b, 1.0])
            .collect()
    } else {
        read_components::<4>(acc, buffers, Dimensions::Vec4, TYPES, "colour", path)?
    };
    Ok(rgba
        .into_iter()
        .map(|c| c.map(|v| v.clamp(0.0, 1.0)))
        .collect())
}

/// Reads an index accessor (unsigned scalars).
pub(crate) fn read_indices(
    acc: &::gltf::Accessor,
    buffers: &[Cow<[u8]>],
    path: &Path,
) -> Result<Vec<u32>, LoadError> {
    let size = match (acc.dimensions(), acc.data_type()) {
        (Dimensions::Scalar, DataType::U8) => 1,
        (Dimensions::Scalar, DataType::U16) => 2,
        (Dimensions::Scalar, DataType::U32) => 4,
        (d, t) => {
            return Err(LoadError::Invalid {
                at: Location::record(path, format!("accessor {}", acc.index())),
                message: format!("indices of type {t:?} {d:?} (unsigned SCALAR expected)"),
            })
        }
    };
    let (data, start, stride) = layout(acc, buffers, size, path)?;
    let mut out = Vec::with_capacity(acc.count());
    for i in 0..acc.count() {
        let b = &data[start + i * stride..start + i * stride + size];
        out.push(match size {
            1 => b[0] as u32,
            2 => u16::from_le_bytes([b[0], b[1]]) as u32,
            _ => u32::from_le_bytes([b[0], b[1], b[2], b[3]]),
        });
    }
    Ok(out)
}
