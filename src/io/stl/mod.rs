//! STL, ASCII and binary: a soup of triangles, each with its own three
//! corners. Read as such (3 vertices per triangle, unwelded); weld them with
//! [`super::ReadOptions::weld`] or the `weld` operation. Written as triangles:
//! polygons are split into fans.
//!
//! A file is binary when its size is exactly 84 + 50 × the triangle count at
//! byte 80 (binary headers may start with `solid` too), text when it starts
//! with `solid`, and binary otherwise.

use std::fs::File;
use std::io::{Read, Seek, Write};
use std::path::Path;

use glam::DVec3;
use rayon::prelude::*;

mod fast_text;

use super::blocks::write_in_blocks;
use super::decimal::push_point_line;
use super::text::{show, Tokens};
use super::{build_mesh, IoError, Location};
use crate::error::MeshError;
use crate::mesh::Mesh;

const HEADER: usize = 80;
const RECORD: usize = 50;

/// Parses an STL file, ASCII or binary.
///
/// # Errors
/// [`IoError::Parse`] with the byte offset where a binary file is too short
/// for its triangle count, or the line where a text file departs from
/// `facet normal … outer loop vertex … endloop endfacet`;
/// [`IoError::InvalidMesh`] for a non-finite coordinate.
pub fn parse(data: &[u8]) -> Result<Mesh, IoError> {
    match is_binary(data) {
        true => parse_binary(data),
        false => parse_ascii(data),
    }
}

/// Whether `data` is read as a binary file (see the module doc).
fn is_binary(data: &[u8]) -> bool {
    let binary_size = data
        .get(HEADER..HEADER + 4)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as u64 * RECORD as u64 + 84);
    binary_size == Some(data.len() as u64) || !starts_with_solid(data)
}

/// Whether `data`'s first word starts with `solid`, as a text file's does.
fn starts_with_solid(data: &[u8]) -> bool {
    let start = data
        .iter()
        .position(|b| !b.is_ascii_whitespace())
        .unwrap_or(0);
    data[start..].starts_with(b"solid")
}

fn parse_binary(data: &[u8]) -> Result<Mesh, IoError> {
    let Some(count) = data.get(HEADER..HEADER + 4) else {
        return Err(IoError::parse(
            Location::Byte(data.len()),
            format!(
                "binary STL ends after {} bytes; expected an 80-byte header and a 4-byte triangle count",
                data.len()
            ),
        ));
    };
    let count = u32::from_le_bytes([count[0], count[1], count[2], count[3]]) as usize;
    let available = (data.len() - 84) / RECORD;
    if count > available {
        return Err(IoError::parse(
            Location::Byte(84 + available * RECORD),
            format!(
                "binary STL is truncated: the header promises {count} triangles ({} bytes) but only {} bytes follow it",
                count as u64 * RECORD as u64,
                data.len() - 84
            ),
        ));
    }
    let mut positions = Vec::with_capacity(count * 3);
    push_corners(&mut positions, &data[84..84 + count * RECORD]);
    soup(positions)
}

/// Reads an STL file a block at a time, the next block read from the file
/// while this one is read, never holding all its bytes: binary, a block of
/// triangles at a time, and text, a block of facets at a time on all
/// threads. A binary file whose size is not that of its triangle count
/// (truncated, or text), and a text file with something to report or a
/// rarer form (see `fast_text`), are read whole, text word by word.
///
/// # Errors
/// As [`parse`], naming the file; [`IoError::File`] when the file cannot be
/// read.
pub(crate) fn read_path(path: &Path) -> Result<Mesh, IoError> {
    if let Some((mesh, _)) = read_in_blocks(path, BLOCK_TRIANGLES, Corners::Own)? {
        return Ok(mesh);
    }
    let failed = super::read_failed(path);
    let mut file = File::open(path).map_err(failed)?;
    // A truncated binary file is known by its start, before any block is
    // read (one holds no `endfacet` line to cut a block at).
    let mut head = Vec::new();
    Read::by_ref(&mut file)
        .take(1 << 16)
        .read_to_end(&mut head)
        .map_err(failed)?;
    if starts_with_solid(&head) {
        file.rewind().map_err(failed)?;
        let streamed = fast_text::read_source(file, fast_text::BLOCK, fast_text::PIECE);
        if let Some(mesh) = streamed.map_err(failed)? {
            return Ok(mesh);
        }
    }
    // Binary, or the pieces have given up: the words, not the pieces again.
    let data = super::read_bytes(path)?;
    let whole = match is_binary(&data) {
        true => parse_binary(&data),
        false => parse_ascii_words(&data),
    };
    whole.map_err(|e| e.in_file(path))
}

/// [`read_path`] for a weld to follow: the exact copies of a position near
/// each other in the file (a soup's every position, about six times) are
/// merged while reading, so that the positions held are about a sixth of
/// the corners (see `mend::weld::append_triangle_sites`); the weld of the
/// mesh is the weld of the soup. Returns the mesh and how many corners were
/// merged into a copy. Corners that are few copies of one another in the
/// first block (triangles in no spatial order) are read as [`read_path`]
/// reads them.
///
/// # Errors
/// As [`read_path`].
pub(crate) fn read_path_to_weld(path: &Path) -> Result<Option<(Mesh, usize)>, IoError> {
    read_in_blocks(path, BLOCK_TRIANGLES, Corners::MergedIfCopies)
}

/// How [`read_in_blocks`] makes a block's corners vertices.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Corners {
    /// Each corner a vertex of its own, as the file holds them.
    Own,
    /// The copies near each other merged, when the first block has many.
    MergedIfCopies,
}

/// The vertices read so far: every corner's, or the merged copies' sites
/// and each corner's site.
enum Vertices {
    Own(Vec<DVec3>),
    Merged {
        sites: Vec<DVec3>,
        corner_sites: Vec<u32>,
        corners: Vec<DVec3>,
    },
}

impl Vertices {
    fn push(&mut self, records: &[u8]) -> crate::error::Result<()> {
        match self {
            Vertices::Own(positions) => {
                push_corners(positions, records);
                Ok(())
            }
            Vertices::Merged {
                sites,
                corner_sites,
                corners,
            } => {
                corners.clear();
                push_corners(corners, records);
                crate::mend::weld::append_triangle_sites(corners, sites, corner_sites)
            }
        }
    }
}

/// [`read_path`], `block_triangles` at a time, the corners made vertices
/// as `corners` says; with the mesh, how many corners were merged.
fn read_in_blocks(
    path: &Path,
    block_triangles: usize,
    corners: Corners,
) -> Result<Option<(Mesh, usize)>, IoError> {
    let block_triangles = block_triangles.max(1);
    let failed = super::read_failed(path);
    let mut file = File::open(path).map_err(failed)?;
    let size = file.metadata().map_err(failed)?.len();
    let mut head = [0u8; 84];
    if size < 84 {
        return Ok(None);
    }
    file.read_exact(&mut head).map_err(failed)?;
    let count = u32::from_le_bytes([head[80], head[81], head[82], head[83]]) as usize;
    if count as u64 * RECORD as u64 + 84 != size {
        return Ok(None);
    }
    let block = count.min(block_triangles) * RECORD;
    let (mut front, mut back) = (vec![0u8; block], vec![0u8; block]);
    let mut left = count;
    let mut filled = left.min(block_triangles) * RECORD;
    file.read_exact(&mut front[..filled]).map_err(failed)?;
    left -= filled / RECORD;
    let merged = corners == Corners::MergedIfCopies && {
        // The sample's triangles only: the block is decoded once, below.
        let sample = filled.min(crate::mend::weld::COPIES_SAMPLE.div_ceil(3) * RECORD);
        let mut first = Vec::new();
        push_corners(&mut first, &front[..sample]);
        crate::mend::weld::worth_merging(&first)
    };
    let mut vertices = if merged {
        Vertices::Merged {
            sites: Vec::new(),
            corner_sites: Vec::with_capacity(count * 3),
            corners: Vec::with_capacity(block / RECORD * 3),
        }
    } else {
        Vertices::Own(Vec::with_capacity(count * 3))
    };
    let out_of_memory = |source| IoError::Weld {
        path: path.to_path_buf(),
        source,
    };
    while filled > 0 {
        let next = left.min(block_triangles) * RECORD;
        let (pushed, read_next) = rayon::join(
            || vertices.push(&front[..filled]),
            || file.read_exact(&mut back[..next]),
        );
        pushed.map_err(out_of_memory)?;
        read_next.map_err(failed)?;
        std::mem::swap(&mut front, &mut back);
        (filled, left) = (next, left - next / RECORD);
    }
    let (mesh, merged) = match vertices {
        Vertices::Own(positions) => (soup(positions), 0),
        Vertices::Merged {
            sites,
            corner_sites,
            ..
        } => {
            let merged = corner_sites.len() - sites.len();
            (merged_soup(sites, corner_sites), merged)
        }
    };
    mesh.map(|mesh| Some((mesh, merged)))
        .map_err(|e| e.in_file(path))
}

/// Triangles a block of [`read_path`] holds: 13 MB.
const BLOCK_TRIANGLES: usize = 1 << 18;

/// Appends the corners of binary STL `records` (whole ones), each on its
/// own, written on all threads.
fn push_corners(positions: &mut Vec<DVec3>, records: &[u8]) {
    let corners = records.len() / RECORD * 3;
    positions.par_extend((0..corners).into_par_iter().with_min_len(4096).map(|v| {
        let (t, corner) = (v / 3, v % 3);
        let at = t * RECORD + 12 + corner * 12;
        let xyz: [f64; 3] = std::array::from_fn(|axis| {
            let b = &records[at + axis * 4..at + axis * 4 + 4];
            f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64
        });
        DVec3::from_array(xyz)
    }));
}

/// The mesh of a binary file's corners: a triangle every three.
fn soup(positions: Vec<DVec3>) -> Result<Mesh, IoError> {
    let mut indices = Vec::with_capacity(positions.len());
    indices.par_extend(
        (0..positions.len() as u32)
            .into_par_iter()
            .with_min_len(4096),
    );
    mesh_of_triangles(positions, indices, |v| Location::Byte(corner_byte(v)))
}

/// The mesh of a binary file's triangles, three `corner_vertices` each.
fn mesh_of_triangles(
    positions: Vec<DVec3>,
    corner_vertices: Vec<u32>,
    vertex_location: impl Fn(usize) -> Location,
) -> Result<Mesh, IoError> {
    let count = corner_vertices.len() / 3;
    let mut sizes = Vec::with_capacity(count);
    sizes.par_extend(rayon::iter::repeat_n(3u32, count).with_min_len(4096));
    build_mesh(positions, sizes, corner_vertices, vertex_location, |f| {
        Location::Byte(84 + f * RECORD)
    })
}

/// The mesh of a binary file's corners merged into `sites`: a triangle
/// every three corners, each naming its corner's site. A non-finite
/// position is reported at its first corner, as [`soup`] reports it.
fn merged_soup(sites: Vec<DVec3>, corner_sites: Vec<u32>) -> Result<Mesh, IoError> {
    if crate::mesh::first_non_finite(&sites).is_some() {
        let corner = corner_sites
            .par_iter()
            .position_first(|&s| !sites[s as usize].is_finite())
            .unwrap_or(0);
        let p = sites[corner_sites[corner] as usize];
        return Err(IoError::InvalidMesh {
            file: None,
            location: Location::Byte(corner_byte(corner)),
            source: MeshError::NonFiniteCoordinate {
                vertex: corner,
                x: p.x,
                y: p.y,
                z: p.z,
            },
        });
    }
    // Every position is finite: no vertex to locate.
    mesh_of_triangles(sites, corner_sites, |_| Location::Byte(0))
}

/// Where corner `v` of a binary file starts.
fn corner_byte(v: usize) -> usize {
    84 + v / 3 * RECORD + 12 + v % 3 * 12
}

/// A text file's mesh: on all threads, or word by word when the file has
/// something to report or a form the pieces leave to it.
fn parse_ascii(data: &[u8]) -> Result<Mesh, IoError> {
    match fast_text::read(data, fast_text::PIECE) {
        Some(mesh) => Ok(mesh),
        None => parse_ascii_words(data),
    }
}

/// [`parse_ascii`] word by word, each vertex and facet with its line.
fn parse_ascii_words(data: &[u8]) -> Result<Mesh, IoError> {
    let mut tokens = Tokens::new(data, 1);
    let mut positions = Vec::new();
    let mut vertex_lines = Vec::new();
    let mut face_sizes = Vec::new();
    let mut face_lines = Vec::new();
    tokens.expect_keyword("solid")?;
    tokens.skip_line(); // the solid's name
    while let Some((word, line)) = tokens.next_word() {
        if word.eq_ignore_ascii_case(b"endsolid") {
            tokens.skip_line();
            // Some files hold several solids one after another.
            if tokens
                .next_word()
                .is_some_and(|(w, _)| w.eq_ignore_ascii_case(b"solid"))
            {
                tokens.skip_line();
                continue;
            }
            break;
        }
        if !word.eq_ignore_ascii_case(b"facet") {
            return Err(IoError::parse(
                Location::Line(line),
                format!("expected \"facet\" or \"endsolid\", found {}", show(word)),
            ));
        }
        let size = read_facet(&mut tokens, &mut positions, |line| vertex_lines.push(line))?;
        face_sizes.push(size);
        face_lines.push(line);
    }
    let indices = (0..positions.len() as u32).collect();
    build_mesh(
        positions,
        face_sizes,
        indices,
        |v| Location::Line(vertex_lines[v]),
        |f| Location::Line(face_lines[f]),
    )
}

/// Reads a facet after its word `facet`, through `endfacet`: pushes its
/// corners (telling `corner_line` each one's line) and returns their count.
fn read_facet(
    tokens: &mut Tokens,
    positions: &mut Vec<DVec3>,
    mut corner_line: impl FnMut(usize),
) -> Result<u32, IoError> {
    tokens.expect_keyword("normal")?;
    for _ in 0..3 {
        tokens.next_f64("a normal coordinate")?;
    }
    tokens.expect_keyword("outer")?;
    tokens.expect_keyword("loop")?;
    let mut size = 0u32;
    loop {
        let (word, line) = tokens.expect_word("\"vertex\" or \"endloop\"")?;
        if word.eq_ignore_ascii_case(b"endloop") {
            break;
        }
        if !word.eq_ignore_ascii_case(b"vertex") {
            return Err(IoError::parse(
                Location::Line(line),
                format!("expected \"vertex\" or \"endloop\", found {}", show(word)),
            ));
        }
        let x = tokens.next_f64("the x coordinate of a vertex")?;
        let y = tokens.next_f64("the y coordinate of a vertex")?;
        let z = tokens.next_f64("the z coordinate of a vertex")?;
        positions.push(DVec3::new(x, y, z));
        corner_line(line);
        size += 1;
    }
    tokens.expect_keyword("endfacet")?;
    Ok(size)
}

/// The triangles of face `f`, as a fan from its first corner.
fn face_triangles(mesh: &Mesh, f: usize) -> impl Iterator<Item = [DVec3; 3]> + '_ {
    let face = mesh.face(f);
    let p = |i: usize| mesh.positions()[face[i] as usize];
    (1..face.len() - 1).map(move |i| [p(0), p(i), p(i + 1)])
}

fn normal([a, b, c]: [DVec3; 3]) -> DVec3 {
    (b - a).cross(c - a).normalize_or_zero()
}

/// Writes a mesh as STL, binary or text. Binary stores `f32` coordinates;
/// text keeps every digit of the `f64`s.
///
/// # Errors
/// Whatever the writer returns; [`std::io::ErrorKind::InvalidInput`] when a
/// binary file would need more than 2^32 − 1 triangles, or naming the first
/// vertex with a coordinate beyond the `f32` range (about 3.4e38), which
/// would be written as infinity; text STL keeps such coordinates.
pub fn write(w: &mut dyn Write, mesh: &Mesh, ascii: bool) -> std::io::Result<()> {
    if ascii {
        writeln!(w, "solid weft")?;
        write_in_blocks(w, mesh.face_count(), |faces, w| {
            for t in faces.flat_map(|f| face_triangles(mesh, f)) {
                push_point_line(w, b"  facet normal ", normal(t));
                w.extend_from_slice(b"    outer loop\n");
                for p in t {
                    push_point_line(w, b"      vertex ", p);
                }
                w.extend_from_slice(b"    endloop\n  endfacet\n");
            }
            Ok(())
        })?;
        writeln!(w, "endsolid weft")?;
        return Ok(());
    }
    let count: u64 = mesh.face_sizes().iter().map(|&s| s as u64 - 2).sum();
    let count = u32::try_from(count).map_err(|_| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            "too many triangles for a binary STL file",
        )
    })?;
    let positions = mesh.positions();
    if let Some(&v) = mesh
        .face_indices()
        .iter()
        .find(|&&v| positions[v as usize].abs().max_element() > f32::MAX as f64)
    {
        let p = positions[v as usize];
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            format!(
                "vertex {v} ({}, {}, {}) is beyond the range of the 32-bit floats of a binary STL file; write text STL instead",
                p.x, p.y, p.z
            ),
        ));
    }
    let mut header = [b' '; HEADER];
    let title = format!("binary STL written by weft {}", crate::VERSION);
    header[..title.len()].copy_from_slice(title.as_bytes());
    w.write_all(&header)?;
    w.write_all(&count.to_le_bytes())?;
    write_in_blocks(w, mesh.face_count(), |faces, w| {
        for t in faces.flat_map(|f| face_triangles(mesh, f)) {
            let mut record = [0u8; RECORD];
            for (k, v) in std::iter::once(normal(t)).chain(t).enumerate() {
                for (axis, c) in v.to_array().into_iter().enumerate() {
                    let at = k * 12 + axis * 4;
                    record[at..at + 4].copy_from_slice(&(c as f32).to_le_bytes());
                }
            }
            w.extend_from_slice(&record);
        }
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::shapes;

    fn binary(mesh: &Mesh) -> Vec<u8> {
        let mut bytes = Vec::new();
        write(&mut bytes, mesh, false).unwrap();
        bytes
    }

    /// A file of `bytes` under a name of its own, removed when dropped.
    struct Scratch(tempfile::TempPath);

    impl Scratch {
        fn new(name: &str, bytes: &[u8]) -> Scratch {
            let mut file = tempfile::Builder::new()
                .prefix(&format!("weft-stl-{name}-"))
                .suffix(".stl")
                .tempfile()
                .unwrap();
            std::io::Write::write_all(&mut file, bytes).unwrap();
            Scratch(file.into_temp_path())
        }
    }

    /// Each position's bits (so -0 and 0 differ).
    pub(super) fn position_bits(mesh: &Mesh) -> Vec<[u64; 3]> {
        let positions = mesh.positions().iter();
        positions.map(|p| p.to_array().map(f64::to_bits)).collect()
    }

    /// The mesh `read_in_blocks` gives for a file of `bytes`, with its
    /// [`position_bits`].
    fn read_file(bytes: &[u8], block_triangles: usize) -> Option<(Mesh, Vec<[u64; 3]>)> {
        let file = Scratch::new(&format!("{}-{block_triangles}", bytes.len()), bytes);
        let (mesh, merged) = read_in_blocks(&file.0, block_triangles, Corners::Own).unwrap()?;
        assert_eq!(merged, 0);
        let bits = position_bits(&mesh);
        Some((mesh, bits))
    }

    /// A triangle torus whose first vertex has x = -0, which reading must
    /// keep apart from +0 bit for bit.
    fn torus_with_negative_zero(rows: usize, columns: usize) -> Mesh {
        let mut torus = shapes::triangle_torus(rows, columns);
        torus.positions_mut()[0].x = -0.0;
        torus
    }

    /// A soup of `mesh`'s faces (fans of triangles) in a binary file's
    /// bytes, with a triangle whose corners are two copies of one position
    /// and one at a single position, in front and in the middle: welded,
    /// each collapses.
    fn soup_bytes(mesh: &Mesh) -> Vec<u8> {
        let faces = binary(mesh);
        let (p, q) = (mesh.positions()[0], mesh.positions()[1]);
        let extra = Mesh::new(vec![p, q, p, p, p, p], vec![3, 3], vec![0, 1, 2, 3, 4, 5]);
        let extra = binary(&extra.unwrap());
        let middle = 84 + mesh.face_count() / 2 * RECORD;
        let mut soup = faces[..84].to_vec();
        for part in [
            &extra[84..],
            &faces[84..middle],
            &extra[84..],
            &faces[middle..],
        ] {
            soup.extend_from_slice(part);
        }
        let count = (soup.len() - 84) / RECORD;
        soup[80..84].copy_from_slice(&(count as u32).to_le_bytes());
        soup
    }

    #[test]
    fn copies_merged_while_reading_weld_as_the_soup_does() {
        // 80,000 triangles: two pieces of copies, and blocks of any size.
        let bytes = soup_bytes(&torus_with_negative_zero(200, 200));
        let soup = parse(&bytes).unwrap();
        for block in [1, 999, 65_536, BLOCK_TRIANGLES] {
            let file = Scratch::new(&format!("merged-{block}"), &bytes);
            let (mesh, merged) = read_in_blocks(&file.0, block, Corners::MergedIfCopies)
                .unwrap()
                .unwrap();
            assert_eq!(mesh.face_count(), soup.face_count());
            assert_eq!(mesh.vertex_count() + merged, soup.vertex_count());
            // A first block of one triangle shows no copies: read as the soup.
            let merging = block > 1;
            assert_eq!(
                mesh.vertex_count() < soup.vertex_count() / 4,
                merging,
                "block of {block}"
            );
            // Every corner keeps its position, bit for bit.
            let corner_bits = |m: &Mesh| -> Vec<[u64; 3]> {
                let bits = position_bits(m);
                m.face_indices().iter().map(|&v| bits[v as usize]).collect()
            };
            let same_corners = corner_bits(&mesh) == corner_bits(&soup);
            assert!(same_corners, "block of {block}");
            for tolerance in [0.0, 1e-9, 0.01, 0.3] {
                let (welded, report) = crate::mend::weld::weld(&mesh, tolerance).unwrap();
                let (expected, expected_report) =
                    crate::mend::weld::weld(&soup, tolerance).unwrap();
                let same = position_bits(&welded) == position_bits(&expected) && welded == expected;
                assert!(same, "block of {block}, tolerance {tolerance}");
                assert_eq!(
                    report.merged_vertex_count + merged,
                    expected_report.merged_vertex_count
                );
                assert_eq!(
                    (report.removed_face_count, report.unused_vertex_count),
                    (
                        expected_report.removed_face_count,
                        expected_report.unused_vertex_count
                    )
                );
                assert!(report.removed_face_count >= 4);
            }
        }
    }

    #[test]
    fn corners_with_few_copies_are_read_as_their_own_vertices() {
        // Every triangle its own, far from the others: nothing to merge.
        let triangles: Vec<DVec3> = (0..3000)
            .map(|i| DVec3::new(i as f64, (i % 3) as f64, 0.5 * i as f64))
            .collect();
        let mesh = Mesh::new(triangles, vec![3; 1000], (0..3000).collect()).unwrap();
        let bytes = binary(&mesh);
        let file = Scratch::new("few-copies", &bytes);
        let (read, merged) = read_in_blocks(&file.0, 100, Corners::MergedIfCopies)
            .unwrap()
            .unwrap();
        assert_eq!((read, merged), (parse(&bytes).unwrap(), 0));
    }

    #[test]
    fn binary_files_read_in_blocks_of_any_size_as_their_bytes_parse() {
        let bytes = binary(&torus_with_negative_zero(6, 5));
        let whole = parse(&bytes).unwrap();
        let bits = position_bits(&whole);
        let triangles = whole.face_count();
        for block in [
            0,
            1,
            2,
            7,
            triangles - 1,
            triangles,
            triangles + 5,
            BLOCK_TRIANGLES,
        ] {
            let (mesh, read_bits) = read_file(&bytes, block).unwrap();
            assert_eq!(mesh, whole, "block of {block}");
            assert_eq!(read_bits, bits, "block of {block}");
        }
        // No triangles at all.
        let empty = binary(&Mesh::empty());
        assert_eq!(read_file(&empty, 4).unwrap().0, Mesh::empty());
    }

    #[test]
    fn files_whose_size_is_not_their_triangle_count_are_left_to_the_whole_reading() {
        let bytes = binary(&shapes::cube());
        // Truncated, one byte too long, shorter than a header, and text.
        assert!(read_file(&bytes[..bytes.len() - 1], 3).is_none());
        assert!(read_file(&[&bytes[..], b" "].concat(), 3).is_none());
        assert!(read_file(&bytes[..40], 3).is_none());
        let mut text = Vec::new();
        write(&mut text, &shapes::cube(), true).unwrap();
        assert!(read_file(&text, 3).is_none());
    }

    #[test]
    fn text_files_read_from_disk_as_their_bytes_parse() {
        let mut text = Vec::new();
        write(&mut text, &torus_with_negative_zero(30, 20), true).unwrap();
        let file = Scratch::new("text", &text);
        let read = read_path(&file.0).unwrap();
        let whole = parse(&text).unwrap();
        assert_eq!(
            (&read, position_bits(&read)),
            (&whole, position_bits(&whole))
        );
        // A broken facet: the whole reading names its line.
        let broken = String::from_utf8(text)
            .unwrap()
            .replacen("endloop", "endlop", 7);
        let file = Scratch::new("text-broken", broken.as_bytes());
        let error = read_path(&file.0).unwrap_err().to_string();
        assert_eq!(
            error,
            parse(broken.as_bytes())
                .unwrap_err()
                .in_file(&file.0)
                .to_string()
        );
        assert!(
            error.contains("line 7:") && error.contains("\"endlop\""),
            "{error}"
        );
        // A truncated binary file: the whole reading names where it ends.
        let truncated = &binary(&shapes::cube())[..84 + 5 * RECORD + 7];
        let file = Scratch::new("truncated", truncated);
        let error = read_path(&file.0).unwrap_err().to_string();
        assert_eq!(
            error,
            parse(truncated).unwrap_err().in_file(&file.0).to_string()
        );
        assert!(error.contains("truncated"), "{error}");
    }

    #[test]
    fn a_non_finite_corner_read_in_blocks_is_named_by_its_byte() {
        let mut bytes = binary(&shapes::cube());
        // The second triangle's third corner's y.
        let at = 84 + RECORD + 12 + 2 * 12 + 4;
        bytes[at..at + 4].copy_from_slice(&f32::NAN.to_le_bytes());
        let file = Scratch::new("nan", &bytes);
        let streamed = read_in_blocks(&file.0, 1, Corners::Own);
        let streamed = streamed.unwrap_err().to_string();
        let whole = parse(&bytes).unwrap_err().in_file(&file.0).to_string();
        assert_eq!(streamed, whole);
        assert!(streamed.contains(&format!("byte {}", at - 4)), "{streamed}");
        // Merged while reading, named by the same corner.
        let merged = read_in_blocks(&file.0, 12, Corners::MergedIfCopies);
        assert_eq!(merged.unwrap_err().to_string(), whole);
    }
}
