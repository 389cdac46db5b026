// Gathers the glslangValidator --vn headers (one const uint32_t array each) behind shaders::spirv().
#include "shaders/spirv.h"

#include <cstdlib>

namespace cetview::shaders {
namespace {
using std::uint32_t;  // the generated headers spell it unqualified

#include "background_frag.h"
#include "background_vert.h"
#include "edge_frag.h"
#include "edge_vert.h"
#include "mesh_frag.h"
#include "mesh_pushed_frag.h"
#include "mesh_pushed_vert.h"
#include "mesh_vert.h"
#include "wire_frag.h"
#include "wire_pushed_frag.h"

template <std::size_t N>
Spirv wrap(const std::uint32_t (&words)[N]) {
  return Spirv{words, sizeof(words)};
}
}  // namespace

Spirv spirv(ShaderId id) {
  switch (id) {
    case ShaderId::kBackgroundVert:
      return wrap(spirv_background_vert);
    case ShaderId::kBackgroundFrag:
      return wrap(spirv_background_frag);
    case ShaderId::kMeshVert:
      return wrap(spirv_mesh_vert);
    case ShaderId::kMeshFrag:
      return wrap(spirv_mesh_frag);
    case ShaderId::kWireFrag:
      return wrap(spirv_wire_frag);
    case ShaderId::kMeshPushedVert:
      return wrap(spirv_mesh_pushed_vert);
    case ShaderId::kMeshPushedFrag:
      return wrap(spirv_mesh_pushed_frag);
    case ShaderId::kWirePushedFrag:
      return wrap(spirv_wire_pushed_frag);
    case ShaderId::kEdgeVert:
      return wrap(spirv_edge_vert);
    case ShaderId::kEdgeFrag:
      return wrap(spirv_edge_frag);
  }
  std::abort();  // unreachable: every enumerator is handled above
}

}  // namespace cetview::shaders
