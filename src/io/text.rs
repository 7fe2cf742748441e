//! Reading text formats byte by byte: they need not be UTF-8 outside the
//! numbers, and every token carries its line for error messages.

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
pub(crate) fn words(line: &[u8]) -> impl Iterator<Item = &[u8]> {
    line.split(|b| b.is_ascii_whitespace())
        .filter(|w| !w.is_empty())
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

/// Parses a floating-point number.
pub(crate) fn parse_f64(word: &[u8], line: usize, what: &str) -> Result<f64, IoError> {
    std::str::from_utf8(word)
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .ok_or_else(|| {
            IoError::parse(
                Location::Line(line),
                format!("expected a number for {what}, found {}", show(word)),
            )
        })
}

/// Parses a signed integer.
pub(crate) fn parse_i64(word: &[u8], line: usize, what: &str) -> Result<i64, IoError> {
    std::str::from_utf8(word)
        .ok()
        .and_then(|s| s.parse::<i64>().ok())
        .ok_or_else(|| {
            IoError::parse(
                Location::Line(line),
                format!("expected an integer for {what}, found {}", show(word)),
            )
        })
}

/// Parses a count or index that must be non-negative.
pub(crate) fn parse_count(word: &[u8], line: usize, what: &str) -> Result<usize, IoError> {
    let value = parse_i64(word, line, what)?;
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
    pub(crate) fn expect_word(&mut self, what: &str) -> Result<(&'a [u8], usize), IoError> {
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
        let (word, line) = self.expect_word(&format!("\"{keyword}\""))?;
        if word.eq_ignore_ascii_case(keyword.as_bytes()) {
            Ok(line)
        } else {
            Err(IoError::parse(
                Location::Line(line),
                format!("expected \"{keyword}\", found {}", show(word)),
            ))
        }
    }

    pub(crate) fn next_f64(&mut self, what: &str) -> Result<f64, IoError> {
        let (word, line) = self.expect_word(what)?;
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
