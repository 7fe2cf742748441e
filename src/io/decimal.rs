//! Writing numbers as text, byte for byte as `write!(w, "{value}")` writes
//! them, without the formatter: the text writers spend most of their time
//! on the coordinates.

use std::io::Write;

use glam::DVec3;

/// The two-digit numbers 00 to 99, written out.
const PAIRS: &[u8; 200] = b"\
    0001020304050607080910111213141516171819\
    2021222324252627282930313233343536373839\
    4041424344454647484950515253545556575859\
    6061626364656667686970717273747576777879\
    8081828384858687888990919293949596979899";

/// Appends `value` in decimal, as `write!(w, "{value}")` does.
#[inline]
pub(crate) fn push_u64(w: &mut Vec<u8>, value: u64) {
    let mut digits = [b'0'; 20];
    let count = put_u64(&mut digits, 0, value);
    push_fixed(w, &digits, count);
}

/// Writes `value` in decimal into `out` from `at`, which has room for its
/// digits (20 at most); returns where the digits end.
#[inline]
pub(crate) fn put_u64(out: &mut [u8], at: usize, value: u64) -> usize {
    let count = value.checked_ilog10().unwrap_or(0) as usize + 1;
    let digits = &mut out[at..at + count];
    let (mut rest, mut end) = (value, count);
    while rest >= 10 {
        let pair = (rest % 100) as usize * 2;
        rest /= 100;
        end -= 2;
        digits[end..end + 2].copy_from_slice(&PAIRS[pair..pair + 2]);
    }
    if end == 1 {
        digits[0] = b'0' + rest as u8;
    }
    at + count
}

/// Appends `lead`, the coordinates of `p` between spaces, and the line's
/// end, as OFF's vertices and text STL's points are written.
pub(crate) fn push_point_line(w: &mut Vec<u8>, lead: &[u8], p: DVec3) {
    w.extend_from_slice(lead);
    push_f64(w, p.x);
    w.push(b' ');
    push_f64(w, p.y);
    w.push(b' ');
    push_f64(w, p.z);
    w.push(b'\n');
}

/// Appends the line of `face` as OFF and text PLY write it: its corner
/// count, then its 0-based vertex indices.
pub(crate) fn push_counted_face(w: &mut Vec<u8>, face: &[u32]) {
    push_u64(w, face.len() as u64);
    for &v in face {
        w.push(b' ');
        push_u64(w, v.into());
    }
    w.push(b'\n');
}

/// Appends the first `count` bytes of `bytes`: the whole array is copied
/// and the rest cut off again, which the compiler does with a few wide
/// moves instead of a call to copy a length it does not know.
#[inline]
pub(crate) fn push_fixed<const N: usize>(w: &mut Vec<u8>, bytes: &[u8; N], count: usize) {
    let len = w.len();
    w.extend_from_slice(bytes);
    w.truncate(len + count);
}

/// How `value` is written: zmij's text as it stands, zmij's text with an
/// exponent (at byte `e`) to lay out, or through the formatter.
enum Text<'a> {
    Plain(&'a [u8]),
    Exponent(&'a [u8], usize),
    Formatter,
}

#[inline]
fn text_of(buffer: &mut zmij::Buffer, value: f64) -> Text<'_> {
    if !value.is_finite() || may_be_a_tie(value) {
        // NaN and the infinities (which a mesh never holds), and doubles
        // halfway between two shortest decimals, which the formatter and
        // the shortest-digit algorithms may round differently.
        return Text::Formatter;
    }
    let text = buffer.format_finite(value).as_bytes();
    // zmij writes most numbers as `{}` does, but for a `.0` after integers:
    // `-5.0`, `0.25`, `1234.5678`. An exponent is `e` and at most four more
    // bytes (`e-324`): only the tail is searched.
    let tail = text.len().saturating_sub(5);
    match text[tail..].iter().position(|&c| c == b'e') {
        Some(e) => Text::Exponent(text, tail + e),
        None => Text::Plain(text.strip_suffix(b".0").unwrap_or(text)),
    }
}

/// Room [`put_f64`] needs: the longest text zmij writes without an
/// exponent (a sign, `0.0000` and 17 digits: 24 bytes) and one byte more.
pub(crate) const F64_ROOM: usize = 25;

/// Writes `value` as [`push_f64`] appends it into `out` from `at`, which
/// has [`F64_ROOM`] bytes of room, and returns where it ends; `None`, with
/// nothing written, for a value that needs more laying out (an exponent,
/// a tie, not finite), which [`push_f64`] writes.
#[inline]
pub(crate) fn put_f64(out: &mut [u8], at: usize, value: f64) -> Option<usize> {
    let mut buffer = zmij::Buffer::new();
    match text_of(&mut buffer, value) {
        Text::Plain(text) if text.len() <= F64_ROOM => {
            out[at..at + text.len()].copy_from_slice(text);
            Some(at + text.len())
        }
        _ => None,
    }
}

/// Appends `value` as `write!(w, "{value}")` does: the shortest digits that
/// read back as the same double, never in exponent form (`1e20` is written
/// `100000000000000000000`, `1.0` is `1`, `-0.0` is `-0`). The digits are
/// zmij's (Schubfach), which are the standard library's; only the layout is
/// done here.
pub(crate) fn push_f64(w: &mut Vec<u8>, value: f64) {
    let mut buffer = zmij::Buffer::new();
    let (text, e) = match text_of(&mut buffer, value) {
        Text::Plain(text) => {
            w.extend_from_slice(text);
            return;
        }
        Text::Exponent(text, e) => (text, e),
        Text::Formatter => {
            let _ = write!(w, "{value}");
            return;
        }
    };
    // Digits, maybe a point and digits, `e` and an exponent.
    let (mantissa, exponent) = (&text[..e], exponent_of(&text[e + 1..]));
    if value.is_sign_negative() {
        w.push(b'-');
    }
    let mantissa = mantissa.strip_prefix(b"-").unwrap_or(mantissa);
    let mut digits = [0u8; 24];
    let mut count = 0;
    let mut before_point = mantissa.len() as i32;
    for (i, &c) in mantissa.iter().enumerate() {
        if c == b'.' {
            before_point = i as i32;
        } else {
            digits[count] = c;
            count += 1;
        }
    }
    // The digits without leading or trailing zeros; `point` of them come
    // before the decimal point (none or fewer than none: zeros after it).
    let leading = digits[..count].iter().take_while(|&&d| d == b'0').count();
    let trailing = digits[leading..count]
        .iter()
        .rev()
        .take_while(|&&d| d == b'0')
        .count();
    let digits = &digits[leading..count - trailing];
    let point = before_point - leading as i32 + exponent;
    let len = digits.len() as i32;
    if point <= 0 {
        w.extend_from_slice(b"0.");
        w.extend(std::iter::repeat_n(b'0', (-point) as usize));
        w.extend_from_slice(digits);
    } else if point < len {
        w.extend_from_slice(&digits[..point as usize]);
        w.push(b'.');
        w.extend_from_slice(&digits[point as usize..]);
    } else {
        w.extend_from_slice(digits);
        w.extend(std::iter::repeat_n(b'0', (point - len) as usize));
    }
}

/// Whether `value` could lie exactly halfway between two decimals of its
/// shortest length, where the shortest-digit algorithms and the formatter
/// may choose differently. A tie is one digit longer than the shortest
/// form, so its exact decimal expansion has 16 to 18 significant digits
/// (`1690060720831323.25`, whose shortest forms end in 2 and 3): with 15 or
/// fewer, no shorter decimal reads back as the same double, and the exact
/// digits are the only shortest ones (integers, halves, the coordinates of
/// grids). Doubles with 16 to 18 exact digits are integers or have few
/// binary fraction digits; scanned and subdivided coordinates almost never do.
fn may_be_a_tie(value: f64) -> bool {
    // 16 to 18 digits (or fewer, with trailing zeros: counted as a maybe).
    const DIGITS: std::ops::Range<u128> = 1_000_000_000_000_000..1_000_000_000_000_000_000;
    let bits = value.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as i32;
    let fraction = bits & ((1 << 52) - 1);
    // value = ±mantissa · 2^power, the mantissa odd.
    let (mut mantissa, mut power) = match exponent {
        0 => (fraction, -1074),
        _ => (fraction | (1 << 52), exponent - 1075),
    };
    if mantissa == 0 {
        return false;
    }
    let zeros = mantissa.trailing_zeros();
    mantissa >>= zeros;
    power += zeros as i32;
    // The exact expansion's significant digits are those of mantissa · 2^power
    // (an integer) or of mantissa · 5^-power (its digits after the point).
    // 2^60 and 5^26 alone pass 1e18: most doubles stop here.
    if !(-25..60).contains(&power) {
        return false;
    }
    let digits = match power {
        0.. => 2u128.checked_pow(power as u32),
        _ => 5u128.checked_pow(power.unsigned_abs()),
    }
    .and_then(|scale| scale.checked_mul(mantissa as u128));
    digits.is_some_and(|n| DIGITS.contains(&n))
}

/// The exponent zmij wrote after its `e` (`e-7`, `e+16`).
fn exponent_of(text: &[u8]) -> i32 {
    let (sign, digits) = match text.split_first() {
        Some((b'-', rest)) => (-1, rest),
        Some((b'+', rest)) => (1, rest),
        _ => (1, text),
    };
    sign * digits
        .iter()
        .fold(0i32, |n, &d| n * 10 + i32::from(d - b'0'))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `push_f64`'s text, checked against `put_f64`'s wherever that writes.
    fn pushed(value: f64) -> String {
        let mut w = Vec::new();
        push_f64(&mut w, value);
        let mut room = [b'#'; 7 + F64_ROOM + 3];
        match put_f64(&mut room, 7, value) {
            Some(end) => assert_eq!(&room[7..end], &w[..], "{value:e}"),
            None => assert!(room.iter().all(|&b| b == b'#'), "{value:e}"),
        }
        String::from_utf8(w).unwrap()
    }

    #[test]
    fn doubles_without_an_exponent_are_put_in_place() {
        let mut room = [0u8; F64_ROOM];
        for value in [
            -4.9939024390243905,
            -0.000012345678901234567,
            -5.0,
            0.1,
            -0.0,
            123456789012345.6,
        ] {
            let end = put_f64(&mut room, 0, value).unwrap();
            assert_eq!(&room[..end], format!("{value}").as_bytes());
        }
        assert_eq!(put_f64(&mut room, 0, -5.0), Some(2));
        // Laid out from an exponent, ties and non-finite values are left
        // to `push_f64`.
        for value in [
            1e-7,
            1e20,
            -3.2e-17,
            1_690_060_720_831_323.0 + 0.25,
            f64::NAN,
        ] {
            assert_eq!(put_f64(&mut room, 0, value), None, "{value:e}");
        }
    }

    #[test]
    fn doubles_are_written_as_the_formatter_writes_them() {
        let named = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.1,
            0.3,
            2.0 / 3.0,
            1e-7,
            1.5e-7,
            123.456,
            1e15,
            1e16,
            1e20,
            1e21,
            1e22,
            1.2345e23,
            9007199254740993.0,
            // Halfway between 1690060720831323.2 and .3 (clippy would shorten the literal).
            1_690_060_720_831_323.0 + 0.25,
            5e-324,
            f64::MIN_POSITIVE,
            f64::MAX,
            f64::MIN,
            f64::EPSILON,
            1e300,
            1e-300,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for value in named {
            assert_eq!(pushed(value), format!("{value}"), "{value:e}");
        }
        // Every exponent and many mantissas: random bit patterns, and
        // decimals of a few digits as meshes hold them.
        let mut next = crate::test_random::words(0x9e37_79b9_7f4a_7c15u64);
        for _ in 0..400_000 {
            let value = f64::from_bits(next());
            assert_eq!(pushed(value), format!("{value}"), "{value:e}");
            let decimal = (next() % 2_000_001) as f64 / 1000.0 - 1000.0;
            assert_eq!(pushed(decimal), format!("{decimal}"));
        }
        // Integers, halves and grid steps, whose exact digits are short.
        for i in -300_000..300_000 {
            for value in [i as f64, i as f64 * 0.5, i as f64 * 0.125, i as f64 * 1e-3] {
                assert_eq!(pushed(value), format!("{value}"), "{value:e}");
            }
        }
        for power in 0..64 {
            for value in [2f64.powi(power), 10f64.powi(power / 3), 2f64.powi(-power)] {
                for value in [value, value - 1.0, value + 1.0, -value] {
                    assert_eq!(pushed(value), format!("{value}"), "{value:e}");
                }
            }
        }
        // Full mantissas with few binary fraction digits, or none, where
        // halfway doubles lie (and just past where they can).
        for power in -16..=16 {
            for _ in 0..20_000 {
                let mantissa = (next() >> 11) | (1 << 52);
                let value = mantissa as f64 * 2f64.powi(power);
                assert_eq!(pushed(value), format!("{value}"), "{value:e}");
            }
        }
    }

    #[test]
    fn integers_are_written_as_the_formatter_writes_them() {
        let mut values = vec![0, 1, 9, 10, 99, 100, 12345, u32::MAX as u64, u64::MAX];
        // Every digit count, and its first and last values.
        for digits in 1..20 {
            let first = 10u64.pow(digits);
            values.extend([first - 1, first, first + 1, first + first / 2 + 42]);
        }
        let mut next = crate::test_random::words(0x2545_f491_4f6c_dd1du64);
        for _ in 0..100_000 {
            let state = next();
            values.extend([state, state >> (state % 64), state % 10_000_000]);
        }
        for value in values {
            let mut w = b"f ".to_vec();
            push_u64(&mut w, value);
            assert_eq!(w, format!("f {value}").as_bytes());
        }
    }
}
