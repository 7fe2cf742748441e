//! Crease side files: creases and corners for `weft subdivide --creases`,
//! for meshes in formats that cannot hold them (PLY, OFF, STL) or to add to
//! an OBJ's own.
//!
//! One statement per line; `#` starts a comment; blank lines are skipped.
//! Vertex indices count from 0 in the mesh file's vertex order (as PLY, OFF
//! and OpenSubdiv's `t crease` tags count them):
//!
//! ```text
//! # i j sharpness: the edge from vertex i to vertex j
//! 0 1 inf          # a hard crease
//! 1 2 2.5          # semi-sharp: sharp for 2 levels, then softens
//! crease 2 3 1     # the same with a keyword
//! corner 4 inf     # vertex 4 stays where it is
//! ```
//!
//! A sharpness is a number of 0 or more, or `inf` (`infinite`, `infinity`);
//! 10 or more is infinite, as in OpenSubdiv.

use std::path::Path;

use super::mesh_file::{parse_sharpness, FileCorner, FileCrease};
use super::text::{lines, parse_count, words};
use super::{IoError, Location};

/// Creases and corners of a side file, in file order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CreaseFile {
    pub creases: Vec<FileCrease>,
    pub corners: Vec<FileCorner>,
}

const EXPECTED: &str =
    "expected \"i j sharpness\", \"crease i j sharpness\" or \"corner v sharpness\"";

/// Parses a crease side file (format in the module doc).
///
/// # Errors
/// [`IoError::Parse`] naming the line and what was expected there.
pub fn parse(data: &[u8]) -> Result<CreaseFile, IoError> {
    let mut file = CreaseFile::default();
    for (line, text) in lines(data) {
        let w: Vec<&[u8]> = words(text).collect();
        let bad = |what: String| IoError::parse(Location::Line(line), what);
        let vertex = |word: &[u8]| -> Result<u32, IoError> {
            let i = parse_count(word, line, "a vertex index")?;
            u32::try_from(i).map_err(|_| bad(format!("vertex index {i} is too large")))
        };
        match w.as_slice() {
            [] => {}
            [keyword, v, s] if keyword.eq_ignore_ascii_case(b"corner") => {
                file.corners.push(FileCorner {
                    vertex: vertex(v)?,
                    sharpness: parse_sharpness(s, line)?,
                    line,
                });
            }
            [keyword, i, j, s] if keyword.eq_ignore_ascii_case(b"crease") => {
                file.creases.push(crease(vertex(i)?, vertex(j)?, s, line)?);
            }
            [i, j, s] if i.first().is_some_and(u8::is_ascii_digit) => {
                file.creases.push(crease(vertex(i)?, vertex(j)?, s, line)?);
            }
            [first, ..] => {
                let found = String::from_utf8_lossy(text).trim().to_owned();
                let hint = if first.eq_ignore_ascii_case(b"corner") {
                    "; a corner takes one vertex and a sharpness".to_owned()
                } else if first.eq_ignore_ascii_case(b"crease") || first[0].is_ascii_digit() {
                    "; a crease takes two vertices and a sharpness".to_owned()
                } else {
                    String::new()
                };
                return Err(bad(format!("{EXPECTED}, found \"{found}\"{hint}")));
            }
        }
    }
    Ok(file)
}

fn crease(a: u32, b: u32, sharpness: &[u8], line: usize) -> Result<FileCrease, IoError> {
    if a == b {
        return Err(IoError::parse(
            Location::Line(line),
            format!("a crease joins two different vertices; both are {a}"),
        ));
    }
    Ok(FileCrease {
        edge: [a, b],
        sharpness: parse_sharpness(sharpness, line)?,
        line,
    })
}

/// Reads a crease side file.
///
/// # Errors
/// [`IoError::File`] when it cannot be read; [`IoError::Parse`] naming the
/// file and line of a malformed statement.
pub fn read(path: impl AsRef<Path>) -> Result<CreaseFile, IoError> {
    let path = path.as_ref();
    let bytes = super::read_bytes(path)?;
    parse(&bytes).map_err(|e| e.in_file(path))
}

/// Writes creases and corners as a side file.
///
/// # Errors
/// Whatever the writer returns.
pub fn write(w: &mut dyn std::io::Write, file: &CreaseFile) -> std::io::Result<()> {
    writeln!(w, "# weft creases: i j sharpness, corner v sharpness")?;
    for c in &file.creases {
        writeln!(
            w,
            "{} {} {}",
            c.edge[0],
            c.edge[1],
            sharpness_word(c.sharpness)
        )?;
    }
    for c in &file.corners {
        writeln!(w, "corner {} {}", c.vertex, sharpness_word(c.sharpness))?;
    }
    Ok(())
}

fn sharpness_word(s: f64) -> String {
    if s >= crate::subdivide::SHARPNESS_INFINITE {
        "inf".to_owned()
    } else {
        s.to_string()
    }
}
