//! Draco-compressed primitives (`KHR_draco_mesh_compression`: triangle meshes, and
//! point clouds for point primitives), decoded by the
//! `draco-core` crate (a Rust Draco decoder, no `unsafe`, with ceilings on what one
//! decode may produce) into plain accessors.
//!
//! A compressed primitive names a buffer view holding a Draco mesh and, per attribute,
//! the Draco attribute that holds it; its own accessors give the type, component type
//! and count but no data. Each decoded attribute (and the faces, as `UNSIGNED_INT`
//! indices) is written into one buffer made for the purpose, in the accessor's own
//! component type, and the accessor is pointed at it: everything after reads the
//! primitive as if the file had stored it uncompressed.

use std::borrow::Cow;
use std::path::Path;

use ::gltf::json::accessor::{ComponentType, GenericComponentType, Type};
use ::gltf::json::validation::{Checked, USize64};
use ::gltf::json::{buffer, Index, Root};
use serde_json::Value;

use crate::{LoadError, Location};

/// The extension's name.
pub(crate) const NAME: &str = "KHR_draco_mesh_compression";

/// One compressed primitive: where its Draco mesh is and which accessor each decoded
/// attribute fills.
#[derive(Debug)]
pub(crate) struct Primitive {
    mesh: usize,
    primitive: usize,
    view: usize,
    /// (accessor, Draco attribute id) per attribute the extension lists.
    attributes: Vec<(usize, u32)>,
    /// The indices' accessor.
    indices: Option<usize>,
    /// A point primitive (mode 0): a Draco point cloud.
    points: bool,
}

/// The compressed primitives of a file (empty when it has none).
pub(crate) fn read(json: &[u8], path: &Path) -> Result<Vec<Primitive>, LoadError> {
    let root: Value = serde_json::from_slice(json).map_err(|e| LoadError::Syntax {
        at: Location::file(path),
        message: format!("glTF JSON: {e}"),
    })?;
    let index = |v: Option<&Value>| v.and_then(Value::as_u64).map(|i| i as usize);
    let mut out = Vec::new();
    let meshes = root.get("meshes").and_then(Value::as_array);
    for (m, mesh) in meshes.into_iter().flatten().enumerate() {
        let prims = mesh.get("primitives").and_then(Value::as_array);
        for (p, prim) in prims.into_iter().flatten().enumerate() {
            let Some(ext) = prim.get("extensions").and_then(|e| e.get(NAME)) else {
                continue;
            };
            let bad = |what: &str| LoadError::Invalid {
                at: Location::record(path, format!("mesh {m} primitive {p}")),
                message: format!("{NAME}: {what}"),
            };
            let view = index(ext.get("bufferView")).ok_or_else(|| bad("no bufferView"))?;
            let own = prim.get("attributes").and_then(Value::as_object);
            let listed = ext.get("attributes").and_then(Value::as_object);
            let mut attributes = Vec::new();
            for (name, id) in listed.into_iter().flatten() {
                let id = id
                    .as_u64()
                    .and_then(|i| u32::try_from(i).ok())
                    .ok_or_else(|| bad(&format!("attribute {name}: not a Draco attribute id")))?;
                let accessor = index(own.and_then(|a| a.get(name))).ok_or_else(|| {
                    bad(&format!(
                        "attribute {name} is not among the primitive's own"
                    ))
                })?;
                attributes.push((accessor, id));
            }
            out.push(Primitive {
                mesh: m,
                primitive: p,
                view,
                attributes,
                indices: index(prim.get("indices")),
                points: prim.get("mode").and_then(Value::as_u64) == Some(0),
            });
        }
    }
    Ok(out)
}

/// Decodes every compressed primitive from `buffers` and points its accessors at the
/// decoded values, in a buffer appended to `root` whose bytes are returned (to be
/// appended to `buffers` in the same place).
pub(crate) fn decode(
    prims: &[Primitive],
    root: &mut Root,
    buffers: &[Cow<'_, [u8]>],
    path: &Path,
) -> Result<Vec<u8>, LoadError> {
    let target = root.buffers.len();
    let mut out: Vec<u8> = Vec::new();
    for prim in prims {
        let at = Location::record(
            path,
            format!("mesh {} primitive {}", prim.mesh, prim.primitive),
        );
        let bad = |what: String| LoadError::Invalid {
            at: at.clone(),
            message: format!("{NAME}: {what}"),
        };
        let view = root
            .buffer_views
            .get(prim.view)
            .ok_or_else(|| bad(format!("buffer view {} does not exist", prim.view)))?;
        let (b, o) = (
            view.buffer.value(),
            view.byte_offset.map_or(0, |o| o.0 as usize),
        );
        let n = view.byte_length.0 as usize;
        let bytes = buffers
            .get(b)
            .and_then(|buf| buf.get(o..o.checked_add(n)?))
            .ok_or_else(|| bad(format!("bytes {o}..+{n} of buffer {b} do not exist")))?;
        let mut stream = draco_core::DecoderBuffer::new(bytes);
        let undecodable =
            |e: draco_core::DracoError| bad(format!("the stream does not decode: {e}"));
        let mut mesh = draco_core::Mesh::new();
        let mut cloud = draco_core::PointCloud::new();
        let (decoded, faces): (&draco_core::PointCloud, &[draco_core::mesh::Face]) = if prim.points
        {
            draco_core::PointCloudDecoder::new()
                .decode(&mut stream, &mut cloud)
                .map_err(undecodable)?;
            (&cloud, &[])
        } else {
            draco_core::MeshDecoder::new()
                .decode(&mut stream, &mut mesh)
                .map_err(undecodable)?;
            (&mesh, mesh.faces())
        };
        let points = decoded.num_points();
        for &(accessor, id) in &prim.attributes {
            let attribute = decoded
                .attribute_by_unique_id(id)
                .ok_or_else(|| bad(format!("Draco attribute {id} is not in the stream")))?;
            let acc = root
                .accessors
                .get(accessor)
                .ok_or_else(|| bad(format!("accessor {accessor} does not exist")))?;
            let (Checked::Valid(ty), Checked::Valid(GenericComponentType(ct))) =
                (acc.type_, acc.component_type)
            else {
                return Err(bad(format!("accessor {accessor}: invalid type")));
            };
            if acc.count.0 as usize != points {
                return Err(bad(format!(
                    "accessor {accessor} counts {} values, the Draco stream has {points} points",
                    acc.count.0
                )));
            }
            let values = attribute.read_f32s(points, ty.multiplicity());
            let start = place(&mut out);
            for v in values {
                push_component(&mut out, ct, v);
            }
            point_at(root, accessor, target, start, out.len() - start, None);
        }
        if let Some(accessor) = prim.indices {
            if accessor >= root.accessors.len() {
                return Err(bad(format!("accessor {accessor} does not exist")));
            }
            let start = place(&mut out);
            for face in faces {
                for p in face {
                    out.extend_from_slice(&p.0.to_le_bytes());
                }
            }
            let count = 3 * faces.len();
            point_at(
                root,
                accessor,
                target,
                start,
                out.len() - start,
                Some(count),
            );
        }
    }
    root.buffers.push(buffer::Buffer {
        byte_length: USize64(out.len() as u64),
        name: None,
        uri: None,
        extensions: None,
        extras: Default::default(),
    });
    Ok(out)
}

/// Pads `out` to a multiple of four bytes (the alignment of every component type) and
/// returns where the next values start.
fn place(out: &mut Vec<u8>) -> usize {
    out.resize(out.len().next_multiple_of(4), 0);
    out.len()
}

/// Appends one component of type `ct` holding `v` (an integer for integer types, as the
/// Draco attribute stores it).
fn push_component(out: &mut Vec<u8>, ct: ComponentType, v: f32) {
    match ct {
        ComponentType::F32 => out.extend_from_slice(&v.to_le_bytes()),
        ComponentType::U8 => out.push(v as u8),
        ComponentType::I8 => out.push(v as i8 as u8),
        ComponentType::U16 => out.extend_from_slice(&(v as u16).to_le_bytes()),
        ComponentType::I16 => out.extend_from_slice(&(v as i16).to_le_bytes()),
        ComponentType::U32 => out.extend_from_slice(&(v as u32).to_le_bytes()),
    }
}

/// Points `accessor` at `len` bytes from `start` of buffer `target` through a new buffer
/// view, tightly packed; `indices`: it now counts that many `UNSIGNED_INT` indices.
fn point_at(
    root: &mut Root,
    accessor: usize,
    target: usize,
    start: usize,
    len: usize,
    indices: Option<usize>,
) {
    let view = Index::push(
        &mut root.buffer_views,
        buffer::View {
            buffer: Index::new(target as u32),
            byte_length: USize64(len as u64),
            byte_offset: Some(USize64(start as u64)),
            byte_stride: None,
            name: None,
            target: None,
            extensions: None,
            extras: Default::default(),
        },
    );
    let acc = &mut root.accessors[accessor];
    acc.buffer_view = Some(view);
    acc.byte_offset = Some(USize64(0));
    acc.sparse = None;
    if let Some(count) = indices {
        acc.count = USize64(count as u64);
        acc.component_type = Checked::Valid(GenericComponentType(ComponentType::U32));
        acc.type_ = Checked::Valid(Type::Scalar);
    }
}
