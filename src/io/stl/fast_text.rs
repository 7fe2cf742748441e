//! Text STL read on all threads. A line whose only word is `endfacet` ends
//! a facet wherever it stands (a solid's name is the rest of a line that
//! holds `solid` or `endsolid`), so the body is cut after such lines into
//! pieces that each hold whole facets, and the pieces are read a round at
//! a time on all threads, each as the word-by-word reader reads facets.
//! Anything that reader would report, a mesh it refuses, and the rarer
//! forms (several solids, words after `endsolid`) make the file go to it,
//! so errors and their lines are its own.
//!
//! Read from a file, blocks go through two buffers, one read while the
//! other is filled, each cut after its last `endfacet` line, so that the
//! file's bytes are never all in memory.

use std::io::Read;

use glam::DVec3;
use memchr::{memchr, memrchr};
use rayon::prelude::*;

use super::super::blocks::read_blocks;
use super::super::text::{read_in_rounds, Tokens};
use super::super::{build_mesh, Location};
use super::read_facet;
use crate::mesh::Mesh;

/// Bytes a piece holds at least (it ends after the next `endfacet` line).
pub(super) const PIECE: usize = 1 << 20;

/// Bytes read from a file at a time.
pub(super) const BLOCK: usize = 16 << 20;

/// The mesh of `data`, read in pieces of `piece` bytes; `None` where the
/// word-by-word reader must read it (see the module doc).
pub(super) fn read(data: &[u8], piece: usize) -> Option<Mesh> {
    let body = &data[header_end(data)?..];
    let mut facets = Facets::default();
    facets.read(body, piece, true)?;
    facets.mesh()
}

/// Reads a text file from `source` through two buffers of `block` bytes,
/// each read in pieces of `piece` bytes (see [`read`]); `Ok(None)` where
/// the word-by-word reader must read it.
///
/// # Errors
/// Whatever `source` returns.
pub(super) fn read_source(
    source: impl Read + Send,
    block: usize,
    piece: usize,
) -> std::io::Result<Option<Mesh>> {
    // A block ends after an `endfacet` line, so past the header's line.
    let header = |text: &[u8]| Some((Facets::default(), header_end(text)?));
    let read = |facets: &mut Facets, text: &[u8], last| facets.read(text, piece, last);
    let facets = read_blocks(source, block, after_last_facet, header, read)?;
    Ok(facets.and_then(Facets::mesh))
}

/// Where the body starts, after the line of `solid` and its name.
fn header_end(data: &[u8]) -> Option<usize> {
    let mut tokens = Tokens::new(data, 1);
    tokens.expect_keyword("solid").ok()?;
    tokens.skip_line();
    Some(data.len() - tokens.remaining())
}

/// The corners and facet sizes read so far.
#[derive(Default)]
struct Facets {
    positions: Vec<DVec3>,
    sizes: Vec<u32>,
}

impl Facets {
    /// Reads `text`, whole facets, in pieces of `piece` bytes on all
    /// threads; the `last` text of the file may end with `endsolid`.
    fn read(&mut self, text: &[u8], piece: usize, last: bool) -> Option<()> {
        let pieces = cut(text, piece.max(1));
        let last_piece = pieces.len().saturating_sub(1);
        read_in_rounds(
            &pieces,
            |i, text| read_piece(text, last && i == last_piece),
            |piece| {
                self.positions.extend_from_slice(&piece.positions);
                self.sizes.extend_from_slice(&piece.sizes);
            },
        )
    }

    fn mesh(self) -> Option<Mesh> {
        let mut indices = Vec::with_capacity(self.positions.len());
        indices.par_extend(
            (0..u32::try_from(self.positions.len()).ok()?)
                .into_par_iter()
                .with_min_len(4096),
        );
        // Lines are not kept: a mesh refused is read again word by word,
        // which names them.
        build_mesh(
            self.positions,
            self.sizes,
            indices,
            |_| Location::Line(0),
            |_| Location::Line(0),
        )
        .ok()
    }
}

/// Where the last line of `bytes` whose only word is `endfacet` ends.
fn after_last_facet(bytes: &[u8]) -> Option<usize> {
    let mut end = memrchr(b'\n', bytes)? + 1;
    loop {
        let start = memrchr(b'\n', &bytes[..end - 1]).map_or(0, |at| at + 1);
        if bytes[start..end]
            .trim_ascii()
            .eq_ignore_ascii_case(b"endfacet")
        {
            return Some(end);
        }
        if start == 0 {
            return None;
        }
        end = start;
    }
}

/// `body` cut into pieces of at least `piece` bytes, each ending after a
/// line whose only word is `endfacet` (the last at the end of `body`).
fn cut(body: &[u8], piece: usize) -> Vec<&[u8]> {
    let mut pieces = Vec::new();
    let mut rest = body;
    while !rest.is_empty() {
        let end = facets_end(rest, piece).unwrap_or(rest.len());
        let (head, tail) = rest.split_at(end);
        pieces.push(head);
        rest = tail;
    }
    pieces
}

/// Where the first line past byte `from` of `text` whose only word is
/// `endfacet` ends (after its line end).
fn facets_end(text: &[u8], from: usize) -> Option<usize> {
    // The line that holds byte `from` may be an `endfacet` line cut short.
    let mut start = from + memchr(b'\n', text.get(from..)?)? + 1;
    loop {
        let line_end = memchr(b'\n', &text[start..]).map_or(text.len(), |at| start + at + 1);
        if line_end == start {
            return None;
        }
        if text[start..line_end]
            .trim_ascii()
            .eq_ignore_ascii_case(b"endfacet")
        {
            return Some(line_end);
        }
        start = line_end;
    }
}

/// The corners and facet sizes of a piece.
struct Piece {
    positions: Vec<DVec3>,
    sizes: Vec<u32>,
}

/// Reads the facets of `text`; `None` at anything the word-by-word reader
/// would report, and at `endsolid` but at the end of the `last` piece.
fn read_piece(text: &[u8], last: bool) -> Option<Piece> {
    let mut tokens = Tokens::new(text, 1);
    let mut piece = Piece {
        positions: Vec::with_capacity(text.len() / 70),
        sizes: Vec::with_capacity(text.len() / 210),
    };
    while let Some((word, _)) = tokens.next_word() {
        if word.eq_ignore_ascii_case(b"endsolid") {
            tokens.skip_line();
            return (last && tokens.next_word().is_none()).then_some(piece);
        }
        if !word.eq_ignore_ascii_case(b"facet") {
            return None;
        }
        let size = read_facet(&mut tokens, &mut piece.positions, |_| {}).ok()?;
        piece.sizes.push(size);
    }
    Some(piece)
}

#[cfg(test)]
mod tests {
    use super::super::tests::position_bits;
    use super::super::{parse_ascii_words, write};
    use super::*;
    use crate::mesh::shapes;

    fn text(mesh: &Mesh) -> Vec<u8> {
        let mut bytes = Vec::new();
        write(&mut bytes, mesh, true).unwrap();
        bytes
    }

    /// Text files as other programs write them: upper case, CRLF, tabs,
    /// keywords sharing lines, polygons, blank lines, no `endsolid`.
    fn files() -> Vec<Vec<u8>> {
        let mut torus = shapes::triangle_torus(9, 7);
        torus.positions_mut()[0].x = -0.0;
        let ours = text(&torus);
        let lines = String::from_utf8(ours.clone()).unwrap();
        let upper_crlf = lines.to_uppercase().replace('\n', "\r\n").into_bytes();
        let tabs = lines.replace("  ", "\t").replace('\n', "\n\n").into_bytes();
        // Every facet on one line but its endfacet.
        let joined = lines
            .replace("\n    outer loop\n", " outer loop ")
            .replace("\n      vertex", " vertex")
            .replace("\n    endloop\n", " endloop\n")
            .into_bytes();
        let no_end = lines.replace("endsolid weft\n", "").into_bytes();
        let quad = b"solid quad name with endfacet in it\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid quad\n\n".to_vec();
        vec![ours, upper_crlf, tabs, joined, no_end, quad]
    }

    #[test]
    fn pieces_of_any_size_read_as_the_words_do() {
        for (i, bytes) in files().iter().enumerate() {
            let words = parse_ascii_words(bytes).unwrap();
            let bits = position_bits(&words);
            for piece in [1, 2, 50, 333, 4096, PIECE] {
                let mesh = read(bytes, piece).unwrap_or_else(|| panic!("file {i}, piece {piece}"));
                assert_eq!(mesh, words, "file {i}, piece {piece}");
                assert_eq!(position_bits(&mesh), bits, "file {i}, piece {piece}");
            }
        }
        // Read from a stream in blocks of any size too.
        for (i, bytes) in files().iter().enumerate() {
            let words = parse_ascii_words(bytes).unwrap();
            for block in [1, 7, 64, 1000, BLOCK] {
                for piece in [1, 50, PIECE] {
                    let mesh = read_source(bytes.as_slice(), block, piece).unwrap();
                    let mesh = mesh.unwrap_or_else(|| panic!("file {i}, block {block}"));
                    assert_eq!(mesh, words, "file {i}, block {block}, piece {piece}");
                    assert_eq!(position_bits(&mesh), position_bits(&words));
                }
            }
        }
        // More pieces than a round: every round appended in order.
        let torus = shapes::triangle_torus(40, 30);
        let bytes = text(&torus);
        let mesh = read(&bytes, 100).unwrap();
        assert!(bytes.len() / 100 > 2 * crate::io::text::ROUND);
        assert_eq!(mesh, parse_ascii_words(&bytes).unwrap());
    }

    #[test]
    fn blocks_end_after_their_last_endfacet_line() {
        let bytes = b"solid a\nfacet normal 0 0 1\n endfacet \r\nfacet\nendfacet";
        assert_eq!(after_last_facet(bytes), Some(39));
        assert_eq!(after_last_facet(&bytes[..39]), Some(39));
        assert_eq!(after_last_facet(&bytes[..38]), None);
        assert_eq!(after_last_facet(b"endfacet\n"), Some(9));
        assert_eq!(after_last_facet(b""), None);
    }

    #[test]
    fn pieces_cut_after_endfacet_lines_only() {
        let bytes = text(&shapes::triangle_torus(5, 4));
        for piece in [1, 17, 300] {
            let pieces = cut(&bytes, piece);
            assert_eq!(pieces.concat(), bytes);
            for p in &pieces[..pieces.len() - 1] {
                let last = p.trim_ascii_end().rsplit(|&b| b == b'\n').next().unwrap();
                assert_eq!(last.trim_ascii(), b"endfacet", "piece of {piece}");
            }
        }
    }

    #[test]
    fn rarer_forms_and_errors_are_left_to_the_words() {
        let cube = String::from_utf8(text(&shapes::cube())).unwrap();
        let two_solids = format!("{cube}{cube}");
        let trailing = format!("{cube}anything at all\n");
        let bad_number = cube.replacen("vertex ", "vertex x", 1);
        let first_vertex = cube.lines().find(|l| l.contains("vertex")).unwrap();
        let nan = cube.replacen(first_vertex, "      vertex nan 0 0", 1);
        let missing_endloop = cube.replacen("    endloop\n", "", 1);
        let stray = cube.replacen("  endfacet\n", "  endfacet\nendfacet\n", 1);
        for (name, file) in [
            ("two solids", &two_solids),
            ("trailing words", &trailing),
            ("bad number", &bad_number),
            ("nan", &nan),
            ("missing endloop", &missing_endloop),
            ("stray endfacet", &stray),
        ] {
            for piece in [1, 100, PIECE] {
                assert!(
                    read(file.as_bytes(), piece).is_none(),
                    "{name}, piece {piece}"
                );
                for block in [1, 100, BLOCK] {
                    let streamed = read_source(file.as_bytes(), block, piece).unwrap();
                    assert!(streamed.is_none(), "{name}, block {block}, piece {piece}");
                }
            }
            // The whole reading gives what the words give, mesh or error.
            let words = parse_ascii_words(file.as_bytes()).map_err(|e| e.to_string());
            let whole = super::super::parse(file.as_bytes()).map_err(|e| e.to_string());
            assert_eq!(whole, words, "{name}");
        }
        assert_eq!(
            super::super::parse(two_solids.as_bytes())
                .unwrap()
                .face_count(),
            2 * shapes::cube().face_count() * 2
        );
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]

        /// Files a few bytes away from well-formed ones: whatever the
        /// pieces and blocks read, the words read the same.
        #[test]
        fn what_the_pieces_read_the_words_read_alike(
            file in 0usize..6,
            edits in proptest::collection::vec((0usize..100_000, 0u8..32, 0u8..3), 0..4),
            piece in 1usize..300,
            block in 1usize..600,
        ) {
            let bytes = crate::io::text::edited(&files()[file], &edits);
            let words = parse_ascii_words(&bytes).ok();
            let streamed = read_source(bytes.as_slice(), block, piece).unwrap();
            for mesh in [read(&bytes, piece), streamed].into_iter().flatten() {
                let words = words.as_ref().expect("the words read what the pieces read");
                proptest::prop_assert_eq!(&mesh, words);
                proptest::prop_assert_eq!(position_bits(&mesh), position_bits(words));
            }
        }
    }
}
