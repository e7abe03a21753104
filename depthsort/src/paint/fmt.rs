//! Byte-level writing shared by the text backends: numbers, colours, XML escaping and a
//! buffered, counting sink.
//!
//! Numbers are formatted by hand rather than with `write!`: this is the inner loop of
//! every vector backend (two numbers per point) and the hand-written path is several
//! times faster, with the same output every time.

use std::io::Write;

/// The largest number of decimals a backend accepts; larger settings are clamped to it.
pub(crate) const MAX_DECIMALS: u8 = 9;

const POW10: [u64; 10] = [
    1,
    10,
    100,
    1_000,
    10_000,
    100_000,
    1_000_000,
    10_000_000,
    100_000_000,
    1_000_000_000,
];

/// Below this magnitude a scaled value converts exactly to an integer (2^53).
const EXACT_INT: f64 = 9_007_199_254_740_992.0;

/// Appends the decimal digits of `v`.
pub(crate) fn push_uint(buf: &mut Vec<u8>, mut v: u64) {
    let mut digits = [0u8; 20];
    let mut i = digits.len();
    loop {
        i -= 1;
        digits[i] = b'0' + (v % 10) as u8;
        v /= 10;
        if v == 0 {
            break;
        }
    }
    buf.extend_from_slice(&digits[i..]);
}

/// Appends `v` rounded to at most `decimals` decimals (clamped to [`MAX_DECIMALS`]):
/// trailing zeros and a bare decimal point are trimmed, a result that rounds to zero is
/// `0` (never `-0`), and no exponent is ever used. Rounding is half away from zero on
/// `v · 10^decimals`. Non-finite values (which validated input never holds) are written
/// as `0`.
pub(crate) fn push_num(buf: &mut Vec<u8>, v: f64, decimals: u8) {
    let decimals = decimals.min(MAX_DECIMALS);
    let scale = POW10[usize::from(decimals)];
    let scaled = (v * scale as f64).round();
    if !scaled.is_finite() {
        buf.push(b'0');
        return;
    }
    if scaled.abs() >= EXACT_INT {
        push_num_slow(buf, v, decimals);
        return;
    }
    if scaled == 0.0 {
        buf.push(b'0');
        return;
    }
    if scaled < 0.0 {
        buf.push(b'-');
    }
    // Exact: |scaled| < 2^53 is an integer.
    let n = scaled.abs() as u64;
    push_uint(buf, n / scale);
    let mut frac = n % scale;
    if frac == 0 {
        return;
    }
    let mut width = usize::from(decimals);
    while frac.is_multiple_of(10) {
        frac /= 10;
        width -= 1;
    }
    buf.push(b'.');
    let mut digits = [b'0'; MAX_DECIMALS as usize];
    let mut i = width;
    while frac > 0 {
        i -= 1;
        digits[i] = b'0' + (frac % 10) as u8;
        frac /= 10;
    }
    buf.extend_from_slice(&digits[..width]);
}

/// Large magnitudes: Rust's exact decimal expansion, trimmed the same way.
#[cold]
fn push_num_slow(buf: &mut Vec<u8>, v: f64, decimals: u8) {
    let start = buf.len();
    // Writing to a Vec cannot fail.
    let _ = write!(buf, "{:.*}", usize::from(decimals), v);
    if buf[start..].contains(&b'.') {
        while buf.last() == Some(&b'0') {
            buf.pop();
        }
        if buf.last() == Some(&b'.') {
            buf.pop();
        }
    }
}

/// A colour channel as 8 bits: `round(clamp(c, 0, 1) · 255)`.
pub(crate) fn channel_u8(c: f64) -> u8 {
    // NaN clamps to NaN, which `as` turns into 0.
    (c.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// Three channels as 8 bits each.
pub(crate) fn rgb_u8(c: [f64; 3]) -> [u8; 3] {
    [channel_u8(c[0]), channel_u8(c[1]), channel_u8(c[2])]
}

/// An opacity in thousandths: `round(clamp(a, 0, 1) · 1000)`.
pub(crate) fn alpha_milli(a: f64) -> u16 {
    (a.clamp(0.0, 1.0) * 1000.0).round() as u16
}

/// A colour channel quantised to `decimals` decimals, as the integer that is written.
pub(crate) fn channel_fixed(c: f64, decimals: u8) -> u32 {
    let scale = POW10[usize::from(decimals.min(MAX_DECIMALS))] as f64;
    (c.clamp(0.0, 1.0) * scale).round() as u32
}

/// Appends `#rrggbb` (lower-case hex).
pub(crate) fn push_hex_color(buf: &mut Vec<u8>, c: [u8; 3]) {
    const HEX: &[u8; 16] = b"0123456789abcdef";
    buf.push(b'#');
    for v in c {
        buf.push(HEX[usize::from(v >> 4)]);
        buf.push(HEX[usize::from(v & 15)]);
    }
}

/// Appends a thousandths value as a decimal fraction (`500` → `0.5`).
pub(crate) fn push_milli(buf: &mut Vec<u8>, m: u16) {
    push_num(buf, f64::from(m) / 1000.0, 3);
}

/// Appends a fixed-point colour channel from [`channel_fixed`].
pub(crate) fn push_fixed(buf: &mut Vec<u8>, q: u32, decimals: u8) {
    let decimals = decimals.min(MAX_DECIMALS);
    push_num(
        buf,
        f64::from(q) / POW10[usize::from(decimals)] as f64,
        decimals,
    );
}

/// Appends `s` escaped for an XML attribute value in double quotes.
///
/// `& < > " '` become entities; tab, line feed and carriage return become character
/// references so that attribute normalisation keeps them; other characters that XML 1.0
/// forbids (C0 controls, U+FFFE, U+FFFF) become U+FFFD. Everything else, non-ASCII
/// included, is written as UTF-8.
pub(crate) fn push_xml_attr(buf: &mut Vec<u8>, s: &str) {
    for ch in s.chars() {
        match ch {
            '&' => buf.extend_from_slice(b"&amp;"),
            '<' => buf.extend_from_slice(b"&lt;"),
            '>' => buf.extend_from_slice(b"&gt;"),
            '"' => buf.extend_from_slice(b"&quot;"),
            '\'' => buf.extend_from_slice(b"&apos;"),
            '\t' => buf.extend_from_slice(b"&#9;"),
            '\n' => buf.extend_from_slice(b"&#10;"),
            '\r' => buf.extend_from_slice(b"&#13;"),
            '\u{0}'..='\u{1f}' | '\u{fffe}' | '\u{ffff}' => {
                buf.extend_from_slice("\u{fffd}".as_bytes());
            }
            _ => {
                let mut utf8 = [0u8; 4];
                buf.extend_from_slice(ch.encode_utf8(&mut utf8).as_bytes());
            }
        }
    }
}

/// A buffer in front of the output that flushes in large blocks and counts bytes.
pub(crate) struct Sink<'w> {
    out: &'w mut dyn Write,
    /// Pending bytes; backends append to it directly.
    pub buf: Vec<u8>,
    written: u64,
}

const FLUSH_AT: usize = 1 << 16;

impl<'w> Sink<'w> {
    /// A sink writing to `out`.
    pub fn new(out: &'w mut dyn Write) -> Self {
        Sink {
            out,
            buf: Vec::with_capacity(FLUSH_AT + 4096),
            written: 0,
        }
    }

    /// Writes the buffer out if it is large.
    pub fn maybe_flush(&mut self) -> std::io::Result<()> {
        if self.buf.len() >= FLUSH_AT {
            self.flush_buf()?;
        }
        Ok(())
    }

    fn flush_buf(&mut self) -> std::io::Result<()> {
        self.out.write_all(&self.buf)?;
        self.written += self.buf.len() as u64;
        self.buf.clear();
        Ok(())
    }

    /// Writes everything out, flushes the output and returns the bytes written.
    pub fn finish(mut self) -> std::io::Result<u64> {
        self.flush_buf()?;
        self.out.flush()?;
        Ok(self.written)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn num(v: f64, d: u8) -> String {
        let mut b = Vec::new();
        push_num(&mut b, v, d);
        String::from_utf8(b).unwrap()
    }

    #[test]
    fn numbers_are_trimmed_and_never_negative_zero() {
        assert_eq!(num(0.0, 2), "0");
        assert_eq!(num(-0.0, 2), "0");
        assert_eq!(num(-0.004, 2), "0");
        assert_eq!(num(-0.005, 2), "-0.01");
        assert_eq!(num(1.5, 2), "1.5");
        assert_eq!(num(1.25, 1), "1.3");
        assert_eq!(num(10.0, 2), "10");
        assert_eq!(num(1920.0, 0), "1920");
        assert_eq!(num(0.05, 2), "0.05");
        assert_eq!(num(-3.10, 3), "-3.1");
        assert_eq!(num(123.456789, 9), "123.456789");
        assert_eq!(num(2.675, 2), "2.68"); // the product 2.675 · 100 rounds to 267.5
        assert_eq!(num(7.0, 200), "7");
        assert_eq!(num(f64::NAN, 2), "0");
        assert_eq!(num(f64::INFINITY, 2), "0");
    }

    #[test]
    fn huge_numbers_have_no_exponent() {
        assert_eq!(num(1e20, 2), "100000000000000000000");
        assert_eq!(num(-1e17, 3), "-100000000000000000");
        let s = num(1e300, 2);
        assert_eq!(s.len(), 301);
        assert!(!s.contains('e'));
    }

    #[test]
    fn integers() {
        for v in [0u64, 7, 10, 99, 100, 12345, u64::MAX] {
            let mut b = Vec::new();
            push_uint(&mut b, v);
            assert_eq!(String::from_utf8(b).unwrap(), v.to_string());
        }
    }

    #[test]
    fn colours() {
        assert_eq!(rgb_u8([0.2, 0.4, 0.6]), [51, 102, 153]);
        assert_eq!(rgb_u8([-1.0, 2.0, f64::NAN]), [0, 255, 0]);
        let mut b = Vec::new();
        push_hex_color(&mut b, [51, 102, 255]);
        assert_eq!(b, b"#3366ff");
        assert_eq!(alpha_milli(0.5), 500);
        assert_eq!(alpha_milli(0.99951), 1000);
        assert_eq!(channel_fixed(0.2, 4), 2000);
        let mut b = Vec::new();
        push_fixed(&mut b, 2000, 4);
        assert_eq!(b, b"0.2");
    }

    #[test]
    fn xml_escaping() {
        let mut b = Vec::new();
        push_xml_attr(&mut b, "a<&\"'>\tß\u{1}𝄞");
        assert_eq!(
            String::from_utf8(b).unwrap(),
            "a&lt;&amp;&quot;&apos;&gt;&#9;ß\u{fffd}𝄞"
        );
    }
}
