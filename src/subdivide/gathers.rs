//! Where the arithmetic pass finds the old points each new point gathers.
//!
//! A [`Plan`] stores the gathers of a level once, for a refiner to re-apply
//! to new positions; a [`LevelGathers`] reads the same gathers straight from
//! the level's faces, connectivity and tags. The one-shot path uses the
//! latter for its last level, which is never applied twice: writing the
//! plan's hundred-odd megabytes only to read them back once costs more than
//! finding each gather where it already lies. Both give the same gathers in
//! the same order, so both give the same bits.

use super::level::{Connectivity, Faces, Plan, VertexRule, NONE};
use super::rules::Tags;
use super::Scheme;

/// The gathers of one level, as the scheme's point rules read them.
pub(crate) trait Gathers: Sync {
    /// Vertex count of the level read.
    fn vertex_count(&self) -> usize;
    /// Edge count of the level read, in edge-point order.
    fn edge_count(&self) -> usize;
    /// Face count of the level read (0 when the scheme makes no face points).
    fn face_count(&self) -> usize;
    /// The vertices of face `f`.
    fn face(&self, f: usize) -> &[u32];
    /// Edge `e` as `[a, b, wing, wing]` (see [`Plan::edges`]).
    fn edge(&self, e: usize) -> [u32; 4];
    /// How vertex `v`'s point is made.
    fn rule(&self, v: usize) -> VertexRule;
    /// A crease vertex's two sharp neighbours.
    fn crease_neighbours(&self, v: usize) -> [u32; 2];
    /// A smooth vertex's neighbours, around it.
    fn neighbours(&self, v: usize) -> impl ExactSizeIterator<Item = u32> + '_;
    /// A smooth vertex's faces, in the order of [`Gathers::neighbours`].
    fn faces_around(&self, v: usize) -> impl Iterator<Item = u32> + '_;
}

impl Gathers for Plan {
    fn vertex_count(&self) -> usize {
        self.vertex_count
    }

    fn edge_count(&self) -> usize {
        self.edges.len()
    }

    fn face_count(&self) -> usize {
        self.face_offsets.len().saturating_sub(1)
    }

    #[inline]
    fn face(&self, f: usize) -> &[u32] {
        &self.face_indices[self.face_offsets[f] as usize..self.face_offsets[f + 1] as usize]
    }

    #[inline]
    fn edge(&self, e: usize) -> [u32; 4] {
        self.edges[e]
    }

    #[inline]
    fn rule(&self, v: usize) -> VertexRule {
        self.vertex_rules[v]
    }

    #[inline]
    fn crease_neighbours(&self, v: usize) -> [u32; 2] {
        let ring = self.ring(v);
        [ring[0], ring[1]]
    }

    #[inline]
    fn neighbours(&self, v: usize) -> impl ExactSizeIterator<Item = u32> + '_ {
        let ring = self.ring(v);
        let n = ring.len() / self.ring_stride();
        ring[..n].iter().copied()
    }

    #[inline]
    fn faces_around(&self, v: usize) -> impl Iterator<Item = u32> + '_ {
        let ring = self.ring(v);
        let n = ring.len() / self.ring_stride();
        ring[n..].iter().copied()
    }
}

/// The gathers of a level read from its faces, connectivity and tags.
#[derive(Clone, Copy)]
pub(crate) struct LevelGathers<'a> {
    pub(crate) scheme: Scheme,
    pub(crate) faces: &'a Faces,
    pub(crate) connectivity: &'a Connectivity,
    pub(crate) tags: &'a Tags,
}

impl LevelGathers<'_> {
    /// The vertex following corner `c` in its face.
    #[inline]
    fn next_vertex(&self, c: u32) -> u32 {
        let c = c as usize;
        self.faces.indices[self.faces.next(c, self.connectivity.face_of(c))]
    }
}

impl Gathers for LevelGathers<'_> {
    fn vertex_count(&self) -> usize {
        self.faces.vertex_count
    }

    fn edge_count(&self) -> usize {
        self.connectivity.edge_count()
    }

    fn face_count(&self) -> usize {
        match self.scheme {
            Scheme::CatmullClark => self.faces.face_count(),
            Scheme::Loop => 0,
        }
    }

    #[inline]
    fn face(&self, f: usize) -> &[u32] {
        self.faces.face(f)
    }

    #[inline]
    fn edge(&self, e: usize) -> [u32; 4] {
        let [a, b] = self.connectivity.edges[e];
        let wings = match (self.tags.edge_sharp[e], self.connectivity.edge_corners(e)) {
            (false, &[c1, c2]) => match self.scheme {
                Scheme::CatmullClark => {
                    [c1, c2].map(|c| self.connectivity.face_of(c as usize) as u32)
                }
                // The vertex opposite the edge in a triangle follows the edge's far end.
                Scheme::Loop => [c1, c2].map(|c| {
                    let f = self.connectivity.face_of(c as usize);
                    self.faces.indices[self.faces.next(self.faces.next(c as usize, f), f)]
                }),
            },
            _ => [NONE, NONE],
        };
        [a, b, wings[0], wings[1]]
    }

    #[inline]
    fn rule(&self, v: usize) -> VertexRule {
        self.tags.vertex_rules[v]
    }

    /// The far ends of the first two of `v`'s sharp edges in edge order
    /// (a crease vertex has exactly two): each edge at `v` leaves it from a
    /// corner or arrives at one.
    fn crease_neighbours(&self, v: usize) -> [u32; 2] {
        let connectivity = self.connectivity;
        let mut sharp = [NONE; 2];
        for &c in connectivity.vertex_corners(v) {
            let c = c as usize;
            let previous = self.faces.prev(c, connectivity.face_of(c));
            for e in [
                connectivity.corner_edges[c],
                connectivity.corner_edges[previous],
            ] {
                if !self.tags.edge_sharp[e as usize] || sharp.contains(&e) {
                    continue;
                }
                // Keep the two lowest edge indices, ascending.
                if e < sharp[0] {
                    sharp = [e, sharp[0]];
                } else if e < sharp[1] {
                    sharp[1] = e;
                }
            }
        }
        sharp.map(|e| {
            if e == NONE {
                return v as u32;
            }
            let [a, b] = connectivity.edges[e as usize];
            if a as usize == v {
                b
            } else {
                a
            }
        })
    }

    #[inline]
    fn neighbours(&self, v: usize) -> impl ExactSizeIterator<Item = u32> + '_ {
        // Around a smooth (manifold, interior, oriented) vertex each edge
        // leaves v in exactly one face: the corners' next vertices are the ring.
        self.connectivity
            .vertex_corners(v)
            .iter()
            .map(|&c| self.next_vertex(c))
    }

    #[inline]
    fn faces_around(&self, v: usize) -> impl Iterator<Item = u32> + '_ {
        self.connectivity
            .vertex_corners(v)
            .iter()
            .map(|&c| self.connectivity.face_of(c as usize) as u32)
    }
}
