//! OpenSubdiv's tags in an OBJ file: `t crease`, `t corner` and `t hole`.

use crate::io::mesh_file::{parse_sharpness, FileCorner, FileCrease};
use crate::io::text::parse_count;
use crate::io::{IoError, Location};

/// Reads an OpenSubdiv tag: `t NAME ints/floats/strings INTS FLOATS STRINGS`.
/// `crease`, `corner` and `hole` are read; any other tag (OpenSubdiv's
/// hierarchical edits among them) is passed over.
pub(super) fn tag(
    w: Vec<&[u8]>,
    line: usize,
    creases: &mut Vec<FileCrease>,
    corners: &mut Vec<FileCorner>,
    holes: &mut Vec<(u32, usize)>,
) -> Result<(), IoError> {
    let bad = |what: &str| IoError::parse(Location::Line(line), what.to_owned());
    let Some(&name) = w.first() else {
        return Err(bad("expected a tag name after \"t\""));
    };
    if name == b"hole" {
        return hole_tag(&w, line, holes);
    }
    let is_crease = name == b"crease";
    if !is_crease && name != b"corner" {
        return Ok(());
    }
    let form = if is_crease {
        "expected \"t crease 2/1/0 i j sharpness\" (0-based vertex indices)"
    } else {
        "expected \"t corner 1/1/0 v sharpness\" (0-based vertex indices)"
    };
    let counts: Vec<&[u8]> = w
        .get(1)
        .map(|c| c.split(|&b| b == b'/').collect())
        .unwrap_or_default();
    if counts.len() < 2 || counts.len() > 3 {
        return Err(bad(form));
    }
    let ints = parse_count(counts[0], line, "the number of integer arguments")?;
    let floats = parse_count(counts[1], line, "the number of float arguments")?;
    let args = &w[2..];
    if args.len() < ints.saturating_add(floats) {
        return Err(bad(&format!("{form}; the tag announces {ints} indices and {floats} sharpness values but has {} arguments", args.len())));
    }
    let mut vertices = Vec::with_capacity(ints);
    for word in &args[..ints] {
        let v = parse_count(word, line, "a vertex index")?;
        vertices.push(u32::try_from(v).map_err(|_| bad("a vertex index is too large"))?);
    }
    let sharpness = args[ints..ints + floats]
        .iter()
        .map(|word| parse_sharpness(word, line))
        .collect::<Result<Vec<f64>, IoError>>()?;
    let segments = if is_crease {
        ints.saturating_sub(1)
    } else {
        ints
    };
    if segments == 0 || !(sharpness.len() == 1 || sharpness.len() == segments) {
        return Err(bad(&format!(
            "{form}; one sharpness for all or one per {}",
            if is_crease { "segment" } else { "vertex" }
        )));
    }
    let s = |i: usize| sharpness[if sharpness.len() == 1 { 0 } else { i }];
    if is_crease {
        for (i, pair) in vertices.windows(2).enumerate() {
            if pair[0] == pair[1] {
                return Err(bad("a crease joins two different vertices"));
            }
            creases.push(FileCrease {
                edge: [pair[0], pair[1]],
                sharpness: s(i),
                line,
            });
        }
    } else {
        for (i, &vertex) in vertices.iter().enumerate() {
            corners.push(FileCorner {
                vertex,
                sharpness: s(i),
                line,
            });
        }
    }
    Ok(())
}

/// Reads `t hole N/0/0 f1 … fN`: 0-based face indices.
fn hole_tag(w: &[&[u8]], line: usize, holes: &mut Vec<(u32, usize)>) -> Result<(), IoError> {
    let form = "expected \"t hole N/0/0 f1 ... fN\" (0-based face indices)";
    let bad = |what: String| IoError::parse(Location::Line(line), what);
    let counts: Vec<&[u8]> = w
        .get(1)
        .map(|c| c.split(|&b| b == b'/').collect())
        .unwrap_or_default();
    if counts.len() < 2 || counts.len() > 3 {
        return Err(bad(form.to_owned()));
    }
    let ints = parse_count(counts[0], line, "the number of integer arguments")?;
    let args = &w[2..];
    if args.len() < ints {
        return Err(bad(format!(
            "{form}; the tag announces {ints} faces but has {} arguments",
            args.len()
        )));
    }
    for word in &args[..ints] {
        let f = parse_count(word, line, "a face index")?;
        let f = u32::try_from(f).map_err(|_| bad("a face index is too large".to_owned()))?;
        holes.push((f, line));
    }
    Ok(())
}
