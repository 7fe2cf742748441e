//! The refiner: the plans of every level of one cage's topology, computed
//! once, re-applied to new cage positions without allocating (OpenSubdiv's
//! `Far::TopologyRefiner` + `PrimvarRefiner`, or its stencil tables, in spirit).
//! One-shot subdivision uses the same two passes, level by level.

use std::sync::Mutex;

use glam::DVec3;

use super::creases::SubdivisionOptions;
use super::gathers::{plan, LevelGathers, LoopRefinedGathers, ParentGroups, Plan, RefinedGathers};
use super::level::{uniform_offsets, Connectivity, Faces};
use super::point_rules::{self, apply, child_faces, child_faces_into};
use super::rules::{cage_tags, child_tags, Tags};
use super::scheme::{check_counts, NakedEdges, RefinedCounts, Scheme};
use super::subdivider::Subdivider;
use super::{bands, catmull_clark, loop_subdivision, scale};
use crate::buffers::{fresh_zeroed, try_vec};
use crate::error::{Error, Result};
use crate::mesh::Mesh;

/// What depends only on a cage's faces: the plans of every level and the
/// refined faces. Build with [`Refiner::new`], evaluate with
/// [`Refiner::evaluate`] as often as the positions change.
#[derive(Debug)]
pub struct Refiner {
    scheme: Scheme,
    naked_edges: NakedEdges,
    cage_vertex_count: usize,
    plans: Vec<Plan>,
    faces: Faces<'static>,
    /// The cage's positions, for [`Refiner::mesh`].
    cage_positions: Vec<DVec3>,
    /// Two buffers for the intermediate levels, reserved once.
    scratch: Mutex<[Vec<DVec3>; 2]>,
    /// With creases or corners: the stencils that evaluate instead of the plans.
    creased: Option<Box<Subdivider>>,
}

impl Refiner {
    /// Plans `levels` levels of `scheme` on `cage`'s faces with the given
    /// naked-edge mode. The plans are laid out for the threads of the
    /// rayon pool this is called in, which evaluation runs best in; any
    /// pool evaluates to the same bits.
    ///
    /// # Errors
    /// [`Error::NotTriangles`] for Loop on a face that is not a triangle;
    /// [`Error::ResultTooLarge`] when a level would pass
    /// [`crate::error::MAX_ELEMENTS`]; [`Error::OutOfMemory`].
    pub fn new(
        cage: &Mesh,
        scheme: Scheme,
        levels: u32,
        naked_edges: NakedEdges,
    ) -> Result<Refiner> {
        if naked_edges == NakedEdges::None {
            // Holes at the boundary: the creased path filters the faces.
            return Refiner::with_options(
                cage,
                scheme,
                levels,
                &SubdivisionOptions::new(naked_edges),
            );
        }
        let mut plans = Vec::new();
        let request = Levels {
            cage,
            scheme,
            levels,
            naked_edges,
        };
        let faces = plan_levels(request, |plan| plans.push(plan))?;
        let largest_intermediate = plans
            .iter()
            .skip(1)
            .map(|p| p.vertex_count)
            .max()
            .unwrap_or(0);
        let mut a = try_vec(largest_intermediate, "refiner scratch")?;
        a.resize(largest_intermediate, DVec3::ZERO);
        let mut b = try_vec(largest_intermediate, "refiner scratch")?;
        b.resize(largest_intermediate, DVec3::ZERO);
        Ok(Refiner {
            scheme,
            naked_edges,
            cage_vertex_count: cage.vertex_count(),
            plans,
            faces: faces.into_owned(),
            cage_positions: cage.positions().to_vec(),
            scratch: Mutex::new([a, b]),
            creased: None,
        })
    }

    /// Plans `levels` levels of `scheme` on `cage`'s faces with creases,
    /// corners and the naked-edge mode of `options` (see [`Subdivider`]).
    ///
    /// # Errors
    /// As [`Subdivider::new`].
    pub fn with_options(
        cage: &Mesh,
        scheme: Scheme,
        levels: u32,
        options: &SubdivisionOptions,
    ) -> Result<Refiner> {
        let creased = Subdivider::new(cage, scheme, levels, options)?;
        Ok(Refiner {
            scheme,
            naked_edges: options.naked_edges,
            cage_vertex_count: cage.vertex_count(),
            plans: Vec::new(),
            faces: creased.output_faces().clone(),
            cage_positions: cage.positions().to_vec(),
            scratch: Mutex::new([Vec::new(), Vec::new()]),
            creased: Some(Box::new(creased)),
        })
    }

    /// The creased subdivision, when built [`Refiner::with_options`]: for
    /// carried data, face-varying values and the limit.
    pub fn subdivider(&self) -> Option<&Subdivider> {
        self.creased.as_deref()
    }

    /// The scheme it refines with.
    pub fn scheme(&self) -> Scheme {
        self.scheme
    }

    /// The naked-edge mode it refines with.
    pub fn naked_edges(&self) -> NakedEdges {
        self.naked_edges
    }

    /// Number of levels.
    pub fn levels(&self) -> usize {
        self.creased
            .as_ref()
            .map_or(self.plans.len(), |creased| creased.levels())
    }

    /// Number of cage vertices [`Refiner::evaluate`] expects.
    pub fn cage_vertex_count(&self) -> usize {
        self.cage_vertex_count
    }

    /// Number of refined vertices [`Refiner::evaluate`] writes.
    pub fn vertex_count(&self) -> usize {
        self.faces.vertex_count
    }

    /// Number of refined faces.
    pub fn face_count(&self) -> usize {
        self.faces.face_count()
    }

    /// The refined faces' vertex indices, one face after another.
    pub fn face_indices(&self) -> &[u32] {
        &self.faces.indices
    }

    /// Where each refined face starts in [`Refiner::face_indices`], plus the total.
    pub fn face_offsets(&self) -> &[u32] {
        &self.faces.offsets
    }

    /// Computes the refined positions of new cage positions into `out`,
    /// without allocating.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] when `cage` does not have
    /// [`Refiner::cage_vertex_count`] positions, `out` not
    /// [`Refiner::vertex_count`], or a cage coordinate is not finite;
    /// [`Error::DegenerateInput`] naming the vertex when a refined point lies
    /// beyond the largest `f64` (`out` is then left partly written).
    pub fn evaluate(&self, cage: &[DVec3], out: &mut [DVec3]) -> Result<()> {
        if cage.len() != self.cage_vertex_count {
            return Err(Error::InvalidArgument(format!(
                "the refiner was built for {} cage vertices but {} positions were given",
                self.cage_vertex_count,
                cage.len()
            )));
        }
        if out.len() != self.vertex_count() {
            return Err(Error::InvalidArgument(format!(
                "the refined mesh has {} vertices but the output has room for {}",
                self.vertex_count(),
                out.len()
            )));
        }
        if let Some(v) = crate::mesh::first_non_finite(cage) {
            return Err(Error::InvalidArgument(format!(
                "cage vertex {v} has a non-finite coordinate"
            )));
        }
        if let Some(creased) = &self.creased {
            return creased.evaluate(cage, out);
        }
        let Some((last, intermediate)) = self.plans.split_last() else {
            out.copy_from_slice(cage);
            return Ok(());
        };
        // Near the top of the f64 range: an exactly scaled-down copy (the
        // only allocation, and only for such positions; see `scale.rs`).
        if let Some(scale) = scale::for_points(cage) {
            let scaled = scale::scaled_points(cage, scale);
            self.apply_plans(last, intermediate, &scaled, out);
            return scale::restore_points(out, scale, "the position");
        }
        self.apply_plans(last, intermediate, cage, out);
        Ok(())
    }

    /// Applies every level's plan to `cage`, the last into `out`.
    fn apply_plans(&self, last: &Plan, intermediate: &[Plan], cage: &[DVec3], out: &mut [DVec3]) {
        let mut scratch = self
            .scratch
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        let [a, b] = &mut *scratch;
        // Level 1 goes to `a`, level 2 to `b`, level 3 to `a`, ...; the last to `out`.
        let mut source_len = 0;
        for (i, plan) in intermediate.iter().enumerate() {
            let target_len = self.plans[i + 1].vertex_count;
            match i {
                0 => apply(self.scheme, plan, cage, &mut a[..target_len]),
                _ if i % 2 == 1 => apply(self.scheme, plan, &a[..source_len], &mut b[..target_len]),
                _ => apply(self.scheme, plan, &b[..source_len], &mut a[..target_len]),
            }
            source_len = target_len;
        }
        let source: &[DVec3] = match intermediate.len() {
            0 => cage,
            n if n % 2 == 1 => &a[..source_len],
            _ => &b[..source_len],
        };
        apply(self.scheme, last, source, out);
    }

    /// The refined mesh at the cage positions the refiner was built from.
    ///
    /// # Errors
    /// [`Error::OutOfMemory`].
    pub fn mesh(&self) -> Result<Mesh> {
        let mut positions = try_vec(self.vertex_count(), "refined positions")?;
        positions.resize(self.vertex_count(), DVec3::ZERO);
        self.evaluate(&self.cage_positions, &mut positions)?;
        Ok(self.mesh_with(positions))
    }

    fn mesh_with(&self, positions: Vec<DVec3>) -> Mesh {
        let sizes = self.faces.sizes();
        Mesh::from_valid_parts(positions, sizes, self.faces.indices.to_vec())
    }
}

/// A level handed on by [`gather_levels`].
pub(crate) enum Step<'a> {
    /// A level's gathers, read from the level.
    Level(LevelGathers<'a>),
    /// Catmull-Clark's last level's gathers, read from the level before the
    /// one they apply to.
    Refined(RefinedGathers<'a>),
    /// Loop's, the same way.
    LoopRefined(&'a LoopRefinedGathers<'a>),
}

/// Where [`gather_levels`] has a level's points written, and read.
pub(crate) enum Points<'a> {
    /// An intermediate level's, into a buffer of the callback's own.
    Next,
    /// The points of the level before the last, into this slice: the tail
    /// of the last level's index buffer, written over only once the last
    /// level's points have read them.
    NextInto(&'a mut [DVec3]),
    /// The last level's, made from these points when given (those written
    /// [`Points::NextInto`]), else from those the callback made before.
    Last(Option<&'a [DVec3]>),
}

/// A cage and what to do to it: the plain subdivision both the refiner and
/// the one-shot drivers walk level by level.
#[derive(Clone, Copy)]
pub(crate) struct Levels<'a> {
    pub(crate) cage: &'a Mesh,
    pub(crate) scheme: Scheme,
    pub(crate) levels: u32,
    pub(crate) naked_edges: NakedEdges,
}

impl<'a> Levels<'a> {
    /// For each level to refine, whether it is the last and whether the
    /// next one is.
    fn steps(&self) -> impl Iterator<Item = (bool, bool)> {
        let n = self.levels as usize;
        (0..n).map(move |level| (level + 1 == n, level + 2 == n))
    }

    /// The cage's faces, connectivity and tags, or its faces alone when
    /// there is nothing to refine (no level or no face). Checks the scheme's
    /// preconditions and every level's size before allocating.
    fn cage_level(
        &self,
    ) -> Result<std::result::Result<(Faces<'a>, Connectivity, Tags), Faces<'a>>> {
        let Levels {
            cage,
            scheme,
            levels,
            naked_edges,
        } = *self;
        scheme.check_cage(cage)?;
        if levels == 0 || cage.face_count() == 0 {
            return Ok(Err(Faces::of_mesh(cage)));
        }
        // The vertices' edges serve the next levels only (see `of_cage`).
        let (faces, connectivity) = Connectivity::of_cage(cage, scheme, levels, levels > 1)?;
        let tags = cage_tags(&faces, &connectivity, naked_edges)?;
        Ok(Ok((faces, connectivity, tags)))
    }
}

/// Plans every level in turn, handing each plan to `each`, and returns the
/// faces of the last level, with offsets.
pub(crate) fn plan_levels(request: Levels<'_>, mut each: impl FnMut(Plan)) -> Result<Faces<'_>> {
    let (mut faces, mut connectivity, mut tags) = match request.cage_level()? {
        Ok(cage) => cage,
        Err(faces) => return Ok(faces),
    };
    let scheme = request.scheme;
    let mut groups = None;
    for (last, next_last) in request.steps() {
        let next_faces = child_faces(scheme, &faces, &connectivity, true)?;
        let mut plan = plan(scheme, &faces, &connectivity, &tags)?;
        // This level's plan groups around the level before; the next's
        // around this one.
        plan.parent = groups.take();
        if !last {
            // The next level's edges and adjacency, written from this one's.
            let (next_connectivity, inside) =
                connectivity.refine_with_inside(scheme, &faces, !next_last)?;
            tags = child_tags(scheme, &tags, &faces, &next_connectivity)?;
            groups = Some(parent_groups(&faces, &mut connectivity, inside)?);
            connectivity = next_connectivity;
        } else {
            // Not needed any more: free it before the last, largest pass.
            connectivity = Connectivity::default();
        }
        if scheme == Scheme::CatmullClark {
            faces.drop_uniform_offsets();
            plan.faces = faces.into_owned();
            plan.bands = bands::plan_bands(&plan)?;
        }
        each(plan);
        faces = next_faces;
    }
    Ok(faces)
}

/// How the elements of the level refined from `faces` group around them
/// (see [`ParentGroups`]), the lists moved out of `connectivity`, which
/// has its vertices' edges and is done with. `loop_inside` are Loop's
/// inside-edge offsets, handed on by the refinement that counted them;
/// `None` for Catmull-Clark, whose groups are the parent's own lists.
fn parent_groups(
    faces: &Faces,
    connectivity: &mut Connectivity,
    loop_inside: Option<Vec<u32>>,
) -> Result<ParentGroups> {
    let (face_faces, edge_inside) = match loop_inside {
        Some(inside_offsets) => (Vec::new(), inside_offsets),
        None => {
            // Faces of one size may have no offsets (see `gather_levels`).
            let face_faces = if faces.offsets.is_empty() {
                uniform_offsets(faces.face_count(), faces.size, true)?
            } else {
                let mut copy = try_vec(faces.offsets.len(), "parent groups")?;
                copy.extend_from_slice(&faces.offsets);
                copy
            };
            let edge_inside = std::mem::take(&mut connectivity.adjacency.edge_offsets);
            (face_faces, edge_inside)
        }
    };
    Ok(ParentGroups {
        face_faces,
        edge_inside,
        vertex_halves: std::mem::take(&mut connectivity.vertex_edge_offsets),
    })
}

/// One-shot subdivision's levels: hands each level's gathers to `each`
/// with where its points go ([`Points`]), read where they lie instead of
/// planned (each applies once), and returns the faces of the last level,
/// without offsets (all the same size). The last two levels both come from
/// the connectivity of the level before them, so the largest connectivity
/// is never built; the points of the level between them are kept in the
/// last level's index buffer until the last points are made, and the last
/// faces are written after them.
///
/// With `last_indices`, a caller's buffer, the last level's face indices
/// are written there instead (the returned faces then have none); `room`
/// first sees the result's counts, before anything is written, and
/// refuses buffers too small for them.
pub(crate) fn gather_levels<'a>(
    request: Levels<'a>,
    mut last_indices: Option<&mut [u32]>,
    room: impl FnOnce(RefinedCounts) -> Result<()>,
    mut each: impl FnMut(Step<'_>, Points<'_>) -> Result<()>,
) -> Result<Faces<'a>> {
    let scheme = request.scheme;
    let (mut faces, mut connectivity, mut tags) = match request.cage_level()? {
        Ok(cage) => cage,
        Err(faces) => return Ok(faces),
    };
    // Faces of one size are read by arithmetic here, as every refined
    // level's are.
    faces.drop_uniform_offsets();
    let (vertex_count, face_count, index_count) = check_counts(
        scheme,
        faces.vertex_count as u64,
        connectivity.edge_count() as u64,
        faces.face_count() as u64,
        faces.corner_count() as u64,
        request.levels,
    )?;
    room(RefinedCounts {
        vertex_count: vertex_count as usize,
        face_count: face_count as usize,
        index_count: index_count as usize,
    })?;
    // How the level read groups around the level before it, once there is one.
    let mut groups = None;
    for (last, next_last) in request.steps() {
        let gathers = LevelGathers {
            scheme,
            faces: &faces,
            connectivity: &connectivity,
            tags: &tags,
            groups: groups.as_ref(),
        };
        if next_last {
            // The next level's points, then the last level's points and
            // faces from this level's connectivity: the next level's is
            // never built.
            let mut own_indices = Vec::new();
            let indices: &mut [u32] = match last_indices.take() {
                Some(into) => &mut into[..index_count as usize],
                None => {
                    own_indices = fresh_zeroed(index_count as usize, "child faces")?;
                    &mut own_indices
                }
            };
            let next_points = point_rules::point_count(scheme, &gathers);
            let kept = match points_tail(indices, next_points) {
                Some(tail) => {
                    each(Step::Level(gathers), Points::NextInto(tail))?;
                    true
                }
                None => {
                    each(Step::Level(gathers), Points::Next)?;
                    false
                }
            };
            let mut last_faces = match scheme {
                Scheme::CatmullClark => {
                    let refined = RefinedGathers { parent: gathers };
                    let source = kept_points(indices, next_points, kept);
                    each(Step::Refined(refined), Points::Last(source))?;
                    catmull_clark::grandchild_faces(&refined, Some(indices))?
                }
                Scheme::Loop => {
                    let refined = LoopRefinedGathers::new(gathers)?;
                    let source = kept_points(indices, next_points, kept);
                    each(Step::LoopRefined(&refined), Points::Last(source))?;
                    loop_subdivision::grandchild_faces(&refined, Some(indices))?
                }
            };
            last_faces.indices = own_indices.into();
            return Ok(last_faces);
        }
        if last {
            // The points first: then the last faces, the largest array, are
            // written once most of this level's connectivity is freed.
            each(Step::Level(gathers), Points::Last(None))?;
            connectivity.keep_only_corner_edges();
            drop(tags);
            let into = last_indices.take();
            return child_faces_into(scheme, &faces, &connectivity, false, into);
        }
        let next_faces = child_faces(scheme, &faces, &connectivity, false)?;
        each(Step::Level(gathers), Points::Next)?;
        // The vertices' edges are read by the next refinement, and by
        // Catmull-Clark's refined gathers.
        let (next_connectivity, inside) =
            connectivity.refine_with_inside(scheme, &faces, !next_last)?;
        tags = child_tags(scheme, &tags, &faces, &next_connectivity)?;
        groups = Some(parent_groups(&faces, &mut connectivity, inside)?);
        (faces, connectivity) = (next_faces, next_connectivity);
    }
    Ok(faces)
}

/// Room for `count` points at the end of `indices`, when they fit there
/// (as they do for every mesh whose level before the last has fewer
/// points than a sixth of the last level's indices) and the memory is
/// aligned for them.
fn points_tail(indices: &mut [u32], count: usize) -> Option<&mut [DVec3]> {
    let words = count.checked_mul(6)?;
    // An even start keeps a buffer aligned to 8 bytes aligned for f64s.
    let start = indices.len().checked_sub(words)? & !1;
    bytemuck::try_cast_slice_mut(&mut indices[start..start + words]).ok()
}

/// The points [`points_tail`] made room for, when `kept` there.
fn kept_points(indices: &mut [u32], count: usize, kept: bool) -> Option<&[DVec3]> {
    match kept {
        true => points_tail(indices, count).map(|points| &*points),
        false => None,
    }
}
