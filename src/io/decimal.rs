//! Writing numbers as text, byte for byte as `write!(w, "{value}")` writes
//! them, without the formatter: the text writers spend most of their time
//! on the coordinates.

use std::io::Write;

/// Appends `value` in decimal, as `write!(w, "{value}")` does.
#[inline]
pub(crate) fn push_u64(w: &mut Vec<u8>, mut value: u64) {
    let mut digits = [0u8; 20];
    let mut at = digits.len();
    loop {
        at -= 1;
        digits[at] = b'0' + (value % 10) as u8;
        value /= 10;
        if value == 0 {
            break;
        }
    }
    w.extend_from_slice(&digits[at..]);
}

/// Appends `value` as `write!(w, "{value}")` does: the shortest digits that
/// read back as the same double, never in exponent form (`1e20` is written
/// `100000000000000000000`, `1.0` is `1`, `-0.0` is `-0`). The digits are
/// ryu's, which are the standard library's; only the layout is done here.
pub(crate) fn push_f64(w: &mut Vec<u8>, value: f64) {
    if !value.is_finite() || may_be_a_tie(value) {
        // NaN and the infinities (which a mesh never holds), and doubles
        // halfway between two shortest decimals, which the formatter and
        // ryu round differently: through the formatter.
        let _ = write!(w, "{value}");
        return;
    }
    if value.is_sign_negative() {
        w.push(b'-');
    }
    if value == 0.0 {
        w.push(b'0');
        return;
    }
    let mut buffer = ryu::Buffer::new();
    let text = buffer.format_finite(value.abs()).as_bytes();
    // ryu writes digits, a point and digits, then maybe `e` and an exponent.
    let (mantissa, exponent) = match text.iter().position(|&c| c == b'e') {
        Some(e) => (&text[..e], exponent_of(&text[e + 1..])),
        None => (text, 0),
    };
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
/// shortest length, where ryu and the formatter choose differently: only a
/// double whose exact decimal expansion has at most 18 significant digits
/// can (`1690060720831323.25`, whose shortest forms end in 2 and 3). Such
/// doubles are integers below 1e18 or have few binary fraction digits;
/// the coordinates of scanned and subdivided meshes almost never are.
fn may_be_a_tie(value: f64) -> bool {
    const LIMIT: u128 = 1_000_000_000_000_000_000;
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
    let digits = match power {
        0.. => 2u128.checked_pow(power as u32),
        _ => 5u128.checked_pow(power.unsigned_abs()),
    }
    .and_then(|scale| scale.checked_mul(mantissa as u128));
    digits.is_some_and(|n| n < LIMIT)
}

/// The exponent ryu wrote after its `e`.
fn exponent_of(text: &[u8]) -> i32 {
    let (sign, digits) = match text.split_first() {
        Some((b'-', rest)) => (-1, rest),
        _ => (1, text),
    };
    sign * digits
        .iter()
        .fold(0i32, |n, &d| n * 10 + i32::from(d - b'0'))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pushed(value: f64) -> String {
        let mut w = Vec::new();
        push_f64(&mut w, value);
        String::from_utf8(w).unwrap()
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
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        for _ in 0..400_000 {
            let value = f64::from_bits(next());
            assert_eq!(pushed(value), format!("{value}"), "{value:e}");
            let decimal = (next() % 2_000_001) as f64 / 1000.0 - 1000.0;
            assert_eq!(pushed(decimal), format!("{decimal}"));
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
        for value in [0, 1, 9, 10, 99, 100, 12345, u32::MAX as u64, u64::MAX] {
            let mut w = Vec::new();
            push_u64(&mut w, value);
            assert_eq!(w, value.to_string().as_bytes());
        }
    }
}
