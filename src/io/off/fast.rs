//! OFF read on all threads. A row is a line with a word once its `#`
//! comment is cut, and a row's place (vertex v, face f) is its rank among
//! the rows after the counts: the body is cut at line ends into pieces,
//! each piece's rows counted on all threads, then each read knowing the
//! rank of its first row. Anything the row-by-row reader would report (a
//! malformed or missing number, too few rows, a mesh it refuses) makes the
//! file go to that reader, so errors and their lines are its own. Read
//! from a file, blocks cut at line ends go through two buffers, one read
//! while the other is filled.

use std::io::Read;

use glam::DVec3;
use memchr::memchr;

use super::super::blocks::{after_last_line, read_blocks};
use super::super::text::{f64_of, i64_of, read_ranked, words};
use super::super::{build_mesh_with, Location};
use crate::mesh::{Mesh, MeshOptions};

/// Bytes a piece holds at least (it ends at the next line end).
pub(super) const PIECE: usize = 1 << 20;

/// Bytes read from a file at a time.
pub(super) const BLOCK: usize = 16 << 20;

/// The mesh of `data`, read in pieces of `piece` bytes; `None` where the
/// row-by-row reader must read it (see the module doc).
pub(super) fn read(data: &[u8], piece: usize, options: MeshOptions) -> Option<Mesh> {
    let (vertex_count, face_count, body) = counts(data)?;
    let mut reader = Reader::new(vertex_count, face_count);
    reader.read(&data[body..], piece)?;
    reader.mesh(options)
}

/// Reads an OFF file from `source` through two buffers of `block` bytes
/// cut at line ends, each read as [`read`] reads a body; `Ok(None)` where
/// the row-by-row reader must read it.
///
/// # Errors
/// Whatever `source` returns.
pub(super) fn read_source(
    source: impl Read + Send,
    block: usize,
    piece: usize,
    options: MeshOptions,
) -> std::io::Result<Option<Mesh>> {
    // Counts past the first block leave the file to the rows.
    let header = |text: &[u8]| {
        let (vertex_count, face_count, body) = counts(text)?;
        Some((Reader::new(vertex_count, face_count), body))
    };
    let read = |reader: &mut Reader, text: &[u8], _| reader.read(text, piece);
    let reader = read_blocks(source, block, after_last_line, header, read)?;
    Ok(reader.and_then(|reader| reader.mesh(options)))
}

/// The rows read so far.
struct Reader {
    vertex_count: usize,
    face_count: usize,
    /// Rows read so far.
    rank: usize,
    read: Piece,
}

impl Reader {
    fn new(vertex_count: usize, face_count: usize) -> Reader {
        Reader {
            vertex_count,
            face_count,
            rank: 0,
            read: Piece {
                positions: Vec::new(),
                sizes: Vec::new(),
                indices: Vec::new(),
            },
        }
    }

    /// Reads `text`, whole lines, in pieces of `piece` bytes on all threads.
    fn read(&mut self, text: &[u8], piece: usize) -> Option<()> {
        let (vertex_count, face_count) = (self.vertex_count, self.face_count);
        let all = &mut self.read;
        read_ranked(
            text,
            piece,
            &mut self.rank,
            |p| rows_of(p).count(),
            |text, first| read_piece(text, first, vertex_count, face_count),
            |piece| {
                all.positions.extend_from_slice(&piece.positions);
                all.sizes.extend_from_slice(&piece.sizes);
                all.indices.extend_from_slice(&piece.indices);
            },
        )
    }

    /// The mesh read; `None` when rows are missing or the mesh is refused.
    fn mesh(self, options: MeshOptions) -> Option<Mesh> {
        if self.rank < self.vertex_count.checked_add(self.face_count)? {
            return None;
        }
        let Piece {
            positions,
            sizes,
            indices,
        } = self.read;
        // Lines are not kept: a mesh refused is read again row by row,
        // which names them.
        build_mesh_with(
            (positions, sizes, indices),
            options,
            |_| Location::Line(0),
            |_| Location::Line(0),
        )
        .ok()
    }
}

/// The vertex and face counts and where the rows after them start, read as
/// the row-by-row reader reads them.
pub(super) fn counts(data: &[u8]) -> Option<(usize, usize, usize)> {
    let mut rows = rows_ending(data);
    let (mut end, text) = rows.next()?;
    let mut header: Vec<&[u8]> = words(text).collect();
    if header[0].len() >= 3 && header[0][header[0].len() - 3..].eq_ignore_ascii_case(b"OFF") {
        header.remove(0);
        if header.is_empty() {
            let (counts_end, text) = rows.next()?;
            end = counts_end;
            header = words(text).collect();
        }
    }
    let count = |word: Option<&&[u8]>| usize::try_from(i64_of(word?)?).ok();
    Some((count(header.first())?, count(header.get(1))?, end))
}

/// The rows of `text`, as `text::lines` and [`words`] find them: a line whose
/// first byte that is not white space is there and not `#`, cut at its `#`;
/// each with where the line after it starts.
fn rows_ending(text: &[u8]) -> impl Iterator<Item = (usize, &[u8])> {
    let mut start = 0;
    std::iter::from_fn(move || loop {
        let rest = text.get(start..).filter(|rest| !rest.is_empty())?;
        let line = &rest[..memchr(b'\n', rest).map_or(rest.len(), |at| at + 1)];
        start += line.len();
        match line.iter().find(|b| !b.is_ascii_whitespace()) {
            Some(b'#') | None => continue,
            Some(_) => return Some((start, memchr(b'#', line).map_or(line, |at| &line[..at]))),
        }
    })
}

/// The rows of `text` (see [`rows_ending`]).
fn rows_of(text: &[u8]) -> impl Iterator<Item = &[u8]> {
    rows_ending(text).map(|(_, row)| row)
}

/// What a piece holds: its vertices, then its faces' sizes and indices.
struct Piece {
    positions: Vec<DVec3>,
    sizes: Vec<u32>,
    indices: Vec<u32>,
}

/// Reads the rows of `text`, the first of rank `first`; `None` at the first
/// row the row-by-row reader would report.
fn read_piece(text: &[u8], first: usize, vertex_count: usize, face_count: usize) -> Option<Piece> {
    let mut piece = Piece {
        positions: Vec::new(),
        sizes: Vec::new(),
        indices: Vec::new(),
    };
    for (rank, row) in (first..vertex_count + face_count).zip(rows_of(text)) {
        let mut w = words(row);
        if rank < vertex_count {
            let mut xyz = [0.0; 3];
            for value in &mut xyz {
                *value = f64_of(w.next()?)?;
            }
            piece.positions.push(DVec3::from_array(xyz));
            continue;
        }
        let size = usize::try_from(i64_of(w.next()?)?).ok()?;
        for _ in 0..size {
            let index = usize::try_from(i64_of(w.next()?)?).ok()?;
            piece.indices.push(u32::try_from(index).ok()?);
        }
        piece.sizes.push(u32::try_from(size).ok()?);
    }
    Some(piece)
}
