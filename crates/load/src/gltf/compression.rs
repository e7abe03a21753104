//! Compressed glTF: which compression extensions are read, and the buffer views of
//! `EXT_meshopt_compression` decoded.
//!
//! Read: `KHR_mesh_quantization` (integer positions, normals and texture coordinates,
//! read by [`super::data::read_components`]), `EXT_meshopt_compression` (decoded here
//! by the `meshopt` crate, the Rust binding of meshoptimizer, whose decoders are the
//! reference of the extension and safe on untrusted input: every mode and filter) and
//! `KHR_draco_mesh_compression` (decoded by [`super::draco`]).
//! Not read, and refused when a file requires them, with the extension named first:
//! Basis Universal and WebP or AVIF textures (no maintained Rust transcoder of those
//! into RGBA). A file that only *uses* one of
//! them keeps an uncompressed fallback, which is drawn, with a warning.

use std::borrow::Cow;
use std::path::Path;

use serde_json::Value;

use crate::{LoadError, Location};

/// Compression extensions read.
pub(crate) const READ: &[&str] = &[
    "KHR_mesh_quantization",
    "EXT_meshopt_compression",
    "KHR_draco_mesh_compression",
];

/// Extensions not read, with what they hold and why.
const NOT_READ: &[(&str, &str)] = &[
    (
        "KHR_meshopt_compression",
        "meshopt-compressed buffers under the KHR name (EXT_meshopt_compression is read)",
    ),
    (
        "KHR_texture_basisu",
        "KTX2/Basis Universal textures; no maintained Rust transcoder",
    ),
    ("EXT_texture_webp", "WebP textures"),
    ("EXT_texture_avif", "AVIF textures"),
];

/// The error for a required extension limn does not read, when `ext` is one of
/// [`NOT_READ`].
pub(crate) fn refused(ext: &str, path: &Path) -> Option<LoadError> {
    let (_, what) = NOT_READ.iter().find(|(name, _)| *name == ext)?;
    Some(LoadError::Unsupported {
        at: Location::file(path),
        what: format!("required extension {ext} ({what})"),
    })
}

/// The warning for a used (not required) extension that limn does not read: its
/// fallback is drawn.
pub(crate) fn fallback_warning(ext: &str, path: &Path) -> Option<String> {
    let (_, what) = NOT_READ.iter().find(|(name, _)| *name == ext)?;
    Some(format!(
        "{}: {ext} ({what}) is not read; the file's uncompressed fallback is drawn",
        path.display()
    ))
}

/// What `EXT_meshopt_compression` says of a file's buffers and buffer views.
#[derive(Debug, Default)]
pub(crate) struct Meshopt {
    /// Per buffer: a fallback buffer (its bytes are made by decoding).
    pub fallback: Vec<bool>,
    /// The compressed buffer views.
    views: Vec<View>,
}

/// One compressed buffer view.
#[derive(Debug)]
struct View {
    index: usize,
    /// The buffer holding the compressed bytes, their offset and length.
    source: (usize, usize, usize),
    /// The view's own buffer, offset and length (where the decoded bytes go).
    target: (usize, usize, usize),
    stride: usize,
    count: usize,
    mode: String,
    filter: String,
}

/// A value of `v` as a `usize`.
fn size(v: &Value, key: &str) -> Option<usize> {
    v.get(key)?.as_u64().and_then(|n| usize::try_from(n).ok())
}

impl Meshopt {
    /// Reads the extension's objects from the glTF JSON `json`.
    pub(crate) fn read(json: &[u8], path: &Path) -> Result<Meshopt, LoadError> {
        let root: Value = serde_json::from_slice(json).map_err(|e| LoadError::Syntax {
            at: Location::file(path),
            message: format!("glTF JSON: {e}"),
        })?;
        let ext = |v: &Value| v.get("extensions")?.get("EXT_meshopt_compression").cloned();
        let empty = Vec::new();
        let list = |key: &str| root.get(key).and_then(Value::as_array).unwrap_or(&empty);
        let fallback = list("buffers")
            .iter()
            .map(|b| ext(b).is_some_and(|e| e.get("fallback") == Some(&Value::Bool(true))))
            .collect();
        let mut views = Vec::new();
        for (index, v) in list("bufferViews").iter().enumerate() {
            let Some(e) = ext(v) else { continue };
            let bad = |what: &str| LoadError::Invalid {
                at: Location::record(path, format!("buffer view {index}")),
                message: format!("EXT_meshopt_compression: {what}"),
            };
            let need = |key: &str| size(&e, key).ok_or_else(|| bad(&format!("no {key}")));
            views.push(View {
                index,
                source: (
                    need("buffer")?,
                    size(&e, "byteOffset").unwrap_or(0),
                    need("byteLength")?,
                ),
                target: (
                    size(v, "buffer").ok_or_else(|| bad("no buffer"))?,
                    size(v, "byteOffset").unwrap_or(0),
                    size(v, "byteLength").ok_or_else(|| bad("no byteLength"))?,
                ),
                stride: need("byteStride")?,
                count: need("count")?,
                mode: e
                    .get("mode")
                    .and_then(Value::as_str)
                    .unwrap_or("")
                    .to_string(),
                filter: e
                    .get("filter")
                    .and_then(Value::as_str)
                    .unwrap_or("NONE")
                    .to_string(),
            });
        }
        Ok(Meshopt { fallback, views })
    }

    /// Decodes every compressed view into its place in its own buffer.
    pub(crate) fn decode(
        &self,
        buffers: &mut [Cow<'_, [u8]>],
        path: &Path,
    ) -> Result<(), LoadError> {
        for v in &self.views {
            let at = || Location::record(path, format!("buffer view {}", v.index));
            let bad = |what: String| LoadError::Invalid {
                at: at(),
                message: format!("EXT_meshopt_compression: {what}"),
            };
            let (b, o, n) = v.source;
            let src = buffers
                .get(b)
                .and_then(|buf| buf.get(o..o.checked_add(n)?))
                .ok_or_else(|| bad(format!("bytes {o}..+{n} of buffer {b} do not exist")))?;
            let len = v
                .count
                .checked_mul(v.stride)
                .filter(|&l| l <= v.target.2)
                .ok_or_else(|| {
                    bad(format!(
                        "{} × {} bytes do not fit the view",
                        v.count, v.stride
                    ))
                })?;
            let decoded = decode_view(src, v).map_err(bad)?;
            debug_assert_eq!(decoded.len(), len);
            let (tb, to, _) = v.target;
            let target = buffers
                .get_mut(tb)
                .ok_or_else(|| bad(format!("buffer {tb} does not exist")))?
                .to_mut();
            let place = to
                .checked_add(len)
                .and_then(|end| target.get_mut(to..end))
                .ok_or_else(|| bad(format!("the view reaches past buffer {tb}")))?;
            place.copy_from_slice(&decoded);
        }
        Ok(())
    }
}

/// A vertex of `N` bytes, for the decoder's element size.
#[derive(Clone, Copy)]
struct Row<const N: usize>([u8; N]);

impl<const N: usize> Default for Row<N> {
    fn default() -> Self {
        Row([0; N])
    }
}

/// `count` vertices of `N` bytes decoded from `src`.
fn rows<const N: usize>(src: &[u8], count: usize) -> Result<Vec<u8>, String> {
    let v: Vec<Row<N>> = meshopt::decode_vertex_buffer(src, count).map_err(|e| e.to_string())?;
    Ok(v.into_iter().flat_map(|r| r.0).collect())
}

/// Decodes one view's bytes (mode, then filter).
fn decode_view(src: &[u8], v: &View) -> Result<Vec<u8>, String> {
    let mut out = match (v.mode.as_str(), v.stride) {
        ("ATTRIBUTES", s) => {
            macro_rules! by_stride {
                ($($n:literal)*) => {
                    match s {
                        $($n => Ok(rows::<$n>(src, v.count)?),)*
                        _ => return Err(format!("byteStride {s} (a multiple of 4 up to 256 is read)")),
                    }
                };
            }
            by_stride!(4 8 12 16 20 24 28 32 36 40 44 48 52 56 60 64 68 72 76 80 84 88 92 96
                100 104 108 112 116 120 124 128 132 136 140 144 148 152 156 160 164 168 172
                176 180 184 188 192 196 200 204 208 212 216 220 224 228 232 236 240 244 248
                252 256)
        }
        ("TRIANGLES", 2) => le16(meshopt::decode_index_buffer::<u16>(src, v.count)),
        ("TRIANGLES", 4) => le32(meshopt::decode_index_buffer::<u32>(src, v.count)),
        ("INDICES", 2) => le16(meshopt::decode_index_sequence::<u16>(src, v.count)),
        ("INDICES", 4) => le32(meshopt::decode_index_sequence::<u32>(src, v.count)),
        (m, s) => return Err(format!("mode {m:?} with byteStride {s}")),
    }
    .map_err(|e| e.to_string())?;
    filter(&mut out, v)?;
    Ok(out)
}

fn le16(r: meshopt::Result<Vec<u16>>) -> meshopt::Result<Vec<u8>> {
    r.map(|v| v.into_iter().flat_map(u16::to_le_bytes).collect())
}

fn le32(r: meshopt::Result<Vec<u32>>) -> meshopt::Result<Vec<u8>> {
    r.map(|v| v.into_iter().flat_map(u32::to_le_bytes).collect())
}

/// Applies the view's filter to the decoded bytes in place.
fn filter(out: &mut [u8], v: &View) -> Result<(), String> {
    match (v.filter.as_str(), v.stride) {
        ("NONE", _) => {}
        ("OCTAHEDRAL", 4) => {
            let mut q: Vec<[i8; 4]> = out
                .chunks_exact(4)
                .map(|c| [0, 1, 2, 3].map(|k| c[k] as i8))
                .collect();
            meshopt::decode_filter_oct(&mut q);
            for (c, x) in out.chunks_exact_mut(4).zip(q) {
                c.copy_from_slice(&x.map(|b| b as u8));
            }
        }
        ("OCTAHEDRAL", 8) | ("QUATERNION", 8) => {
            let mut q: Vec<[i16; 4]> = out
                .chunks_exact(8)
                .map(|c| [0, 1, 2, 3].map(|k| i16::from_le_bytes([c[2 * k], c[2 * k + 1]])))
                .collect();
            if v.filter == "OCTAHEDRAL" {
                meshopt::decode_filter_oct(&mut q);
            } else {
                meshopt::decode_filter_quat(&mut q);
            }
            for (c, x) in out.chunks_exact_mut(8).zip(q) {
                for k in 0..4 {
                    c[2 * k..2 * k + 2].copy_from_slice(&x[k].to_le_bytes());
                }
            }
        }
        ("EXPONENTIAL", s) if s % 4 == 0 => {
            let mut q: Vec<[u32; 1]> = out
                .chunks_exact(4)
                .map(|c| [u32::from_le_bytes([c[0], c[1], c[2], c[3]])])
                .collect();
            meshopt::decode_filter_exp(&mut q);
            for (c, x) in out.chunks_exact_mut(4).zip(q) {
                c.copy_from_slice(&x[0].to_le_bytes());
            }
        }
        (f, s) => return Err(format!("filter {f:?} with byteStride {s}")),
    }
    Ok(())
}
