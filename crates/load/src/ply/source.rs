//! Reading property values from a PLY body, ASCII or binary, with bounds checks.

use std::path::Path;

use super::super::{LoadError, Location};
use super::header::{Encoding, Scalar};

/// Where values come from.
pub(crate) enum Source<'a> {
    /// ASCII: one element per line, values separated by whitespace.
    Ascii {
        rest: &'a [u8],
        /// The current line's unread part.
        line: &'a [u8],
        /// Number of the current line.
        number: u64,
        /// Lines that held values beyond those the header declares (ignored): how
        /// many, and the first.
        extra: (u64, u64),
    },
    /// Binary, of either byte order.
    Binary {
        data: &'a [u8],
        pos: usize,
        big: bool,
        /// The element being read and its 1-based number, for messages.
        record: (String, u64),
    },
}

impl<'a> Source<'a> {
    pub(crate) fn new(encoding: Encoding, body: &'a [u8], first_line: u64) -> Self {
        match encoding {
            Encoding::Ascii => Source::Ascii {
                rest: body,
                line: &[],
                number: first_line - 1,
                extra: (0, 0),
            },
            Encoding::LittleEndian | Encoding::BigEndian => Source::Binary {
                data: body,
                pos: 0,
                big: encoding == Encoding::BigEndian,
                record: (String::new(), 0),
            },
        }
    }

    /// Where the reader is, for messages.
    pub(crate) fn at(&self, path: &Path) -> Location {
        match self {
            Source::Ascii { number, .. } => Location::line(path, *number),
            Source::Binary { record, .. } => {
                Location::record(path, format!("{} {}", record.0, record.1))
            }
        }
    }

    /// Starts element instance `index` (0-based) of element `name`.
    pub(crate) fn begin(&mut self, name: &str, index: u64, path: &Path) -> Result<(), LoadError> {
        match self {
            Source::Ascii {
                rest, line, number, ..
            } => loop {
                if rest.is_empty() {
                    return Err(LoadError::Truncated {
                        at: Location::line(path, *number + 1),
                        detail: format!("{name} {} is missing", index + 1),
                    });
                }
                let (l, r) = match rest.iter().position(|&b| b == b'\n') {
                    Some(i) => (&rest[..i], &rest[i + 1..]),
                    None => (*rest, &rest[rest.len()..]),
                };
                *rest = r;
                *number += 1;
                if l.contains(&0) {
                    return Err(LoadError::NotText {
                        at: Location::line(path, *number),
                    });
                }
                if !l.trim_ascii().is_empty() {
                    *line = l;
                    return Ok(());
                }
            },
            Source::Binary { record, .. } => {
                record.0.clear();
                record.0.push_str(name);
                record.1 = index + 1;
                Ok(())
            }
        }
    }

    /// Ends an element instance. Values left on an ASCII line beyond those the header
    /// declares are ignored and counted (some writers append lists their header does
    /// not name; see [`Source::extra_values`]).
    pub(crate) fn end(&mut self) {
        if let Source::Ascii {
            line,
            number,
            extra,
            ..
        } = self
        {
            if !line.trim_ascii().is_empty() {
                if extra.0 == 0 {
                    extra.1 = *number;
                }
                extra.0 += 1;
            }
        }
    }

    /// How many ASCII lines held values beyond those the header declares, and the
    /// number of the first (`None` when there were none).
    pub(crate) fn extra_values(&self) -> Option<(u64, u64)> {
        match self {
            Source::Ascii { extra, .. } if extra.0 > 0 => Some(*extra),
            _ => None,
        }
    }

    /// Reads one value of type `ty`.
    pub(crate) fn scalar(&mut self, ty: Scalar, path: &Path) -> Result<f64, LoadError> {
        match self {
            Source::Ascii { line, number, .. } => {
                let l = line.trim_ascii_start();
                let end = l
                    .iter()
                    .position(|b| b.is_ascii_whitespace())
                    .unwrap_or(l.len());
                let (tok, rest) = l.split_at(end);
                *line = rest;
                if tok.is_empty() {
                    return Err(LoadError::syntax(
                        path,
                        *number,
                        "fewer values than the header declares",
                    ));
                }
                let v = super::super::text::parse_f64(tok)
                    .filter(|&v| ty.holds(v) && (v.is_finite() || !ty.is_integer()))
                    .ok_or_else(|| {
                        LoadError::syntax(
                            path,
                            *number,
                            format!(
                                "{:?} is not a value of type {ty:?}",
                                String::from_utf8_lossy(tok)
                            ),
                        )
                    })?;
                Ok(v)
            }
            Source::Binary { data, pos, big, .. } => {
                let size = ty.size();
                let Some(b) = data.get(*pos..*pos + size) else {
                    let at = self.at(path);
                    return Err(LoadError::Truncated {
                        at,
                        detail: format!("a {ty:?} value is cut off"),
                    });
                };
                *pos += size;
                let mut a = [0u8; 8];
                a[..size].copy_from_slice(b);
                if *big {
                    a[..size].reverse();
                }
                Ok(match ty {
                    Scalar::I8 => a[0] as i8 as f64,
                    Scalar::U8 => a[0] as f64,
                    Scalar::I16 => i16::from_le_bytes([a[0], a[1]]) as f64,
                    Scalar::U16 => u16::from_le_bytes([a[0], a[1]]) as f64,
                    Scalar::I32 => i32::from_le_bytes([a[0], a[1], a[2], a[3]]) as f64,
                    Scalar::U32 => u32::from_le_bytes([a[0], a[1], a[2], a[3]]) as f64,
                    Scalar::F32 => f32::from_le_bytes([a[0], a[1], a[2], a[3]]) as f64,
                    Scalar::F64 => f64::from_le_bytes(a),
                })
            }
        }
    }

    /// Bytes (binary) or lines (ASCII, an upper bound) left.
    pub(crate) fn room(&self) -> u64 {
        match self {
            Source::Ascii { rest, .. } => rest.iter().filter(|&&b| b == b'\n').count() as u64 + 1,
            Source::Binary { data, pos, .. } => (data.len() - *pos) as u64,
        }
    }

    /// Whether this is a binary body.
    pub(crate) fn is_binary(&self) -> bool {
        matches!(self, Source::Binary { .. })
    }

    /// Bytes left unread at the end (binary), for a warning.
    pub(crate) fn trailing(&self) -> usize {
        match self {
            Source::Ascii { rest, .. } => {
                if rest.trim_ascii().is_empty() {
                    0
                } else {
                    rest.len()
                }
            }
            Source::Binary { data, pos, .. } => data.len() - *pos,
        }
    }
}
