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

/// `x` rounded half away from zero, for |x| < 2^53 (what `f64::round` does, without the
/// library call that baseline x86-64 needs for it).
#[inline]
pub(crate) fn round_i64(x: f64) -> i64 {
    let i = x as i64;
    // Exact: x − trunc(x) has no rounding error below 2^53. Written without branches:
    // colours and coordinates are random enough to defeat branch prediction.
    let frac = x - i as f64;
    i + i64::from(frac >= 0.5) - i64::from(frac <= -0.5)
}

/// Appends `v` rounded to at most `decimals` decimals (clamped to [`MAX_DECIMALS`]):
/// trailing zeros and a bare decimal point are trimmed, a result that rounds to zero is
/// `0` (never `-0`), and no exponent is ever used. Rounding is half away from zero on
/// `v · 10^decimals`. Non-finite values (which validated input never holds) are written
/// as `0`.
pub(crate) fn push_num(buf: &mut Vec<u8>, v: f64, decimals: u8) {
    let decimals = decimals.min(MAX_DECIMALS);
    let scaled = v * POW10[usize::from(decimals)] as f64;
    if scaled.is_nan() || scaled.abs() >= EXACT_INT {
        push_num_slow(buf, v, decimals);
        return;
    }
    push_scaled(buf, round_i64(scaled), decimals);
}

/// `v · 10^decimals` as [`push_num`] computes it before rounding it; `None` where
/// [`push_num`] takes its slow path (NaN, or beyond 2^53 once scaled).
pub(crate) fn scaled(v: f64, decimals: u8) -> Option<f64> {
    let scaled = v * POW10[usize::from(decimals.min(MAX_DECIMALS))] as f64;
    (!scaled.is_nan() && scaled.abs() < EXACT_INT).then_some(scaled)
}

/// `v · 10^decimals` rounded as [`push_num`] rounds it (half away from zero), the number
/// [`push_scaled`] then writes as [`push_num`] writes `v`; `None` where [`push_num`]
/// takes its slow path (NaN, or beyond 2^53 once scaled).
pub(crate) fn round_scaled(v: f64, decimals: u8) -> Option<i64> {
    scaled(v, decimals).map(round_i64)
}

/// "00" to "99".
const PAIRS: &[u8; 200] = b"00010203040506070809\
                            10111213141516171819\
                            20212223242526272829\
                            30313233343536373839\
                            40414243444546474849\
                            50515253545556575859\
                            60616263646566676869\
                            70717273747576777879\
                            80818283848586878889\
                            90919293949596979899";

/// Writes the `width` lowest decimal digits of `v` so that they end at `tmp[end]`.
#[inline]
fn put_digits(tmp: &mut [u8], end: usize, mut v: u64, width: usize) {
    let mut i = end;
    let stop = end - width;
    while i >= stop + 2 {
        let pair = (v % 100) as usize * 2;
        v /= 100;
        tmp[i - 2] = PAIRS[pair];
        tmp[i - 1] = PAIRS[pair + 1];
        i -= 2;
    }
    if i > stop {
        tmp[i - 1] = b'0' + (v % 10) as u8;
    }
}

/// Appends `n / 10^decimals` (`decimals` at most [`MAX_DECIMALS`], |n| < 2^53) in the
/// format of [`push_num`].
pub(crate) fn push_scaled(buf: &mut Vec<u8>, n: i64, decimals: u8) {
    if n == 0 {
        buf.push(b'0');
        return;
    }
    let u = n.unsigned_abs();
    // Constant divisors for the usual settings: a multiplication instead of a division.
    let (int, mut frac) = match decimals {
        0 => (u, 0),
        2 => (u / 100, u % 100),
        3 => (u / 1000, u % 1000),
        4 => (u / 10_000, u % 10_000),
        _ => {
            let scale = POW10[usize::from(decimals.min(MAX_DECIMALS))];
            (u / scale, u % scale)
        }
    };
    let mut frac_width = 0;
    if frac != 0 {
        frac_width = usize::from(decimals);
        while frac.is_multiple_of(10) {
            frac /= 10;
            frac_width -= 1;
        }
    }
    let mut int_width = 1;
    let mut t = int;
    while t >= 10 {
        t /= 10;
        int_width += 1;
    }
    // At most 16 digits (|n| < 2^53), a sign and a point.
    let sign = usize::from(n < 0);
    let len = sign + int_width + if frac_width > 0 { frac_width + 1 } else { 0 };
    let mut tmp = [b'-'; 24];
    if frac_width > 0 {
        put_digits(&mut tmp, len, frac, frac_width);
        tmp[len - frac_width - 1] = b'.';
    }
    put_digits(&mut tmp, sign + int_width, int, int_width);
    // A fixed-size copy compiles to a few moves, where a variable one calls memmove.
    let old = buf.len();
    buf.extend_from_slice(&tmp);
    buf.truncate(old + len);
}

/// Large magnitudes: Rust's exact decimal expansion, trimmed the same way.
#[cold]
fn push_num_slow(buf: &mut Vec<u8>, v: f64, decimals: u8) {
    if !v.is_finite() {
        buf.push(b'0');
        return;
    }
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
    round_i64(c.clamp(0.0, 1.0) * 255.0) as u8
}

/// Three channels as 8 bits each.
pub(crate) fn rgb_u8(c: [f64; 3]) -> [u8; 3] {
    [channel_u8(c[0]), channel_u8(c[1]), channel_u8(c[2])]
}

/// An opacity in thousandths: `round(clamp(a, 0, 1) · 1000)`.
pub(crate) fn alpha_milli(a: f64) -> u16 {
    round_i64(a.clamp(0.0, 1.0) * 1000.0) as u16
}

/// A colour channel quantised to `decimals` decimals, as the integer that is written.
pub(crate) fn channel_fixed(c: f64, decimals: u8) -> u32 {
    let scale = POW10[usize::from(decimals.min(MAX_DECIMALS))] as f64;
    round_i64(c.clamp(0.0, 1.0) * scale) as u32
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

    /// The plain way to write a number, as a reference for the fast one.
    fn reference(v: f64, d: u8) -> String {
        let scale = 10f64.powi(i32::from(d));
        let n = (v * scale).round();
        if n == 0.0 {
            return "0".to_string();
        }
        let s = format!("{:.*}", usize::from(d), n / scale);
        let s = if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.')
        } else {
            &s
        };
        s.to_string()
    }

    proptest::proptest! {
        #[test]
        fn fast_rounding_matches_the_library(x in -9.0e15..9.0e15f64) {
            proptest::prop_assert_eq!(round_i64(x), x.round() as i64);
        }

        #[test]
        fn fast_numbers_match_the_reference(v in -1.0e6..1.0e6f64, d in 0u8..7) {
            proptest::prop_assert_eq!(num(v, d), reference(v, d));
        }

        #[test]
        fn numbers_round_trip_within_half_a_unit(v in -1.0e9..1.0e9f64, d in 0u8..10) {
            let s = num(v, d);
            let back: f64 = s.parse().unwrap();
            let unit = 10f64.powi(-i32::from(d));
            proptest::prop_assert!((back - v).abs() <= unit * 0.5 + v.abs() * 1e-15);
            proptest::prop_assert!(s != "-0" && !s.ends_with('.'));
            proptest::prop_assert!(!s.contains('.') || !s.ends_with('0'));
        }
    }

    #[test]
    fn ties_round_away_from_zero() {
        for x in [
            0.5,
            1.5,
            2.5,
            -0.5,
            -2.5,
            0.49999999999999994,
            4503599627370495.5,
        ] {
            assert_eq!(round_i64(x), x.round() as i64, "{x}");
        }
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
