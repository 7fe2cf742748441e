//! `weft evaluate`: points of a cage's limit surface at given face
//! parameters, with the surface's normals, one line per sample.

use std::io::Write;
use std::path::{Path, PathBuf};

use weft::subdivide::{LimitSurface, Scheme};
use weft::DVec3;

use crate::args::mesh_path;
use crate::carry::with_file_tags;
use crate::files::{with_progress, write_stdout};
use crate::subdivide::{read_cage, Cage};
use crate::{Cli, Failure};

/// The arguments of `weft evaluate`.
#[derive(clap::Args)]
pub struct Evaluate {
    /// The cage to read (.obj, .ply, .stl, .off).
    #[arg(value_parser = mesh_path)]
    pub input: PathBuf,
    /// The samples: one per line, `face u v` (a 0-based cage face and its
    /// parameters, as the C ABI's weft_limit_surface_evaluate documents
    /// them); `#` starts a comment.
    #[arg(long, value_name = "FILE")]
    pub samples: PathBuf,
    /// Where to write the results (default: standard output): one line per
    /// sample, `x y z nx ny nz`, the point and the unit normal.
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
    #[command(flatten)]
    pub cage: Cage,
}

pub fn run(cli: &Cli, args: &Evaluate) -> Result<(), Failure> {
    let Evaluate {
        input,
        samples,
        output,
        cage,
    } = args;
    let (faces, uvs) = read_samples(samples)?;
    let (file, options) = read_cage(cli, input, cage)?;
    let options = with_file_tags(options, &file);
    let scheme = Scheme::from(cage.scheme);
    let count = faces.len();
    let (mut positions, mut du, mut dv) = (
        vec![DVec3::ZERO; count],
        vec![DVec3::ZERO; count],
        vec![DVec3::ZERO; count],
    );
    let surface = with_progress("preparing the limit surface", || {
        LimitSurface::new(&file.mesh, scheme, &options)
    })
    .map_err(|e| Failure::Failed(format!("{}: {e}; nothing written", input.display())))?;
    with_progress("evaluating", || {
        surface.evaluate(&faces, &uvs, &mut positions, Some(&mut du), Some(&mut dv))
    })
    .map_err(|e| {
        // The library names the sample (0-based, in the file's order) and its face.
        Failure::Failed(format!("{}: {e}; nothing written", samples.display()))
    })?;
    let write = |out: &mut dyn Write| -> std::io::Result<()> {
        for ((p, a), b) in positions.iter().zip(&du).zip(&dv) {
            let n = a.cross(*b).normalize_or_zero();
            writeln!(
                out,
                "{:?} {:?} {:?} {:?} {:?} {:?}",
                p.x, p.y, p.z, n.x, n.y, n.z
            )?;
        }
        Ok(())
    };
    match output {
        Some(path) => weft::io::write_atomically(path, |w| write(w))?,
        None => write_stdout(write)?,
    }
    Ok(())
}

/// The samples file: `face u v` per line.
fn read_samples(path: &Path) -> Result<(Vec<u32>, Vec<f64>), Failure> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| Failure::Failed(format!("{}: cannot read: {e}", path.display())))?;
    let (mut faces, mut uvs) = (Vec::new(), Vec::new());
    for (k, line) in text.lines().enumerate() {
        let content = line.split('#').next().unwrap_or("").trim();
        if content.is_empty() {
            continue;
        }
        let bad = |what: &str| {
            Failure::Failed(format!(
                "{}: line {}: {what}; a sample is `face u v` (a 0-based face index and two numbers)",
                path.display(),
                k + 1
            ))
        };
        let words: Vec<&str> = content.split_whitespace().collect();
        if words.len() != 3 {
            return Err(bad(&format!("{} values", words.len())));
        }
        let face = words[0]
            .parse::<u32>()
            .map_err(|_| bad(&format!("the face {:?} is not a face index", words[0])))?;
        let number = |w: &str| {
            w.parse::<f64>()
                .map_err(|_| bad(&format!("{w:?} is not a number")))
        };
        faces.push(face);
        uvs.push(number(words[1])?);
        uvs.push(number(words[2])?);
    }
    if faces.is_empty() {
        return Err(Failure::Failed(format!(
            "{}: holds no sample; one per line, `face u v`",
            path.display()
        )));
    }
    Ok((faces, uvs))
}
