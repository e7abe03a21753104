//! Helpers shared by the text parsers: numbered lines, tokens, numbers, and a small
//! hasher for deduplicating vertices by their exact bits.

use std::borrow::Cow;
use std::hash::{BuildHasherDefault, Hasher};
use std::path::Path;

use super::{LoadError, Location};

/// A logical line and its 1-based number.
pub(crate) type NumberedLine<'a> = (u64, Cow<'a, [u8]>);

/// Lines of a text file with their 1-based numbers. A trailing `\r` is removed, and a
/// line ending in a backslash is joined with the next one (as OBJ and MTL allow); the
/// joined line carries the number of its first physical line. A line holding a NUL byte
/// is reported as binary data.
pub(crate) struct Lines<'a> {
    rest: &'a [u8],
    next_line: u64,
    path: &'a Path,
    join_backslash: bool,
    /// Whether the bytes hold a NUL at all (one SIMD pass over them): lines are looked
    /// into one by one only when they do.
    holds_nul: bool,
}

impl<'a> Lines<'a> {
    pub(crate) fn new(bytes: &'a [u8], path: &'a Path, join_backslash: bool) -> Self {
        Self::starting_at(bytes, path, join_backslash, 1)
    }

    /// Lines of `bytes`, the first numbered `first` (a part of a file that starts a line).
    pub(crate) fn starting_at(
        bytes: &'a [u8],
        path: &'a Path,
        join_backslash: bool,
        first: u64,
    ) -> Self {
        Lines {
            rest: bytes,
            next_line: first,
            path,
            join_backslash,
            holds_nul: memchr::memchr(0, bytes).is_some(),
        }
    }

    /// The number the next line will have.
    pub(crate) fn next_number(&self) -> u64 {
        self.next_line
    }

    /// The bytes not yet returned.
    pub(crate) fn remaining(&self) -> &'a [u8] {
        self.rest
    }

    fn physical(&mut self) -> Option<&'a [u8]> {
        if self.rest.is_empty() {
            return None;
        }
        let (line, rest) = match memchr::memchr(b'\n', self.rest) {
            Some(i) => (&self.rest[..i], &self.rest[i + 1..]),
            None => (self.rest, &self.rest[self.rest.len()..]),
        };
        self.rest = rest;
        self.next_line += 1;
        Some(line.strip_suffix(b"\r").unwrap_or(line))
    }

    /// The next logical line and its number.
    pub(crate) fn next_line(&mut self) -> Option<Result<NumberedLine<'a>, LoadError>> {
        let number = self.next_line;
        let first = self.physical()?;
        let mut line = Cow::Borrowed(first);
        while self.join_backslash && line.last() == Some(&b'\\') {
            let mut joined = line.into_owned();
            joined.pop();
            joined.push(b' ');
            match self.physical() {
                Some(more) => joined.extend_from_slice(more),
                None => {
                    line = Cow::Owned(joined);
                    break;
                }
            }
            line = Cow::Owned(joined);
        }
        if self.holds_nul && line.contains(&0) {
            return Some(Err(LoadError::NotText {
                at: Location::line(self.path, number),
            }));
        }
        Some(Ok((number, line)))
    }
}

/// The part of a line before a `#` comment.
pub(crate) fn strip_comment(line: &[u8]) -> &[u8] {
    match memchr::memchr(b'#', line) {
        Some(i) => &line[..i],
        None => line,
    }
}

/// Whitespace-separated tokens.
pub(crate) fn tokens(line: &[u8]) -> Tokens<'_> {
    Tokens { rest: line }
}

/// The iterator of [`tokens`]: runs of bytes other than ASCII whitespace.
pub(crate) struct Tokens<'a> {
    rest: &'a [u8],
}

impl<'a> Tokens<'a> {
    /// What follows the tokens taken so far, trimmed: after a statement's keyword, the
    /// rest of its line (for names that may hold spaces).
    pub(crate) fn remainder(&self) -> &'a [u8] {
        self.rest.trim_ascii()
    }
}

impl<'a> Iterator for Tokens<'a> {
    type Item = &'a [u8];

    fn next(&mut self) -> Option<&'a [u8]> {
        let start = self.rest.iter().position(|b| !b.is_ascii_whitespace())?;
        let rest = &self.rest[start..];
        let end = rest
            .iter()
            .position(|b| b.is_ascii_whitespace())
            .unwrap_or(rest.len());
        self.rest = &rest[end..];
        Some(&rest[..end])
    }
}

/// Text for messages and names (invalid UTF-8 replaced).
pub(crate) fn lossy(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// Parses a float token; `None` when it is not a number. NaN and infinities parse (the
/// caller reports them as non-finite, which is a clearer message).
///
/// The syntax is Rust's `f64::from_str` (an optional sign, digits with an optional
/// point and exponent, `inf`, `infinity`, `nan` in any case) and so is the value, the
/// correctly rounded one; the bytes are read by `fast_float2`, without the UTF-8 check
/// and with faster digit loops (tested against the standard parser on generated tokens).
pub(crate) fn parse_f64(token: &[u8]) -> Option<f64> {
    fast_float2::parse::<f64, _>(token).ok()
}

/// Parses a float token or reports a syntax error naming `what`.
pub(crate) fn number(
    path: &Path,
    line: u64,
    token: Option<&[u8]>,
    what: &str,
) -> Result<f64, LoadError> {
    match token {
        None => Err(LoadError::syntax(path, line, format!("missing {what}"))),
        Some(t) => parse_f64(t).ok_or_else(|| {
            LoadError::syntax(
                path,
                line,
                format!("{what}: {:?} is not a number", lossy(t)),
            )
        }),
    }
}

/// Parses a signed decimal integer token.
pub(crate) fn parse_i64(token: &[u8]) -> Option<i64> {
    let (neg, digits) = match token.first()? {
        b'-' => (true, &token[1..]),
        b'+' => (false, &token[1..]),
        _ => (false, token),
    };
    if digits.is_empty() {
        return None;
    }
    let mut v: i64 = 0;
    for &d in digits {
        if !d.is_ascii_digit() {
            return None;
        }
        v = v.checked_mul(10)?.checked_add((d - b'0') as i64)?;
    }
    Some(if neg { -v } else { v })
}

/// A fast, deterministic hasher for keys made of a few integers (vertex positions by
/// bits). Inputs are our own parsed numbers; the worst case of an adversarial file is a
/// slower load, never a wrong one.
#[derive(Default, Clone, Copy)]
pub(crate) struct BitsHasher(u64);

impl Hasher for BitsHasher {
    fn finish(&self) -> u64 {
        // murmur3's finaliser: coordinates read from f32 have 29 zero low bits, and the
        // table indexes by the low bits, so they must depend on every input bit.
        let mut h = self.0;
        h ^= h >> 33;
        h = h.wrapping_mul(0xff51_afd7_ed55_8ccd);
        h ^= h >> 33;
        h = h.wrapping_mul(0xc4ce_b9fe_1a85_ec53);
        h ^ (h >> 33)
    }
    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(8) {
            let mut b = [0u8; 8];
            b[..chunk.len()].copy_from_slice(chunk);
            self.write_u64(u64::from_le_bytes(b));
        }
    }
    fn write_u64(&mut self, n: u64) {
        self.0 = (self.0.rotate_left(5) ^ n).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
}

/// Hash map keyed by bit patterns.
pub(crate) type BitsMap<K, V> = std::collections::HashMap<K, V, BuildHasherDefault<BitsHasher>>;

/// The key of a position for deduplication: its bits, with −0 folded into +0.
pub(crate) fn position_key(p: [f64; 3]) -> [u64; 3] {
    p.map(|c| (c + 0.0).to_bits())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_are_numbered_and_joined() {
        let path = Path::new("x.obj");
        let mut l = Lines::new(b"a\r\nb \\\nc\n\nd", path, true);
        let mut got = Vec::new();
        while let Some(r) = l.next_line() {
            let (n, s) = r.unwrap();
            got.push((n, lossy(&s)));
        }
        assert_eq!(
            got,
            vec![
                (1, "a".to_string()),
                (2, "b  c".to_string()),
                (4, String::new()),
                (5, "d".to_string())
            ]
        );
    }

    #[test]
    fn nul_is_binary() {
        let path = Path::new("x.obj");
        let mut l = Lines::new(b"ok\nv 1\0 2\n", path, true);
        assert!(l.next_line().unwrap().is_ok());
        let e = l.next_line().unwrap().unwrap_err();
        assert!(matches!(e, LoadError::NotText { ref at } if at.line == Some(2)));
    }

    #[test]
    fn the_remainder_after_a_keyword_is_the_rest_after_it() {
        for (line, rest) in [
            (&b"usemtl  a b \t"[..], &b"a b"[..]),
            (b"  o x", b"x"),
            (b"g", b""),
            (b"mtllib\tone two.mtl ", b"one two.mtl"),
            (b"newmtl \xe2\x82 x\r", b"\xe2\x82 x"),
            (b"", b""),
        ] {
            let mut toks = tokens(line);
            toks.next();
            assert_eq!(toks.remainder(), rest, "{line:?}");
        }
    }

    #[test]
    fn tokens_split_at_any_ascii_whitespace() {
        let got: Vec<String> = tokens(b" \tf  1/2\x0c3 \r").map(lossy).collect();
        assert_eq!(got, ["f", "1/2", "3"]);
        assert_eq!(tokens(b" \t ").next(), None);
        assert_eq!(tokens(b"").next(), None);
    }

    /// The standard parser's reading of a token, the reference of [`parse_f64`].
    fn standard(token: &[u8]) -> Option<f64> {
        std::str::from_utf8(token).ok()?.parse::<f64>().ok()
    }

    /// Same acceptance, same bits (NaN compared as NaN).
    fn agrees(token: &[u8]) -> bool {
        match (parse_f64(token), standard(token)) {
            (None, None) => true,
            (Some(a), Some(b)) => a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
            _ => false,
        }
    }

    #[test]
    fn floats_read_as_the_standard_parser_reads_them() {
        for t in [
            "0",
            "-0",
            "+0",
            "1",
            "+1.5",
            "-2.25e-3",
            "1.",
            ".5",
            "-.5",
            "+.5e2",
            ".",
            "-.",
            "e5",
            "1e",
            "1e+",
            "1e-",
            "1E+05",
            "1e400",
            "-1e400",
            "1e-400",
            "4.9e-324",
            "2.4703282292062328e-324",
            "2.4703282292062327e-324",
            "1.7976931348623157e308",
            "1.7976931348623159e308",
            "0.1",
            "0.30000000000000004",
            "9007199254740993",
            "123456789012345678901234567890e-10",
            "inf",
            "-inf",
            "+Inf",
            "INFINITY",
            "infinity",
            "infin",
            "nan",
            "NaN",
            "-nan",
            "+NAN",
            "nana",
            "1..2",
            "1.2.3",
            "--1",
            "+-1",
            "1_000",
            "0x10",
            "1e5x",
            " 1",
            "1 ",
            "",
            "١",
        ] {
            assert!(
                agrees(t.as_bytes()),
                "{t:?}: {:?} against {:?}",
                parse_f64(t.as_bytes()),
                standard(t.as_bytes())
            );
        }
        assert!(agrees(&[b'1', 0xff]));
    }

    proptest::proptest! {
        #[test]
        fn generated_floats_read_as_the_standard_parser_reads_them(
            t in "[-+]?[0-9]{0,20}([.][0-9]{0,20})?([eE][-+]?[0-9]{0,4})?"
        ) {
            proptest::prop_assert!(agrees(t.as_bytes()), "{:?}", t);
        }

        #[test]
        fn any_short_token_reads_as_the_standard_parser_reads_it(
            t in "[-+.0-9eEinfatyINFATY]{0,12}"
        ) {
            proptest::prop_assert!(agrees(t.as_bytes()), "{:?}", t);
        }
    }

    #[test]
    fn integers() {
        assert_eq!(parse_i64(b"-12"), Some(-12));
        assert_eq!(parse_i64(b"+7"), Some(7));
        assert_eq!(parse_i64(b"-"), None);
        assert_eq!(parse_i64(b"1x"), None);
        assert_eq!(parse_i64(b"99999999999999999999"), None);
    }
}
