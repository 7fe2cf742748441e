//! Bands: Catmull-Clark's passes around a parent level's faces, edges and
//! vertices, cut so that the face points each edge and vertex point reads
//! are still in the cache.
//!
//! The face pass of a level writes its face points tens of megabytes
//! before the edge and vertex passes read them back, by then from memory.
//! A refiner's plan is cut once into bands of parent faces; each group
//! around a parent edge or vertex goes in the first band whose face points
//! hold every face point it reads, in runs of consecutive groups, each
//! run in the latest band its groups need (the groups at a torus's seam,
//! whose rings reach its last faces, wait for the last band). Evaluation
//! makes a band's face points, then its runs.

use glam::DVec3;

use super::gathers::Plan;
use super::level::NONE;
use super::scheme::VertexRule;
use crate::buffers::par_map;
use crate::error::Result;

/// Groups per run at most: a task's worth of work.
const RUN: usize = 2048;

/// Groups per run at least, but in the last run: a shorter run
/// costs more in handing it to a thread than in making its points.
const MIN_RUN: usize = 256;

/// A run of groups, made in the latest band any of them needs, with the
/// parts of the output they write.
pub(crate) struct Run<'a> {
    band: u32,
    pub(crate) items: std::ops::Range<usize>,
    pub(crate) values: &'a mut [DVec3],
    pub(crate) singles: &'a mut [DVec3],
}

/// `runs` (see [`Bands`]) cut out of the groups' values and singles.
pub(crate) fn runs_of<'a>(
    runs: &[(u32, u32)],
    offsets: &[u32],
    mut values: &'a mut [DVec3],
    mut singles: &'a mut [DVec3],
) -> Vec<Option<Run<'a>>> {
    let count = offsets.len() - 1;
    let mut out = Vec::with_capacity(runs.len());
    for (k, &(start, band)) in runs.iter().enumerate() {
        let end = runs.get(k + 1).map_or(count, |&(next, _)| next as usize);
        let items = start as usize..end;
        let len = (offsets[end] - offsets[items.start]) as usize;
        let (run_values, rest) = std::mem::take(&mut values).split_at_mut(len);
        values = rest;
        let (run_singles, rest) = std::mem::take(&mut singles).split_at_mut(items.len());
        singles = rest;
        out.push(Some(Run {
            band,
            items,
            values: run_values,
            singles: run_singles,
        }));
    }
    out
}

/// The runs of `band`, taken out of `runs`.
pub(crate) fn band_runs<'a>(runs: &mut [Option<Run<'a>>], band: usize) -> Vec<Run<'a>> {
    runs.iter_mut()
        .filter(|run| run.as_ref().is_some_and(|run| run.band as usize == band))
        .filter_map(Option::take)
        .collect()
}

/// Parent faces per band of Catmull-Clark's `apply_grouped`, for each
/// thread that shares the band: each thread's part of a band's face
/// points (65,536 of them, 1.5 MB) stays near its core until the band's
/// groups read them back. Four times as many a thread (6 MB) made a
/// one-thread evaluation a tenth slower on a virtual machine whose
/// last-level cache other machines share; bands grow with the threads
/// because at the end of each band's two passes the threads wait for one
/// another.
const BAND_FACES_PER_THREAD: usize = 16_384;

/// Parent faces per band when `threads` threads share the work.
fn band_faces(threads: usize) -> usize {
    BAND_FACES_PER_THREAD * threads.max(1)
}

/// How a plan's Catmull-Clark's `apply_grouped` goes band by band (see
/// [`plan_bands`]).
#[derive(Debug, Clone)]
pub(crate) struct Bands {
    /// The end of each band's parent faces.
    pub(crate) face_ends: Vec<u32>,
    /// The parent edges' groups in runs `(first group, band)`, in order,
    /// each run made in one band and at most [`RUN`] groups long (see
    /// [`runs`]).
    pub(crate) edge_runs: Vec<(u32, u32)>,
    /// The parent vertices' groups, the same way.
    pub(crate) vertex_runs: Vec<(u32, u32)>,
}

/// The bands of a plan's Catmull-Clark's `apply_grouped`, for a level
/// refined from more parent faces than a band holds (see [`band_faces`],
/// for the threads of the pool the plan is made in): the parent faces cut
/// in bands, and each group around a parent edge or vertex in the first
/// band whose face points hold every face point it reads.
pub(crate) fn plan_bands(plan: &Plan) -> Result<Option<Bands>> {
    let Some(groups) = &plan.parent else {
        return Ok(None);
    };
    let band_faces = band_faces(rayon::current_num_threads());
    let (parent_vertices, parent_edges) = groups.parent_counts();
    let parent_faces = groups.face_faces.len() - 1;
    if parent_faces <= band_faces {
        return Ok(None);
    }
    let face_ends: Vec<u32> = (1..=parent_faces.div_ceil(band_faces))
        .map(|b| (b * band_faces).min(parent_faces) as u32)
        .collect();
    let limits: Vec<u32> = face_ends
        .iter()
        .map(|&end| groups.face_faces[end as usize])
        .collect();
    // The band of a group that reads face points below `need`.
    let band_of = |need: u32| limits.partition_point(|&limit| limit < need) as u32;
    let ring_need = |v: usize| match plan.vertex_rules[v] {
        VertexRule::Smooth => {
            let ring = plan.ring(v);
            ring[ring.len() / 2..]
                .iter()
                .map(|&f| f + 1)
                .max()
                .unwrap_or(0)
        }
        _ => 0,
    };
    let edges_need = |edges: &[[u32; 4]]| {
        edges
            .iter()
            .filter(|edge| edge[2] != NONE)
            .map(|edge| edge[2].max(edge[3]) + 1)
            .max()
            .unwrap_or(0)
    };
    let inside_base = 2 * parent_edges;
    let edge_bands = par_map(parent_edges, "bands", |m| {
        let inside = groups.edge_inside[m] as usize..groups.edge_inside[m + 1] as usize;
        let edges = &plan.edges[inside_base + inside.start..inside_base + inside.end];
        band_of(edges_need(edges).max(ring_need(parent_vertices + m)))
    })?;
    let vertex_bands = par_map(parent_vertices, "bands", |v| {
        let halves = groups.vertex_halves[v] as usize..groups.vertex_halves[v + 1] as usize;
        band_of(edges_need(&plan.edges[halves]).max(ring_need(v)))
    })?;
    Ok(Some(Bands {
        face_ends,
        edge_runs: runs(&edge_bands),
        vertex_runs: runs(&vertex_bands),
    }))
}

/// Consecutive groups, at most [`RUN`] to a run, each run in the latest
/// band any of its groups needs: groups of one band, and a run shorter
/// than [`MIN_RUN`] takes the next groups whatever their band. Where the
/// bands alternate group by group (the groups at a torus's seam, which
/// read the first and the last band), the runs would otherwise be a
/// group or two long, each a task of its own.
fn runs(bands: &[u32]) -> Vec<(u32, u32)> {
    let mut runs: Vec<(u32, u32)> = Vec::new();
    for (i, &band) in bands.iter().enumerate() {
        match runs.last_mut() {
            Some((start, last)) if i - (*start as usize) < RUN => {
                if *last == band {
                    continue;
                }
                if i - (*start as usize) < MIN_RUN {
                    *last = (*last).max(band);
                    continue;
                }
                runs.push((i as u32, band));
            }
            _ => runs.push((i as u32, band)),
        }
    }
    runs
}

#[cfg(test)]
mod tests {
    use crate::mesh::shapes;
    use crate::subdivide::refiner::{plan_levels, Levels};
    use crate::subdivide::{NakedEdges, Scheme};

    #[test]
    fn runs_wait_for_every_band_their_groups_need_and_are_not_tiny() {
        // A seam: bands alternating group by group, then one band.
        let bands: Vec<u32> = (0..600)
            .map(|i| [3, 0, 0, 0][i % 4])
            .chain(std::iter::repeat_n(1, 5000))
            .collect();
        let runs = super::runs(&bands);
        let ends: Vec<usize> = runs
            .iter()
            .skip(1)
            .map(|&(start, _)| start as usize)
            .chain([bands.len()])
            .collect();
        assert_eq!(runs[0].0, 0);
        for (&(start, band), end) in runs.iter().zip(ends) {
            let groups = &bands[start as usize..end];
            assert!(!groups.is_empty() && groups.len() <= super::RUN);
            assert!(groups.iter().all(|&need| need <= band), "run at {start}");
            let pure = groups.iter().all(|&need| need == band);
            assert!(pure || groups.len() >= super::MIN_RUN, "run at {start}");
        }
        // The seam's 600 groups go in three runs, not 300.
        assert_eq!(runs.iter().filter(|&&(start, _)| start < 600).count(), 3);
        assert!(runs.iter().any(|&(_, band)| band == 1));
    }

    #[test]
    fn large_levels_go_band_by_band_and_the_seam_waits() {
        // 18,432 quads: level 1 has 73,728 faces, more than a band's.
        let cage = shapes::torus(144, 128);
        let request = Levels {
            cage: &cage,
            scheme: Scheme::CatmullClark,
            levels: 3,
            naked_edges: NakedEdges::Smooth,
        };
        // Bands of 16,384 parent faces a thread: 65,536 on four threads.
        let plans_on = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let mut plans = Vec::new();
            pool.install(|| plan_levels(request, |plan| plans.push(plan)))
                .unwrap();
            plans
        };
        let on_two = plans_on(2);
        let ends = &on_two[2].bands.as_ref().unwrap().face_ends;
        assert_eq!(ends, &[32_768, 65_536, 73_728]);
        let plans = plans_on(4);
        assert!(
            plans[1].bands.is_none(),
            "level 2 is refined from 18,432 faces"
        );
        let bands = plans[2].bands.as_ref().expect("level 3 goes by bands");
        assert_eq!(bands.face_ends, [65_536, 73_728]);
        for runs in [&bands.edge_runs, &bands.vertex_runs] {
            assert!(runs.iter().all(|&(_, band)| band < 2));
            // Both bands have groups; the first groups, at the seam, read
            // the last faces and wait for the last band.
            assert!(runs.iter().any(|&(_, band)| band == 0));
            assert!(runs.windows(2).any(|pair| pair[0].1 > pair[1].1));
            assert!(runs.windows(2).all(|pair| pair[0].0 < pair[1].0));
        }
    }
}
