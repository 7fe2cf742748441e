//! The parallel OBJ reader: a file is taken in blocks, each block cut at
//! line ends into pieces that rayon's threads read side by side, and the
//! pieces joined in file order.
//!
//! A piece knows nothing of the lines before it, so what depends on them is
//! settled when it is joined: negative (relative) indices get the counts of
//! vertices and UVs read before the piece, `usemtl`, `mtllib`, `l` and `t`
//! lines are replayed in file order through the same code as the
//! line-by-line reader, and whether vertices carry colours and faces UVs is
//! checked against the file's first. Anything the line-by-line reader would
//! report (a malformed number, an index of 0, a face the mesh rejects, a
//! problem with an attribute) makes this reader give up, and the
//! line-by-line reader reads the file again to report it with its line: the
//! result, or the error, is the same either way.
//!
//! Read from a file, blocks go through two buffers, one filled while the
//! other's pieces are read (and the block before is joined), so the file's
//! bytes are never all in memory and the buffers stay in cache.

use std::io::Read;

use glam::DVec3;
use memchr::memchr;
use rayon::prelude::*;

use super::{Collected, Statements};
use crate::io::blocks::{after_last_line, FileBlock};
use crate::io::mesh_file::MeshFile;
use crate::io::text::{f64_at_start, f64_of, i64_of, words};
use crate::mesh::MeshOptions;

/// Bytes read from a file at a time.
pub(crate) const BLOCK: usize = 16 << 20;

/// Bytes of lines one thread reads as one piece.
pub(crate) const PIECE: usize = 1 << 20;

/// What one piece of whole lines holds, its indices still relative to the
/// piece where the file gives them relative.
#[derive(Default)]
struct Piece {
    /// Line ends in the piece.
    newlines: usize,
    positions: Vec<DVec3>,
    colours: Vec<[f64; 4]>,
    /// Whether the piece's vertices have colours (`None`: no vertex).
    coloured: Option<bool>,
    alpha: bool,
    uv_values: Vec<[f64; 2]>,
    face_sizes: Vec<u32>,
    face_indices: Vec<u32>,
    uv_indices: Vec<u32>,
    /// Whether the piece's face corners name UVs (`None`: no corner).
    has_uvs: Option<bool>,
    /// Negative vertex indices: the slot in `face_indices` and the index
    /// counted from the piece's first vertex.
    relative_vertices: Vec<(u32, i64)>,
    /// Negative UV indices, as `relative_vertices`.
    relative_uvs: Vec<(u32, i64)>,
    /// The `usemtl`, `mtllib`, `l` and `t` lines, to replay in order.
    statements: Vec<Statement>,
    /// Whether every line was read; false sends the file to the
    /// line-by-line reader.
    fine: bool,
}

/// A line replayed when its piece is joined.
struct Statement {
    /// Lines before it in its piece.
    line: usize,
    /// Vertices and faces before it in its piece.
    vertices: usize,
    faces: usize,
    /// The line, without its comment.
    text: Vec<u8>,
}

impl Piece {
    fn read(&mut self, data: &[u8]) {
        self.positions.clear();
        self.colours.clear();
        self.coloured = None;
        self.alpha = false;
        self.uv_values.clear();
        self.face_sizes.clear();
        self.face_indices.clear();
        self.uv_indices.clear();
        self.has_uvs = None;
        self.relative_vertices.clear();
        self.relative_uvs.clear();
        self.statements.clear();
        self.newlines = 0;
        self.fine = self.read_lines(data).is_some();
    }

    fn read_lines(&mut self, data: &[u8]) -> Option<()> {
        // The next comment is found once for the lines before it, not on
        // every line: most files have few.
        let next_hash =
            |from: usize| memchr(b'#', &data[from..]).map_or(data.len(), |at| from + at);
        let mut hash = next_hash(0);
        let mut start = 0;
        let mut line = 0;
        loop {
            let end = memchr(b'\n', &data[start..]).map_or(data.len(), |at| start + at);
            let text = &data[start..hash.min(end)];
            if hash < end {
                hash = next_hash(end);
            }
            self.line(text, line)?;
            if end == data.len() {
                break;
            }
            start = end + 1;
            line += 1;
        }
        self.newlines = line;
        Some(())
    }

    /// One line, without its comment; `None` when the line-by-line reader
    /// must read the file.
    #[inline]
    fn line(&mut self, text: &[u8], line: usize) -> Option<()> {
        // Most lines are `v x y z` or `f a b c ...`: read in one pass, or
        // left to the general reading below when anything else is there.
        match text {
            [b'v', b' ', rest @ ..] if self.plain_vertex(rest) => return Some(()),
            [b'f', b' ', rest @ ..] if self.plain_face(rest) => return Some(()),
            _ => {}
        }
        let mut w = words(text);
        match w.next() {
            Some(b"v") => {
                let mut values = [0.0; 7];
                let mut count = 0;
                for word in w {
                    // More than 7 numbers is a problem to report.
                    *values.get_mut(count)? = f64_of(word)?;
                    count += 1;
                }
                if count < 3 || count == 5 {
                    return None;
                }
                let coloured = count >= 6;
                if *self.coloured.get_or_insert(coloured) != coloured {
                    return None;
                }
                if coloured {
                    let alpha = if count == 7 {
                        self.alpha = true;
                        values[6]
                    } else {
                        1.0
                    };
                    let colour = [values[3], values[4], values[5], alpha];
                    if !colour.iter().all(|c| c.is_finite()) {
                        return None;
                    }
                    self.colours.push(colour);
                }
                self.positions
                    .push(DVec3::new(values[0], values[1], values[2]));
            }
            Some(b"vt") => {
                let u = f64_of(w.next()?)?;
                let v = match w.next() {
                    Some(v) => f64_of(v)?,
                    None => 0.0,
                };
                self.uv_values.push([u, v]);
            }
            Some(b"f") => {
                let mut size = 0u32;
                for corner in w {
                    // Corners are short: a scan beats memchr's set-up.
                    let (index, uv) = match corner.iter().position(|&b| b == b'/') {
                        Some(slash) => {
                            let rest = &corner[slash + 1..];
                            let uv = match rest.iter().position(|&b| b == b'/') {
                                Some(end) => &rest[..end],
                                None => rest,
                            };
                            (&corner[..slash], (!uv.is_empty()).then_some(uv))
                        }
                        None => (corner, None),
                    };
                    let slot = self.face_indices.len() as u32;
                    let vertex = index_of(
                        i64_of(index)?,
                        self.positions.len(),
                        slot,
                        &mut self.relative_vertices,
                    )?;
                    self.face_indices.push(vertex);
                    if *self.has_uvs.get_or_insert(uv.is_some()) != uv.is_some() {
                        return None;
                    }
                    if let Some(uv) = uv {
                        let slot = self.uv_indices.len() as u32;
                        let uv = index_of(
                            i64_of(uv)?,
                            self.uv_values.len(),
                            slot,
                            &mut self.relative_uvs,
                        )?;
                        self.uv_indices.push(uv);
                    }
                    size = size.saturating_add(1);
                }
                self.face_sizes.push(size);
            }
            Some(b"usemtl" | b"mtllib" | b"l" | b"t") => self.statements.push(Statement {
                line,
                vertices: self.positions.len(),
                faces: self.face_sizes.len(),
                text: text.to_vec(),
            }),
            _ => {}
        }
        Some(())
    }
}

impl Piece {
    /// A vertex of three coordinates and nothing after them; false, having
    /// read nothing, for anything else.
    #[inline]
    fn plain_vertex(&mut self, text: &[u8]) -> bool {
        if self.coloured == Some(true) {
            return false;
        }
        let mut values = [0.0; 3];
        let mut at = 0;
        for value in &mut values {
            at += skip_space(&text[at..]);
            match f64_at_start(&text[at..]) {
                Some((v, length)) if length > 0 => {
                    *value = v;
                    at += length;
                }
                _ => return false,
            }
        }
        if at + skip_space(&text[at..]) < text.len() {
            return false;
        }
        self.coloured = Some(false);
        self.positions
            .push(DVec3::new(values[0], values[1], values[2]));
        true
    }

    /// A face of positive vertex indices without UVs or normals; false,
    /// having read nothing, for anything else.
    #[inline]
    fn plain_face(&mut self, text: &[u8]) -> bool {
        if self.has_uvs == Some(true) {
            return false;
        }
        let first_corner = self.face_indices.len();
        let mut at = 0;
        loop {
            at += skip_space(&text[at..]);
            if at == text.len() {
                break;
            }
            let start = at;
            let mut value = 0u64;
            while let Some(&b @ b'0'..=b'9') = text.get(at) {
                value = value * 10 + u64::from(b - b'0');
                at += 1;
                if at - start > 10 {
                    break;
                }
            }
            let whole = text.get(at).is_none_or(u8::is_ascii_whitespace);
            if !whole || at == start || value == 0 || value > u64::from(u32::MAX) {
                self.face_indices.truncate(first_corner);
                return false;
            }
            self.face_indices.push((value - 1) as u32);
        }
        let size = self.face_indices.len() - first_corner;
        if size > 0 {
            self.has_uvs = Some(false);
        }
        self.face_sizes
            .push(u32::try_from(size).unwrap_or(u32::MAX));
        true
    }
}

/// How many bytes of white space `text` starts with.
#[inline]
fn skip_space(text: &[u8]) -> usize {
    text.iter()
        .position(|b| !b.is_ascii_whitespace())
        .unwrap_or(text.len())
}

/// An OBJ index made 0-based: positive ones at once, negative ones noted
/// for when the count before the piece is known; `None` for 0 or an index
/// past `u32`.
#[inline]
fn index_of(value: i64, count: usize, slot: u32, relative: &mut Vec<(u32, i64)>) -> Option<u32> {
    if value > 0 {
        u32::try_from(value - 1).ok()
    } else if value < 0 {
        relative.push((slot, (count as i64).checked_add(value)?));
        Some(0)
    } else {
        None
    }
}

/// The pieces one block was cut into, read.
#[derive(Default)]
struct Block {
    pieces: Vec<Piece>,
    /// How many of `pieces` the block filled (the rest are kept for reuse).
    count: usize,
}

impl Block {
    /// Cuts `data` (whole lines) into pieces of about `piece` bytes at line
    /// ends and reads them on all threads.
    fn read(&mut self, data: &[u8], piece: usize) {
        let mut cuts = Vec::new();
        let mut start = 0;
        while start < data.len() {
            let end = block_end(data, start, piece);
            cuts.push(start..end);
            start = end;
        }
        if self.pieces.len() < cuts.len() {
            self.pieces.resize_with(cuts.len(), Piece::default);
        }
        self.count = cuts.len();
        self.pieces[..cuts.len()]
            .par_iter_mut()
            .zip(cuts.par_iter())
            .with_max_len(1)
            .for_each(|(piece, range)| piece.read(&data[range.clone()]));
    }
}

/// The file read so far, block by block.
struct Reader {
    piece: usize,
    lines_before: usize,
    positions: Vec<DVec3>,
    colours: Vec<[f64; 4]>,
    coloured: Option<bool>,
    alpha: bool,
    uv_values: Vec<[f64; 2]>,
    uv_indices: Vec<u32>,
    has_uvs: Option<bool>,
    face_sizes: Vec<u32>,
    face_indices: Vec<u32>,
    statements: Statements,
}

impl Reader {
    fn new(piece: usize) -> Reader {
        Reader {
            piece: piece.max(1),
            lines_before: 0,
            positions: Vec::new(),
            colours: Vec::new(),
            coloured: None,
            alpha: false,
            uv_values: Vec::new(),
            uv_indices: Vec::new(),
            has_uvs: None,
            face_sizes: Vec::new(),
            face_indices: Vec::new(),
            statements: Statements::new(),
        }
    }

    /// Appends a block read; false when the file must be read line by line.
    fn join_block(&mut self, block: &Block) -> bool {
        block.pieces[..block.count]
            .iter()
            .all(|piece| self.join(piece))
    }

    /// Reads `data`'s pieces into `reading` on all threads while `read`,
    /// the block before, is appended and then `beside` runs (it fetches the
    /// next block from a file). Appending is one thread's work; beside the
    /// reading it costs little time. The first of the pair is false when the
    /// file must be read line by line.
    fn overlap<R: Send>(
        &mut self,
        reading: &mut Block,
        data: &[u8],
        read: &Block,
        beside: impl FnOnce() -> R + Send,
    ) -> (bool, R) {
        let piece = self.piece;
        rayon::join(
            || reading.read(data, piece),
            || (self.join_block(read), beside()),
        )
        .1
    }

    /// Appends a piece read; false when the file must be read line by line.
    fn join(&mut self, piece: &Piece) -> bool {
        if !piece.fine {
            return false;
        }
        for (file, piece) in [
            (&mut self.coloured, piece.coloured),
            (&mut self.has_uvs, piece.has_uvs),
        ] {
            if let Some(value) = piece {
                if *file.get_or_insert(value) != value {
                    return false;
                }
            }
        }
        let (vertices, uvs) = (self.positions.len(), self.uv_values.len());
        let (corners, uv_corners) = (self.face_indices.len(), self.uv_indices.len());
        let mut faces = 0;
        for statement in &piece.statements {
            self.statements.faces(statement.faces - faces);
            faces = statement.faces;
            let line = self.lines_before + statement.line + 1;
            let mut w = words(&statement.text);
            let fine = match w.next() {
                Some(b"mtllib") => {
                    self.statements.mtllib(w);
                    true
                }
                Some(b"usemtl") => {
                    self.statements.usemtl(&statement.text);
                    true
                }
                Some(b"l") => self
                    .statements
                    .polyline(w, line, vertices + statement.vertices)
                    .is_none(),
                _ => self.statements.tag(w, line).is_ok(),
            };
            if !fine {
                return false;
            }
        }
        self.statements.faces(piece.face_sizes.len() - faces);
        self.positions.extend_from_slice(&piece.positions);
        self.colours.extend_from_slice(&piece.colours);
        self.alpha |= piece.alpha;
        self.uv_values.extend_from_slice(&piece.uv_values);
        self.face_sizes.extend_from_slice(&piece.face_sizes);
        self.face_indices.extend_from_slice(&piece.face_indices);
        self.uv_indices.extend_from_slice(&piece.uv_indices);
        for (relative, before, indices, start) in [
            (
                &piece.relative_vertices,
                vertices,
                &mut self.face_indices,
                corners,
            ),
            (&piece.relative_uvs, uvs, &mut self.uv_indices, uv_corners),
        ] {
            for &(slot, index) in relative {
                let Some(index) = (before as i64)
                    .checked_add(index)
                    .filter(|&i| i >= 0)
                    .and_then(|i| u32::try_from(i).ok())
                else {
                    return false;
                };
                indices[start + slot as usize] = index;
            }
        }
        self.lines_before += piece.newlines;
        true
    }

    /// The file, or `None` when its problems need the line-by-line reader.
    fn finish(self) -> Option<MeshFile> {
        let collected = Collected {
            positions: self.positions,
            vertex_lines: Vec::new(),
            colours: (self.coloured == Some(true)).then_some(self.colours),
            alpha: self.alpha,
            uv_values: self.uv_values,
            uv_indices: self.uv_indices,
            has_uvs: self.has_uvs == Some(true),
            face_sizes: self.face_sizes,
            face_indices: self.face_indices,
            face_lines: Vec::new(),
            statements: self.statements,
        };
        match collected.finish(None, MeshOptions::default()) {
            Ok((file, None)) => Some(file),
            _ => None,
        }
    }
}

/// Where the block (or piece) that starts at `start` ends: `block` bytes
/// on, moved to the next line end.
fn block_end(data: &[u8], start: usize, block: usize) -> usize {
    let end = (start + block.max(1)).min(data.len());
    if end < data.len() {
        memchr(b'\n', &data[end - 1..]).map_or(data.len(), |at| end + at)
    } else {
        end
    }
}

/// Reads an OBJ file held in memory, `block` bytes and `piece` bytes at a
/// time (cut at line ends); `None` when the line-by-line reader must read it.
pub(crate) fn read_bytes(data: &[u8], block: usize, piece: usize) -> Option<MeshFile> {
    let mut reader = Reader::new(piece);
    let (mut reading, mut read) = (Block::default(), Block::default());
    let mut start = 0;
    while start < data.len() {
        let end = block_end(data, start, block);
        if !reader
            .overlap(&mut reading, &data[start..end], &read, || ())
            .0
        {
            return None;
        }
        std::mem::swap(&mut reading, &mut read);
        start = end;
    }
    reader.join_block(&read).then(|| reader.finish())?
}

/// Reads an OBJ file from `source` through two buffers of `block` bytes
/// (grown for a longer line), one filled while the other is read;
/// `Ok(None)` when the line-by-line reader must read it.
///
/// # Errors
/// Whatever reading `source` returns.
pub(crate) fn read_source(
    mut source: impl Read + Send,
    block: usize,
    piece: usize,
) -> std::io::Result<Option<MeshFile>> {
    let mut reader = Reader::new(piece);
    let (mut reading, mut read) = (Block::default(), Block::default());
    let mut front = FileBlock::new(block);
    front.fill(&mut source, &[], after_last_line)?;
    let mut back = FileBlock::new(block);
    loop {
        let (joined, filled) =
            reader.overlap(&mut reading, front.ready(), &read, || match front.at_end {
                true => Ok(false),
                false => back
                    .fill(&mut source, front.carried(), after_last_line)
                    .map(|()| true),
            });
        if !joined {
            return Ok(None);
        }
        std::mem::swap(&mut reading, &mut read);
        if !filled? {
            break;
        }
        std::mem::swap(&mut front, &mut back);
    }
    Ok(reader.join_block(&read).then(|| reader.finish()).flatten())
}
#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::obj::read_sequential;
    use crate::io::IoError;

    /// What a reader gives, as something to compare: the file, the
    /// positions' bits (so -0 and 0 differ), and the errors' messages.
    fn outcome(read: Result<(MeshFile, Option<IoError>), IoError>) -> String {
        match read {
            Ok((file, problem)) => {
                let bits: Vec<[u64; 3]> = file
                    .mesh
                    .positions()
                    .iter()
                    .map(|p| p.to_array().map(f64::to_bits))
                    .collect();
                format!("{file:?}\n{bits:?}\n{:?}", problem.map(|e| e.to_string()))
            }
            Err(e) => format!("error: {e}"),
        }
    }

    /// Checks the parallel reader against the line-by-line one on `data`,
    /// cut into blocks and pieces of many sizes (so that the cuts fall
    /// inside lines, words and numbers), from memory and from a stream.
    /// Returns whether the parallel reader read it without help.
    fn check(data: &str) -> bool {
        let data = data.as_bytes();
        let expected = outcome(read_sequential(data, MeshOptions::default()));
        let mut read_alone = None;
        for block in [1, 2, 3, 5, 7, 11, 16, 64, 1000, BLOCK] {
            for piece in [1, 2, 3, 4, 9, 17, 100, PIECE] {
                let fast = read_bytes(data, block, piece);
                let streamed = read_source(data, block, piece).unwrap();
                assert_eq!(fast.is_some(), streamed.is_some());
                let alone = fast.is_some();
                assert!(read_alone.is_none_or(|a| a == alone));
                read_alone = Some(alone);
                for got in [fast, streamed] {
                    let got = match got {
                        Some(file) => outcome(Ok((file, None))),
                        None => expected.clone(),
                    };
                    assert_eq!(got, expected, "block {block}, piece {piece}");
                }
            }
        }
        read_alone.unwrap()
    }

    #[test]
    fn plain_file_reads_alone_and_equal() {
        assert!(check(
            "# a square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"
        ));
    }

    #[test]
    fn tricky_well_formed_files_read_alone_and_equal() {
        let files = [
            // CRLF, tabs, blank lines, comments after statements, no final line end.
            "v 0 0 0\r\nv 1 0 0 # right\r\n\r\nv\t1 1 0\r\n\tv 0 1 0\r\nf 1 2 3\r\nf 1 3 4",
            // Negative (relative) indices across many vertices, mixed with positive ones.
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nf -3 -2 -1\nv 0 1 0\nf 1 -2 -1\nv 2 2 2\nv 3 3 3\nf -1 -2 -6\n",
            // v/vt, negative vt, vn ignored, w ignored, groups, objects, smoothing.
            "o thing\ng a\ns 1\nv 0 0 0 1\nv 1 0 0 1\nv 1 1 0 1\nvt 0 0\nvt 1 0\nvt 1 1 0\nvn 0 0 1\n\
             f 1/1/1 2/2/1 3/3/1\nf 1/-3 3/-1 2/-2\n",
            // v//vn.
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n",
            // Colours with and without alpha, numbers of every form.
            "v 0 0 0 1 0 0\nv 1e0 -0 +0.0 0 1 0\nv .5 1. -0.25e1 0 0 1\nv 1.7976931348623157e308 \
             2.2250738585072014e-308 0.30000000000000004 0.1 0.2 0.3 0.5\nf 1 2 3\nf 2 3 4\n",
            // Numbers past the direct path: many digits, long decimals.
            "v 0.123456789012345678901 12345678901234567890 -4.9939024390243905\n\
             v 9007199254740993 0.0000000000000000000000001 1e-320\nv 1 1 1\nf 1 2 3\n",
            // Materials, polylines and tags, faces between them.
            "mtllib a.mtl b.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nusemtl red stone\n\
             f 1 3 4\nusemtl blue\nf 4 3 2\nusemtl red stone\nf 2 1 4\nl 1 2 3\nl -1 -2\n\
             t crease 2/1/0 0 1 2.5\nt corner 1/1/0 3 inf\nt hole 1/0/0 2\nt other 0/0/0\n",
            // Comments at the start, back to back, inside a word, hiding a
            // face, and on a last line without its line end.
            "# first\n#\nv 0 0 0#x\nv 1 0 0 ##\n\nv 1 1 0\n# f 9 9 9\nf 1 2 3 # end",
            // A backslash is no line continuation in this reader: a word of a comment only.
            "v 0 0 0\nv 1 0 0\nv 1 1 0 # \\\nf 1 2 3\n",
            // No faces at all; an empty file.
            "v 1 2 3\n",
            "",
        ];
        for file in files {
            assert!(check(file), "{file}");
        }
    }

    #[test]
    fn problems_are_reported_as_line_by_line() {
        let files = [
            // Hard errors, each with its line.
            "v 0 0 0\nv 1 0\nf 1 2 3\n",
            "v 0 0 0\nv 1 0 x\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 0\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 -4\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 \\\n3\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 2\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 9\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 nan\nf 1 2 3\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 99999999999\n",
            // Problems with attributes: the mesh reads, the file does not.
            "v 0 0 0 1 0 0\nv 1 0 0\nv 1 1 0 0 0 1\nf 1 2 3\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nf 1/1 2/1 3\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nf 1/1 2/1 3/2\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nf 1/-2 2/1 3/1\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt\nf 1 2 3\n",
            "v 0 0 0 1 2\nv 1 0 0\nv 1 1 0\nf 1 2 3\n",
            "v 0 0 0 1 0 inf\nv 1 0 0 1 1 1\nv 1 1 0 1 1 1\nf 1 2 3\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nl 1\nl 1 9\nt crease 2/1/0 0 7 1\n",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nt crease 2/1/0 0 x 1\nt hole 1/0/0 5\n",
        ];
        for file in files {
            assert!(!check(file), "{file}");
        }
    }

    #[test]
    fn lines_on_the_edge_of_the_one_pass_reading_read_equal() {
        let square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
        let lines = [
            // Spacing the one-pass reading must take as the general one does.
            "f  1  2\t3  \r",
            "f 1 2 3 \x0c",
            "v\t2 2 2\nf 1 2 5",
            "v  2   2 2 \r\nf 1 2 5",
            // Numbers it leaves to the general reading.
            "v 1e5 2 3\nf 1 2 5",
            "v 12345678901234567890 1 2\nf 1 2 5",
            "v 0.12345678901234567 -9007199254740993 2\nf 1 2 5",
            "v +1 .5 1.\nf 1 2 5",
            "v -0 -0.0 0.\nf 1 2 5",
            "v inf 1 2\nf 1 2 5",
            "v - 1 2\nf 1 2 5",
            "v . 1 2\nf 1 2 5",
            "v 1 2 3 4\nf 1 2 5",
            "v 1 2\nf 1 2 5",
            "v 1 2 3 0.5 0.5 0.5\nf 1 2 5",
            "v 1 2 3x\nf 1 2 5",
            // Indices it leaves to the general reading.
            "f +1 2 3",
            "f 1 2 -1",
            "f 01 002 0000000003",
            "f 1 2 4294967296",
            "f 1 2 4294967297",
            "f 1 2 99999999999",
            "f 1 2 3a",
            "f 1 2 0",
            "f 1/1 2/2 3/3\nvt 0 0\nf 1 2 3",
            "vt 0 0\nvt 1 0\nvt 1 1\nf 1 2 3\nf 1/1 2/2 3/3",
            "f 1//1 2//1 3//1\nf 1 2 3",
            "f",
            "f ",
        ];
        for line in lines {
            check(&format!("{square}{line}\nf 1 2 3 4\n"));
        }
    }

    #[test]
    fn many_lines_cut_anywhere_read_equal() {
        // Enough lines for many pieces, negative indices across their cuts.
        let mut file = String::from("mtllib m.mtl\n");
        for i in 0..300 {
            let x = i as f64 * 0.1 - 7.3;
            file.push_str(&format!("v {x} {} {}\r\n", x * x, 1.0 / (i as f64 + 3.0)));
            if i % 7 == 0 {
                file.push_str("# comment\nusemtl m\n");
            }
            if i >= 3 {
                file.push_str(&format!("f -1 -2 {}\n", i - 1));
            }
        }
        file.push_str("l 1 2 3\nt corner 1/1/0 4 2\n");
        assert!(check(&file));
    }
}
