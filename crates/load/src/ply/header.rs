//! The PLY header: format, elements and their properties.

use std::path::Path;

use super::super::text::{lossy, tokens, Lines};
use super::super::LoadError;

/// The encoding of the body.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Encoding {
    Ascii,
    LittleEndian,
    BigEndian,
}

/// A scalar type of a property.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn parse(name: &[u8]) -> Option<Scalar> {
        Some(match name {
            b"char" | b"int8" => Scalar::I8,
            b"uchar" | b"uint8" => Scalar::U8,
            b"short" | b"int16" => Scalar::I16,
            b"ushort" | b"uint16" => Scalar::U16,
            b"int" | b"int32" => Scalar::I32,
            b"uint" | b"uint32" => Scalar::U32,
            b"float" | b"float32" => Scalar::F32,
            b"double" | b"float64" => Scalar::F64,
            _ => return None,
        })
    }

    /// Size in bytes in a binary body.
    pub(crate) fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }

    /// Whether values are integers.
    pub(crate) fn is_integer(self) -> bool {
        !matches!(self, Scalar::F32 | Scalar::F64)
    }

    /// The largest value of an integer type (the value that means full intensity for
    /// a colour channel); 1 for floats.
    pub(crate) fn full_scale(self) -> f64 {
        match self {
            Scalar::I8 => i8::MAX as f64,
            Scalar::U8 => u8::MAX as f64,
            Scalar::I16 => i16::MAX as f64,
            Scalar::U16 => u16::MAX as f64,
            Scalar::I32 => i32::MAX as f64,
            Scalar::U32 => u32::MAX as f64,
            Scalar::F32 | Scalar::F64 => 1.0,
        }
    }

    /// Whether `v` is a value of this type (for ASCII bodies).
    pub(crate) fn holds(self, v: f64) -> bool {
        let range = |lo: f64, hi: f64| v.fract() == 0.0 && (lo..=hi).contains(&v);
        match self {
            Scalar::I8 => range(i8::MIN as f64, i8::MAX as f64),
            Scalar::U8 => range(0.0, u8::MAX as f64),
            Scalar::I16 => range(i16::MIN as f64, i16::MAX as f64),
            Scalar::U16 => range(0.0, u16::MAX as f64),
            Scalar::I32 => range(i32::MIN as f64, i32::MAX as f64),
            Scalar::U32 => range(0.0, u32::MAX as f64),
            Scalar::F32 | Scalar::F64 => true,
        }
    }
}

/// A property: a scalar, or a list with a count type and an item type.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Kind {
    Scalar(Scalar),
    List { count: Scalar, item: Scalar },
}

/// A named property of an element.
#[derive(Debug, Clone)]
pub(crate) struct Property {
    pub(crate) name: String,
    pub(crate) kind: Kind,
}

/// An element: a name, a count, properties.
#[derive(Debug, Clone)]
pub(crate) struct Element {
    pub(crate) name: String,
    pub(crate) count: u64,
    pub(crate) properties: Vec<Property>,
    /// The header line declaring it.
    pub(crate) line: u64,
}

impl Element {
    /// The smallest number of bytes one instance can take in a binary body.
    pub(crate) fn min_binary_size(&self) -> u64 {
        self.properties
            .iter()
            .map(|p| match p.kind {
                Kind::Scalar(s) => s.size() as u64,
                Kind::List { count, .. } => count.size() as u64,
            })
            .sum()
    }

    /// Position of the property named `name`, if any.
    pub(crate) fn find(&self, names: &[&str]) -> Option<usize> {
        self.properties
            .iter()
            .position(|p| names.contains(&p.name.as_str()))
    }
}

/// A parsed header.
#[derive(Debug)]
pub(crate) struct Header {
    pub(crate) encoding: Encoding,
    pub(crate) elements: Vec<Element>,
    /// Byte offset of the body.
    pub(crate) body_start: usize,
    /// Line number of the body's first line.
    pub(crate) body_line: u64,
}

/// Parses the header at the start of `bytes`.
pub(crate) fn parse(bytes: &[u8], path: &Path) -> Result<Header, LoadError> {
    let mut lines = Lines::new(bytes, path, false);
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    let first = lines.next_line().transpose()?;
    if !matches!(&first, Some((_, l)) if l.trim_ascii() == b"ply") {
        return Err(LoadError::syntax(
            path,
            1,
            "not a PLY file: the first line must be \"ply\"",
        ));
    }
    loop {
        let Some(next) = lines.next_line() else {
            return Err(LoadError::Truncated {
                at: super::super::Location::line(path, lines.next_number()),
                detail: "the header has no end_header line".into(),
            });
        };
        let (n, line) = next?;
        let mut toks = tokens(&line);
        let Some(key) = toks.next() else { continue };
        let err = |m: String| LoadError::syntax(path, n, m);
        match key {
            b"format" => {
                let e = match toks.next() {
                    Some(b"ascii") => Encoding::Ascii,
                    Some(b"binary_little_endian") => Encoding::LittleEndian,
                    Some(b"binary_big_endian") => Encoding::BigEndian,
                    other => {
                        return Err(err(format!(
                            "unknown PLY format {:?}",
                            lossy(other.unwrap_or_default())
                        )))
                    }
                };
                if toks.next() != Some(b"1.0") {
                    return Err(err("only PLY version 1.0 is read".into()));
                }
                encoding = Some(e);
            }
            b"comment" | b"obj_info" => {}
            b"element" => {
                let name = toks
                    .next()
                    .ok_or_else(|| err("element without a name".into()))?;
                let count = toks
                    .next()
                    .and_then(|t| std::str::from_utf8(t).ok()?.parse::<u64>().ok())
                    .ok_or_else(|| err("element count is not a non-negative integer".into()))?;
                elements.push(Element {
                    name: lossy(name),
                    count,
                    properties: Vec::new(),
                    line: n,
                });
            }
            b"property" => {
                let el = elements
                    .last_mut()
                    .ok_or_else(|| err("property before any element".into()))?;
                let ty = toks.next().unwrap_or_default();
                let scalar = |t: Option<&[u8]>| {
                    Scalar::parse(t.unwrap_or_default()).ok_or_else(|| {
                        err(format!(
                            "unknown property type {:?}",
                            lossy(t.unwrap_or_default())
                        ))
                    })
                };
                let kind = if ty == b"list" {
                    let count = scalar(toks.next())?;
                    if !count.is_integer() {
                        return Err(err("a list count must have an integer type".into()));
                    }
                    Kind::List {
                        count,
                        item: scalar(toks.next())?,
                    }
                } else {
                    Kind::Scalar(scalar(Some(ty))?)
                };
                let name = toks
                    .next()
                    .ok_or_else(|| err("property without a name".into()))?;
                el.properties.push(Property {
                    name: lossy(name),
                    kind,
                });
            }
            b"end_header" => break,
            other => return Err(err(format!("unknown header line {:?}", lossy(other)))),
        }
    }
    let encoding =
        encoding.ok_or_else(|| LoadError::syntax(path, 2, "the header has no format line"))?;
    let body_line = lines.next_number();
    Ok(Header {
        encoding,
        elements,
        body_start: bytes.len() - lines.remaining().len(),
        body_line,
    })
}
