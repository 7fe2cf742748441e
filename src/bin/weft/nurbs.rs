//! `weft nurbs`: the Catmull-Clark limit surface of a cage as bicubic
//! B-spline patches in a STEP file, for CAD (Rhino, FreeCAD, OpenCASCADE).

use std::path::{Path, PathBuf};

use weft::io::{self, step};
use weft::subdivide::{limit_patches, Scheme, MAX_ISOLATION};

use crate::args::{mesh_path, step_path};
use crate::carry::with_file_tags;
use crate::files::{operation_failed, with_progress};
use crate::subdivide::{read_cage, Cage};
use crate::{Cli, Failure};

/// The arguments of `weft nurbs`.
#[derive(clap::Args)]
pub struct Nurbs {
    /// The cage to read (.obj, .ply, .stl, .off).
    #[arg(value_parser = mesh_path)]
    pub input: PathBuf,
    /// The STEP file to write (.step, .stp).
    #[arg(value_parser = step_path)]
    pub output: PathBuf,
    /// Levels of refinement before the patches are made: one patch per
    /// face of the refined cage. Patches away from extraordinary vertices
    /// and crease ends are exact; those touching one approximate it, with
    /// an error that falls as this rises.
    #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u32).range(1..=MAX_ISOLATION as i64))]
    pub isolation: u32,
    #[command(flatten)]
    pub cage: Cage,
}

pub fn run(cli: &Cli, args: &Nurbs) -> Result<(), Failure> {
    let Nurbs {
        input,
        output,
        isolation,
        cage,
    } = args;
    if Scheme::from(cage.scheme) != Scheme::CatmullClark {
        return Err(Failure::Failed(format!(
            "{}: NURBS patches need --scheme catmull-clark: Loop's limit surface is a quartic box spline, which no tensor-product B-spline patch holds exactly; nothing written",
            input.display()
        )));
    }
    let (file, options) = read_cage(cli, input, cage)?;
    let options = with_file_tags(options, &file);
    let patches = with_progress("fitting patches", || {
        limit_patches(&file.mesh, &options, *isolation)
    })
    .map_err(|e| operation_failed(input, "make patches of", e))?;
    if patches.patches.is_empty() {
        return Err(Failure::Failed(format!(
            "{}: no face is left to make a patch of (every face is a hole); nothing written",
            input.display()
        )));
    }
    let name = output
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let controls: Vec<step::Bicubic> = patches.patches.iter().map(|p| p.control).collect();
    with_progress(&format!("writing {}", output.display()), || {
        io::write_atomically(output, |w| step::write(w, &name, &controls))
    })?;
    print_summary(output, &patches);
    Ok(())
}

fn print_summary(output: &Path, patches: &weft::subdivide::LimitPatches) {
    let count = patches.patches.len();
    let relative = if patches.size > 0.0 {
        patches.max_error / patches.size
    } else {
        0.0
    };
    println!("{}", output.display());
    println!("  isolation levels  {}", patches.isolation);
    println!("  patches           {count}");
    println!("  exact             {}", patches.exact_count);
    println!("  approximate       {}", count - patches.exact_count);
    println!(
        "  largest error     {:.3e} ({:.3e} of the cage's diagonal)",
        patches.max_error, relative
    );
}
