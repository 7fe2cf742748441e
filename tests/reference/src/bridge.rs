//! The `cxx` declarations of the C++ side (`src/bridge.cc`). Everything here
//! is crate-private; `lib.rs` checks the arguments and offers plain Rust.

#[cxx::bridge(namespace = "weft_reference")]
pub(crate) mod ffi {
    /// Sdc options as plain numbers (the values of the Sdc enumerations).
    struct OsdSettings {
        /// 0 Catmull-Clark, 1 Loop, 2 bilinear.
        scheme: u32,
        /// `Sdc::Options::VtxBoundaryInterpolation`.
        boundary: u32,
        /// `Sdc::Options::CreasingMethod`.
        creasing: u32,
        /// `Sdc::Options::FVarLinearInterpolation`.
        fvar_linear: u32,
        /// `Sdc::Options::TriangleSubdivision`.
        triangles: u32,
        /// `UniformOptions::fullTopologyInLastLevel`: off, as OpenSubdiv's
        /// users refine for positions and faces; `PrimvarRefiner::Limit`
        /// needs it on.
        full_topology: bool,
    }

    /// A polygon mesh returned by OpenMesh.
    struct OmMesh {
        positions: Vec<f64>,
        face_sizes: Vec<u32>,
        face_indices: Vec<u32>,
    }

    unsafe extern "C++" {
        include!("weft-reference/include/bridge.h");

        /// A `Far::TopologyRefiner` refined uniformly.
        type OsdRefiner;

        #[allow(clippy::too_many_arguments)]
        fn osd_refiner_new(
            vertex_count: u32,
            face_sizes: &[u32],
            face_indices: &[u32],
            crease_pairs: &[u32],
            crease_sharpness: &[f32],
            corners: &[u32],
            corner_sharpness: &[f32],
            fvar_value_count: u32,
            fvar_indices: &[u32],
            holes: &[u32],
            settings: &OsdSettings,
            levels: u32,
        ) -> Result<UniquePtr<OsdRefiner>>;

        fn vertex_count(self: &OsdRefiner) -> usize;
        fn face_count(self: &OsdRefiner) -> usize;
        fn corner_count(self: &OsdRefiner) -> usize;
        fn fvar_value_count(self: &OsdRefiner) -> usize;
        fn faces(self: &OsdRefiner, sizes: &mut [u32], indices: &mut [u32]);
        fn interpolate(
            self: &OsdRefiner,
            cage: &[f64],
            width: usize,
            varying: bool,
            out: &mut [f64],
        ) -> Result<()>;
        fn interpolate_face_varying(
            self: &OsdRefiner,
            cage: &[f64],
            width: usize,
            out_values: &mut [f64],
            out_indices: &mut [u32],
        ) -> Result<()>;
        fn limit(
            self: &OsdRefiner,
            cage_positions: &[f64],
            positions: &mut [f64],
            du: &mut [f64],
            dv: &mut [f64],
        ) -> Result<()>;
        #[allow(clippy::too_many_arguments)]
        fn bfr_evaluate(
            self: &OsdRefiner,
            cage_positions: &[f64],
            approx_smooth: i32,
            approx_sharp: i32,
            faces: &[u32],
            uvs: &[f64],
            positions: &mut [f64],
            du: &mut [f64],
            dv: &mut [f64],
        ) -> Result<()>;

        /// A `Far::StencilTableReal<double>` for the last level.
        type OsdStencils;

        fn osd_stencils_new(refiner: &OsdRefiner) -> Result<UniquePtr<OsdStencils>>;
        fn stencil_count(self: &OsdStencils) -> usize;
        fn update(self: &OsdStencils, cage_positions: &[f64], out: &mut [f64]);
        fn update_on_threads(
            self: &OsdStencils,
            cage_positions: &[f64],
            out: &mut [f64],
            threads: u32,
        ) -> Result<()>;

        /// A `Far::StencilTable` (single precision, as Osd's evaluators
        /// take) for the last level, evaluated by `Osd::OmpEvaluator`.
        type OsdParallelStencils;

        fn osd_parallel_stencils_new(
            refiner: &OsdRefiner,
        ) -> Result<UniquePtr<OsdParallelStencils>>;
        fn stencil_count(self: &OsdParallelStencils) -> usize;
        fn update(
            self: &OsdParallelStencils,
            cage_positions: &[f32],
            out: &mut [f32],
            threads: u32,
        ) -> Result<()>;

        fn om_catmull_clark(
            positions: &[f64],
            face_sizes: &[u32],
            face_indices: &[u32],
            levels: u32,
        ) -> Result<OmMesh>;
        fn om_loop(
            positions: &[f64],
            face_sizes: &[u32],
            face_indices: &[u32],
            levels: u32,
        ) -> Result<OmMesh>;
    }
}

// The C++ objects are immutable after construction and their methods are
// `const` without shared caches, so they may be used from several threads.
unsafe impl Send for ffi::OsdRefiner {}
unsafe impl Sync for ffi::OsdRefiner {}
unsafe impl Send for ffi::OsdStencils {}
unsafe impl Sync for ffi::OsdStencils {}
unsafe impl Send for ffi::OsdParallelStencils {}
unsafe impl Sync for ffi::OsdParallelStencils {}
