// Compiles the public header as C++17 with every warning an error, so the
// extern "C" block and the enum's underlying type work for C++ hosts.
#include "weft.h"

#include <cstdint>
#include <type_traits>

static_assert(sizeof(WeftStatus) == sizeof(std::uint32_t), "WeftStatus is 32 bits");
static_assert(WEFT_STATUS_OK == 0, "success is zero");

int weft_header_cpp17_check();

int weft_header_cpp17_check() {
  WeftMesh *mesh = nullptr;
  WeftMeshInfo info{};
  (void)info;
  return weft_mesh_new(nullptr, 0, nullptr, 0, nullptr, 0, &mesh) == WEFT_STATUS_OK ? 0 : 1;
}
