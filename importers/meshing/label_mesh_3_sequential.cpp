#include "importers/meshing/label_mesh_3_impl.h"

namespace viscera::importers::detail {

Mesh3Output run_mesh_3_sequential(const Mesh3Input& input) {
  return run_mesh_3<CGAL::Sequential_tag>(input);
}

}  // namespace viscera::importers::detail
