//! `weft demo`: the design workflows of Weft, each built only from Weft's own
//! operations on built-in inputs, written as mesh files and pictures with an
//! `index.html` that shows them all.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use clap::ValueEnum;

use weft::io::render::{self, RenderOptions};
use weft::io::{self, IoError};
use weft::{Error, Mesh};

use super::progress::{self, Steps};

mod workflows;

/// The workflows of the demo, in the order they run.
#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Workflow {
    /// Loop levels 1-3 in each naked-edge mode, and a mesh with a hole.
    Loop,
    /// Three surface meshes, one flipped: join, weld, Catmull-Clark.
    Surfaces,
    /// Mismatched U/V counts: T-nodes found and repaired.
    TNodes,
    /// Voronoi cells, a pyramid per cell, Catmull-Clark.
    Voronoi,
    /// Diamond panels with pyramids whose heights come from a picture.
    Fading,
    /// An aggregation of boxes: join, weld, cull the inner faces.
    Boxes,
    /// A block without and with creases, colours and UVs carried.
    Creases,
}

impl Workflow {
    fn title(self) -> &'static str {
        match self {
            Workflow::Loop => "Loop subdivision",
            Workflow::Surfaces => "surfaces joined and welded",
            Workflow::TNodes => "T-nodes",
            Workflow::Voronoi => "Voronoi skin",
            Workflow::Fading => "fading pattern",
            Workflow::Boxes => "aggregation of boxes",
            Workflow::Creases => "creases",
        }
    }
}

/// A grayscale picture sampled by the fading pattern, values 0 (black) to 1.
pub struct Gray {
    width: usize,
    height: usize,
    values: Vec<f64>,
}

impl Gray {
    /// A left-to-right gradient that also rises towards the middle.
    fn built_in() -> Gray {
        let (width, height) = (64, 64);
        let mut values = Vec::with_capacity(width * height);
        for y in 0..height {
            for x in 0..width {
                let u = x as f64 / (width - 1) as f64;
                let v = y as f64 / (height - 1) as f64;
                let bump = 1.0 - (2.0 * v - 1.0).powi(2);
                values.push((u * (0.55 + 0.45 * bump)).clamp(0.0, 1.0));
            }
        }
        Gray {
            width,
            height,
            values,
        }
    }

    /// Reads a PNG of any colour type as luminance.
    pub fn read(path: &Path) -> Result<Gray, String> {
        let name = path.display();
        let file = std::fs::File::open(path).map_err(|e| format!("{name}: cannot read: {e}"))?;
        let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
        decoder.set_transformations(png::Transformations::normalize_to_color8());
        let mut reader = decoder
            .read_info()
            .map_err(|e| format!("{name}: not a PNG picture: {e}"))?;
        let size = reader
            .output_buffer_size()
            .ok_or_else(|| format!("{name}: the picture is too large"))?;
        let mut buffer = Vec::new();
        buffer
            .try_reserve_exact(size)
            .map_err(|_| format!("{name}: the picture is too large"))?;
        buffer.resize(size, 0);
        let frame = reader
            .next_frame(&mut buffer)
            .map_err(|e| format!("{name}: cannot decode: {e}"))?;
        let channels = frame.color_type.samples();
        let (width, height) = (frame.width as usize, frame.height as usize);
        let values = (0..width * height)
            .map(|i| {
                let p = &buffer[i * channels..];
                let luminance = match channels {
                    1 | 2 => p[0] as f64,
                    _ => 0.2126 * p[0] as f64 + 0.7152 * p[1] as f64 + 0.0722 * p[2] as f64,
                };
                luminance / 255.0
            })
            .collect();
        Ok(Gray {
            width,
            height,
            values,
        })
    }

    /// The value at `(u, v)` in `[0, 1]²`, `v` = 0 at the picture's bottom.
    fn sample(&self, u: f64, v: f64) -> f64 {
        let x = (u.clamp(0.0, 1.0) * (self.width - 1) as f64).round() as usize;
        let y = ((1.0 - v.clamp(0.0, 1.0)) * (self.height - 1) as f64).round() as usize;
        self.values[y * self.width + x]
    }
}

struct Entry {
    name: String,
    caption: String,
}

struct Section {
    title: &'static str,
    entries: Vec<Entry>,
}

/// Writes each stage's mesh and picture and remembers them for the index.
struct Demo<'a> {
    dir: PathBuf,
    sections: Vec<Section>,
    progress: &'a mut Steps,
}

/// A failure of the demo, as the message to show.
type Step<T> = Result<T, String>;

fn op<T>(what: &str, result: Result<T, Error>) -> Step<T> {
    result.map_err(|e| format!("demo: {what}: {e}"))
}

fn file<T>(result: Result<T, IoError>) -> Step<T> {
    result.map_err(|e| e.to_string())
}

impl Demo<'_> {
    fn section(&mut self, title: &'static str) {
        self.sections.push(Section {
            title,
            entries: Vec::new(),
        });
    }

    fn save(&mut self, name: &str, caption: &str, mesh: &Mesh) -> Step<()> {
        self.save_file(name, caption, &io::MeshFile::new(mesh.clone()))
    }

    /// As [`Demo::save`], the picture cut away beyond `section` to show
    /// what is inside (the mesh file is whole).
    fn save_cut(
        &mut self,
        name: &str,
        caption: &str,
        mesh: &Mesh,
        section: render::Section,
    ) -> Step<()> {
        let options = RenderOptions {
            section: Some(section),
            ..RenderOptions::default()
        };
        self.save_with(name, caption, &io::MeshFile::new(mesh.clone()), options)
    }

    /// As [`Demo::save`], with the colours, UVs and creases the OBJ carries;
    /// the picture draws the creases in violet.
    fn save_file(&mut self, name: &str, caption: &str, carried: &io::MeshFile) -> Step<()> {
        let options = RenderOptions {
            marked_edges: carried.creases.iter().map(|c| c.edge).collect(),
            ..RenderOptions::default()
        };
        self.save_with(name, caption, carried, options)
    }

    fn save_with(
        &mut self,
        name: &str,
        caption: &str,
        carried: &io::MeshFile,
        options: RenderOptions,
    ) -> Step<()> {
        let mesh = &carried.mesh;
        self.progress.stage(name);
        file(io::write_mesh_file(
            self.dir.join(format!("{name}.obj")),
            carried,
            &io::WriteOptions::default(),
        ))?;
        let image = op(
            &format!("render {name}"),
            match &carried.colours {
                Some(colours) => render::render_coloured(mesh, &options, &colours.rgba),
                None => render::render(mesh, &options),
            },
        )?;
        file(image.save_png(self.dir.join(format!("{name}.png"))))?;
        self.progress.println(&format!(
            "{name}: {caption} ({} vertices, {} faces)",
            mesh.vertex_count(),
            mesh.face_count()
        ));
        self.add_entry(name, caption);
        Ok(())
    }

    /// Shows a stage already saved once more, in the current section.
    fn reuse(&mut self, name: &str, caption: &str) {
        self.progress
            .println(&format!("{name}: {caption} (shown above)"));
        self.add_entry(name, caption);
    }

    /// Lists a stage's picture in the current section of the index.
    fn add_entry(&mut self, name: &str, caption: &str) {
        self.sections
            .last_mut()
            .expect("a section is open")
            .entries
            .push(Entry {
                name: name.to_string(),
                caption: caption.to_string(),
            });
    }

    fn write_index(&self) -> Step<()> {
        let mut html = String::from(
            "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
             <title>Weft demo</title>\n<style>\n\
             body { font-family: system-ui, sans-serif; margin: 2em; color: #222; background: #fafafa; }\n\
             .row { display: flex; flex-wrap: wrap; gap: 1em; }\n\
             figure { margin: 0; width: 400px; }\n\
             img { width: 400px; border: 1px solid #ddd; background: #fff; }\n\
             figcaption { font-size: 0.9em; margin-top: 0.3em; }\n\
             code { font-size: 0.85em; color: #666; }\n\
             </style>\n</head>\n<body>\n<h1>Weft demo</h1>\n\
             <p>Each picture is a mesh written beside it (<code>.obj</code>). Front faces are \
             blue-grey, back faces orange, naked edges red.</p>\n",
        );
        for section in &self.sections {
            let _ = writeln!(
                html,
                "<h2>{}</h2>\n<div class=\"row\">",
                escape(section.title)
            );
            for e in &section.entries {
                let _ = writeln!(
                    html,
                    "<figure><img src=\"{0}.png\" alt=\"{1}\"><figcaption>{1} <code>{0}.obj</code></figcaption></figure>",
                    escape(&e.name),
                    escape(&e.caption)
                );
            }
            html.push_str("</div>\n");
        }
        html.push_str("</body>\n</html>\n");
        file(io::write_atomically(&self.dir.join("index.html"), |w| {
            w.write_all(html.as_bytes())
        }))
    }
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Runs the workflows `only` names (all when empty) into `dir` (created when
/// missing, its parent must exist), with a bar of the workflows on stderr
/// when it is a terminal.
pub fn run(dir: &Path, image: Option<&Path>, only: &[Workflow]) -> Step<()> {
    let gray = match image {
        Some(path) => Gray::read(path)?,
        None => Gray::built_in(),
    };
    if !dir.is_dir() {
        std::fs::create_dir(dir)
            .map_err(|e| format!("{}: cannot create the folder: {e}", dir.display()))?;
    }
    let chosen: Vec<Workflow> = Workflow::value_variants()
        .iter()
        .copied()
        .filter(|w| only.is_empty() || only.contains(w))
        .collect();
    progress::with_steps(chosen.len(), |steps| {
        let mut demo = Demo {
            dir: dir.to_path_buf(),
            sections: Vec::new(),
            progress: steps,
        };
        for &workflow in &chosen {
            demo.progress.start(workflow.title());
            match workflow {
                Workflow::Loop => workflows::loop_levels(&mut demo)?,
                Workflow::Surfaces => workflows::surfaces(&mut demo)?,
                Workflow::TNodes => workflows::t_nodes(&mut demo)?,
                Workflow::Voronoi => workflows::voronoi_skin(&mut demo)?,
                Workflow::Fading => workflows::fading_pattern(&mut demo, &gray)?,
                Workflow::Boxes => workflows::boxes(&mut demo)?,
                Workflow::Creases => workflows::creases(&mut demo)?,
            }
        }
        demo.progress.note("writing index.html");
        demo.write_index()?;
        demo.progress
            .println(&format!("index: {}", dir.join("index.html").display()));
        Ok(())
    })
}
