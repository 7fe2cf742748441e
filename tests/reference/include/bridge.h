// C++ side of weft-reference: OpenSubdiv's Far refiner and stencil tables and
// OpenMesh's uniform subdividers behind a few flat-array calls. Errors are
// thrown as std::runtime_error, which cxx turns into a Rust Err.
#pragma once

#include "rust/cxx.h"

#include <cstddef>
#include <cstdint>
#include <memory>

#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/topologyRefiner.h>

namespace weft_reference {

struct OsdSettings;
struct OmMesh;

class OsdRefiner {
public:
  explicit OsdRefiner(std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> refiner);

  std::size_t vertex_count() const;
  std::size_t face_count() const;
  std::size_t corner_count() const;
  std::size_t fvar_value_count() const;
  void faces(rust::Slice<uint32_t> sizes, rust::Slice<uint32_t> indices) const;
  void interpolate(rust::Slice<const double> cage, std::size_t width, bool varying,
                   rust::Slice<double> out) const;
  void interpolate_face_varying(rust::Slice<const double> cage, std::size_t width,
                                rust::Slice<double> out_values,
                                rust::Slice<uint32_t> out_indices) const;
  void limit(rust::Slice<const double> cage_positions, rust::Slice<double> positions,
             rust::Slice<double> du, rust::Slice<double> dv) const;
  // Bfr's limit surface of the base level at (face, u, v) samples:
  // Bfr::RefinerSurfaceFactory with the given approximation levels.
  void bfr_evaluate(rust::Slice<const double> cage_positions, int32_t approx_smooth,
                    int32_t approx_sharp, rust::Slice<const uint32_t> faces,
                    rust::Slice<const double> uvs, rust::Slice<double> positions,
                    rust::Slice<double> du, rust::Slice<double> dv) const;

  const OpenSubdiv::Far::TopologyRefiner &refiner() const { return *refiner_; }

private:
  std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> refiner_;
};

std::unique_ptr<OsdRefiner> osd_refiner_new(
    uint32_t vertex_count, rust::Slice<const uint32_t> face_sizes,
    rust::Slice<const uint32_t> face_indices, rust::Slice<const uint32_t> crease_pairs,
    rust::Slice<const float> crease_sharpness, rust::Slice<const uint32_t> corners,
    rust::Slice<const float> corner_sharpness, uint32_t fvar_value_count,
    rust::Slice<const uint32_t> fvar_indices, rust::Slice<const uint32_t> holes,
    const OsdSettings &settings, uint32_t levels);

class OsdStencils {
public:
  explicit OsdStencils(std::unique_ptr<const OpenSubdiv::Far::StencilTableReal<double>> table);

  std::size_t stencil_count() const;
  void update(rust::Slice<const double> cage_positions, rust::Slice<double> out) const;
  // UpdateValues on `threads` std::threads, each over a contiguous range of
  // stencils, as a host without TBB spreads Far's table over its cores.
  void update_on_threads(rust::Slice<const double> cage_positions, rust::Slice<double> out,
                         uint32_t threads) const;

private:
  std::unique_ptr<const OpenSubdiv::Far::StencilTableReal<double>> table_;
};

std::unique_ptr<OsdStencils> osd_stencils_new(const OsdRefiner &refiner);

// Osd's own re-evaluation path: a single-precision Far::StencilTable applied
// by Osd::OmpEvaluator::EvalStencils on `threads` OpenMP threads.
class OsdParallelStencils {
public:
  explicit OsdParallelStencils(std::unique_ptr<const OpenSubdiv::Far::StencilTable> table);

  std::size_t stencil_count() const;
  void update(rust::Slice<const float> cage_positions, rust::Slice<float> out,
              uint32_t threads) const;

private:
  std::unique_ptr<const OpenSubdiv::Far::StencilTable> table_;
};

std::unique_ptr<OsdParallelStencils> osd_parallel_stencils_new(const OsdRefiner &refiner);

OmMesh om_catmull_clark(rust::Slice<const double> positions, rust::Slice<const uint32_t> face_sizes,
                        rust::Slice<const uint32_t> face_indices, uint32_t levels);
OmMesh om_loop(rust::Slice<const double> positions, rust::Slice<const uint32_t> face_sizes,
               rust::Slice<const uint32_t> face_indices, uint32_t levels);

} // namespace weft_reference
