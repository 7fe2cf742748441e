//! Reading text formats byte by byte: they need not be UTF-8 outside the
//! numbers, and every token carries its line for error messages.

use std::fmt::Display;

use super::{IoError, Location};

/// The lines of `data` with their 1-based numbers, `\r` and `#` comments removed.
pub(crate) fn lines(data: &[u8]) -> impl Iterator<Item = (usize, &[u8])> {
    data.split(|&b| b == b'\n').enumerate().map(|(i, line)| {
        let line = match line.iter().position(|&b| b == b'#') {
            Some(hash) => &line[..hash],
            None => line,
        };
        (i + 1, line)
    })
}

/// The whitespace-separated words of a line.
pub(crate) fn words(line: &[u8]) -> Words<'_> {
    Words { rest: line }
}

/// The iterator of [`words`]: ASCII white space separates, runs of it
/// count as one.
pub(crate) struct Words<'a> {
    rest: &'a [u8],
}

impl<'a> Iterator for Words<'a> {
    type Item = &'a [u8];

    #[inline]
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

/// `text` cut into pieces of at least `piece` bytes (1 at least), each
/// ending at a line end (the last at the end of `text`), for a reader that
/// reads them on all threads.
pub(crate) fn pieces_at_line_ends(text: &[u8], piece: usize) -> Vec<&[u8]> {
    let piece = piece.max(1);
    let mut pieces = Vec::new();
    let mut rest = text;
    while !rest.is_empty() {
        let end = match rest.get(piece..) {
            Some(after) => memchr::memchr(b'\n', after).map_or(rest.len(), |at| piece + at + 1),
            None => rest.len(),
        };
        let (head, tail) = rest.split_at(end);
        pieces.push(head);
        rest = tail;
    }
    pieces
}

/// Pieces [`read_in_rounds`] reads at once.
pub(crate) const ROUND: usize = 32;

/// Reads `pieces` on all threads, a [`ROUND`] at a time, handing each
/// piece's reading to `append` in order before the next round is read, so
/// that what the pieces hold on their own stays a round's worth; `None` at
/// the first piece `read` gives up on. `read` is told each piece's index.
pub(crate) fn read_in_rounds<T: Send>(
    pieces: &[&[u8]],
    read: impl Fn(usize, &[u8]) -> Option<T> + Sync,
    mut append: impl FnMut(T),
) -> Option<()> {
    use rayon::prelude::*;
    for (r, texts) in pieces.chunks(ROUND).enumerate() {
        let first = r * ROUND;
        let read: Vec<Option<T>> = texts
            .par_iter()
            .enumerate()
            .map(|(i, text)| read(first + i, text))
            .collect();
        for piece in read {
            append(piece?);
        }
    }
    Some(())
}

/// Reads `text` in pieces of `piece` bytes cut at line ends, on all
/// threads, each piece knowing the rank of its first row: `rows_in` counts
/// a piece's rows, and ranks go on from `rank`, which is moved past
/// `text`'s rows. `read` reads a piece from the rank of its first row;
/// what it gives is appended in order (see [`read_in_rounds`]). `None` at
/// the first piece `read` gives up on.
pub(crate) fn read_ranked<T: Send>(
    text: &[u8],
    piece: usize,
    rank: &mut usize,
    rows_in: impl Fn(&[u8]) -> usize + Sync,
    read: impl Fn(&[u8], usize) -> Option<T> + Sync,
    append: impl FnMut(T),
) -> Option<()> {
    use rayon::prelude::*;
    let pieces = pieces_at_line_ends(text, piece);
    let rows: Vec<usize> = pieces.par_iter().map(|p| rows_in(p)).collect();
    let firsts: Vec<usize> = rows
        .iter()
        .scan(*rank, |next, &n| {
            let first = *next;
            *next += n;
            Some(first)
        })
        .collect();
    *rank += rows.iter().sum::<usize>();
    read_in_rounds(&pieces, |i, text| read(text, firsts[i]), append)
}

/// A word shown in an error message, shortened and made printable.
pub(crate) fn show(word: &[u8]) -> String {
    let text = String::from_utf8_lossy(&word[..word.len().min(40)]);
    let mut shown: String = text
        .chars()
        .map(|c| if c.is_control() { '?' } else { c })
        .collect();
    if word.len() > 40 {
        shown.push('…');
    }
    format!("\"{shown}\"")
}

/// A floating-point number, exactly as `str::parse::<f64>` reads it
/// (correctly rounded), or `None` where that fails.
///
/// Words that `fast_float2` reads whole to a finite number are taken from
/// it: both it and the standard library (whose parser is the same
/// algorithm) round correctly, so they give the same bits, and it reads the
/// digits eight at a time without first checking the word is UTF-8.
/// Anything else (`inf`, `NaN`, malformed words, numbers beyond the range
/// of a double) goes to the standard library, which decides.
#[inline]
pub(crate) fn f64_of(word: &[u8]) -> Option<f64> {
    // A word holds no white space; a slice that does is no number, as for
    // the standard library.
    f64_at_start(word)
        .filter(|&(_, length)| length == word.len())
        .map(|(value, _)| value)
}

/// The standard library's reading of `word`.
fn parsed_f64(word: &[u8]) -> Option<f64> {
    std::str::from_utf8(word).ok()?.parse().ok()
}

/// The number the word at the start of `text` holds, read as [`f64_of`]
/// describes, and the word's length. A number is read in the same pass
/// that finds the word's end.
#[inline]
pub(crate) fn f64_at_start(text: &[u8]) -> Option<(f64, usize)> {
    if let Ok((value, end)) = fast_float2::parse_partial::<f64, _>(text) {
        let word_ends = text.get(end).is_none_or(u8::is_ascii_whitespace);
        if word_ends && value.is_finite() {
            return Some((value, end));
        }
    }
    let end = text
        .iter()
        .position(u8::is_ascii_whitespace)
        .unwrap_or(text.len());
    parsed_f64(&text[..end]).map(|value| (value, end))
}

/// A signed integer, exactly as `str::parse::<i64>` reads it, or `None`
/// where that fails.
#[inline]
pub(crate) fn i64_of(word: &[u8]) -> Option<i64> {
    let (negative, digits) = match word.split_first() {
        Some((b'-', rest)) => (true, rest),
        Some((b'+', rest)) => (false, rest),
        _ => (false, word),
    };
    // Up to 18 digits cannot overflow; longer words go to the standard library.
    if digits.is_empty() || digits.len() > 18 {
        return std::str::from_utf8(word).ok()?.parse().ok();
    }
    let mut value = 0i64;
    for &b in digits {
        if !b.is_ascii_digit() {
            return None;
        }
        value = value * 10 + i64::from(b - b'0');
    }
    Some(if negative { -value } else { value })
}

/// What a reader expects, put into words only when an error names it: the
/// readers pass `format_args!` or this, so that reading a value that is
/// there costs no text. (`what` of the `parse_*` and `expect_*` helpers.)
pub(crate) struct Lazy<F>(pub(crate) F);

impl<F: Fn() -> String> Display for Lazy<F> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&(self.0)())
    }
}

/// Parses a floating-point number.
pub(crate) fn parse_f64(word: &[u8], line: usize, what: impl Display) -> Result<f64, IoError> {
    f64_of(word).ok_or_else(|| {
        IoError::parse(
            Location::Line(line),
            format!("expected a number for {what}, found {}", show(word)),
        )
    })
}

/// Parses a signed integer.
pub(crate) fn parse_i64(word: &[u8], line: usize, what: impl Display) -> Result<i64, IoError> {
    i64_of(word).ok_or_else(|| {
        IoError::parse(
            Location::Line(line),
            format!("expected an integer for {what}, found {}", show(word)),
        )
    })
}

/// Parses a count or index that must be non-negative.
pub(crate) fn parse_count(word: &[u8], line: usize, what: impl Display) -> Result<usize, IoError> {
    let value = parse_i64(word, line, &what)?;
    usize::try_from(value).map_err(|_| {
        IoError::parse(
            Location::Line(line),
            format!("expected a non-negative integer for {what}, found {value}"),
        )
    })
}

/// Words across lines, each with its line number: for formats where line
/// breaks carry no meaning (PLY ASCII bodies, ASCII STL).
pub(crate) struct Tokens<'a> {
    data: &'a [u8],
    pos: usize,
    line: usize,
}

impl<'a> Tokens<'a> {
    pub(crate) fn new(data: &'a [u8], first_line: usize) -> Tokens<'a> {
        Tokens {
            data,
            pos: 0,
            line: first_line,
        }
    }

    /// The line the next word is on (or the last line at the end).
    pub(crate) fn line(&mut self) -> usize {
        self.skip_space();
        self.line
    }

    fn skip_space(&mut self) {
        while let Some(&b) = self.data.get(self.pos) {
            if b == b'\n' {
                self.line += 1;
            } else if !b.is_ascii_whitespace() {
                break;
            }
            self.pos += 1;
        }
    }

    /// The next word and its line, or `None` at the end.
    pub(crate) fn next_word(&mut self) -> Option<(&'a [u8], usize)> {
        self.skip_space();
        let start = self.pos;
        while self
            .data
            .get(self.pos)
            .is_some_and(|b| !b.is_ascii_whitespace())
        {
            self.pos += 1;
        }
        (self.pos > start).then(|| (&self.data[start..self.pos], self.line))
    }

    /// The next word, or an error saying `what` was expected.
    pub(crate) fn expect_word(&mut self, what: impl Display) -> Result<(&'a [u8], usize), IoError> {
        let line = self.line();
        self.next_word().ok_or_else(|| {
            IoError::parse(
                Location::Line(line),
                format!("unexpected end of file; expected {what}"),
            )
        })
    }

    /// The next word, which must be `keyword`.
    pub(crate) fn expect_keyword(&mut self, keyword: &str) -> Result<usize, IoError> {
        let (word, line) = self.expect_word(format_args!("\"{keyword}\""))?;
        if word.eq_ignore_ascii_case(keyword.as_bytes()) {
            Ok(line)
        } else {
            Err(IoError::parse(
                Location::Line(line),
                format!("expected \"{keyword}\", found {}", show(word)),
            ))
        }
    }

    pub(crate) fn next_f64(&mut self, what: impl Display) -> Result<f64, IoError> {
        let (word, line) = self.expect_word(&what)?;
        parse_f64(word, line, what)
    }

    /// Skips the rest of the current line.
    pub(crate) fn skip_line(&mut self) {
        while let Some(&b) = self.data.get(self.pos) {
            self.pos += 1;
            if b == b'\n' {
                self.line += 1;
                break;
            }
        }
    }

    /// Bytes not yet read.
    pub(crate) fn remaining(&self) -> usize {
        self.data.len() - self.pos
    }
}

/// For tests of the readers: `bytes` with each of `edits` (a place, and a byte put there,
/// inserted, or the byte there removed).
#[cfg(test)]
pub(crate) fn edited(bytes: &[u8], edits: &[(usize, u8, u8)]) -> Vec<u8> {
    const BYTES: &[u8] = b" \n\r\t0189-.eE+xn#";
    let mut out = bytes.to_vec();
    for &(at, byte, how) in edits {
        if out.is_empty() {
            break;
        }
        let (at, byte) = (at % out.len(), BYTES[byte as usize % BYTES.len()]);
        match how % 3 {
            0 => out[at] = byte,
            1 => out.insert(at, byte),
            _ => {
                out.remove(at);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The direct number path must agree, bit for bit, with the standard
    /// library on every word, read or refused.
    #[test]
    fn numbers_read_as_the_standard_library_reads_them() {
        let mut words: Vec<String> = [
            "0",
            "-0",
            "+0",
            "1",
            "-1",
            "+1",
            ".5",
            "-.5",
            "5.",
            "-5.",
            ".",
            "-",
            "+",
            "",
            "1.2.3",
            "--1",
            "+-1",
            "1e5",
            "1E-5",
            "inf",
            "-inf",
            "NaN",
            "infinity",
            "0x10",
            "1_000",
            " 1",
            "1 ",
            "9007199254740992",
            "9007199254740993",
            "-9007199254740993",
            "0.1234567890123456789",
            "1234567890123456789",
            "12345678901234567890",
            "0.0000000000000000000001",
            "0.00000000000000000000001",
            "-4.9939024390243905",
            "2.689024390243903",
            "0.30000000000000004",
            "00000000000000000001",
            "9223372036854775807",
            "9223372036854775808",
            "-9223372036854775808",
            "-9223372036854775809",
            "١",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        // Pseudo-random decimals of every length and number of decimals.
        let mut next = crate::test_random::words(0x2545_f491_4f6c_dd1du64);
        for _ in 0..200_000 {
            let digits = 1 + next() % 24;
            let mut word = String::new();
            if next() % 2 == 0 {
                word.push('-');
            }
            let dot = next() % (digits + 2);
            for k in 0..digits {
                if k == dot {
                    word.push('.');
                }
                word.push(char::from(b'0' + (next() % 10) as u8));
            }
            words.push(word);
        }
        // Words of number-like bytes: exponents, signs and points anywhere,
        // the special words and their near misses, and the edges of a
        // double's range.
        const PIECES: [&str; 22] = [
            "0", "1", "5", "9", "12345678", "99999999", ".", "e", "E", "+", "-", "e-", "e+", "inf",
            "nan", "NaN", "infinity", "INF", "i", "308", "324", "x",
        ];
        for _ in 0..200_000 {
            let pieces = 1 + next() % 6;
            let word: String = (0..pieces)
                .map(|_| PIECES[(next() % PIECES.len() as u64) as usize])
                .collect();
            words.push(word);
        }
        words.extend(
            [
                "1e308",
                "1.7976931348623157e308",
                "1.7976931348623158e308",
                "1.8e308",
                "1e309",
                "-1e309",
                "4.9e-324",
                "2.4703282292062328e-324",
                "2.4703282292062327e-324",
                "1e-400",
                "-1e-400",
                "2.2250738585072011e-308",
                "2.2250738585072014e-308",
                "+inf",
                "-NaN",
                "+nan",
                "Infinity",
                "-infinity",
                "infinit",
                "1e",
                "1e+",
                "1.e5",
                ".e5",
                "-.e5",
                "1.5E+3",
                "1.5e-3",
                "7.2057594037927933e16",
                "9007199254740993.0000000000000000000001",
            ]
            .map(String::from),
        );
        words.push(format!("0.{}1", "0".repeat(400)));
        words.push(format!("{}.5", "9".repeat(320)));
        words.push(format!("1{}e-300", "0".repeat(300)));
        for word in &words {
            let float = word.parse::<f64>().ok().map(f64::to_bits);
            assert_eq!(f64_of(word.as_bytes()).map(f64::to_bits), float, "{word:?}");
            // At the start of a line: the same number, and the word's end.
            let line = format!("{word} 7\n");
            let at_start = f64_at_start(line.as_bytes()).map(|(x, end)| (x.to_bits(), end));
            let expected = match word.contains(char::is_whitespace) {
                true => at_start,
                false => float.map(|bits| (bits, word.len())),
            };
            assert_eq!(at_start, expected, "{word:?}");
            assert_eq!(
                i64_of(word.as_bytes()),
                word.parse::<i64>().ok(),
                "{word:?}"
            );
        }
    }
}
