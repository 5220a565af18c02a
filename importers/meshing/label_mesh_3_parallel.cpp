#include <tbb/global_control.h>

#include "importers/meshing/label_mesh_3_impl.h"

namespace viscera::importers::detail {

Mesh3Output run_mesh_3_parallel(const Mesh3Input& input) {
  // Mesh_3's parallel refinement locks a grid over the domain's bounding box and works on TBB's
  // task arena; the control caps the arena at the requested thread count.
  const tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                                    static_cast<std::size_t>(std::max(1, input.threads)));
  return run_mesh_3<CGAL::Parallel_tag>(input);
}

}  // namespace viscera::importers::detail
