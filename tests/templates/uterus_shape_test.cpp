#include "templates/hysteroscopy/uterus_shape.h"

#include <gtest/gtest.h>

#include "core/meshing/tet_mesher.h"

namespace viscera::templates {

TEST(UterusShape, default_uterus_is_closed_and_meshes) {
  const UterusShape shape = make_uterus({}, SmoothDeformation());
  EXPECT_TRUE(core::is_closed_and_consistently_oriented(shape.surface));
  EXPECT_TRUE(core::is_closed_and_consistently_oriented(shape.envelope));
  EXPECT_GT(core::enclosed_volume(shape.surface), 0.0);
  std::printf("vertices %zu triangles %zu volume %g envelope %g\n", shape.surface.vertices.size(),
              shape.surface.triangles.size(), core::enclosed_volume(shape.surface) * 1e6,
              core::enclosed_volume(shape.envelope) * 1e6);
  const core::TetMesh body = core::mesh_closed_surface(shape.surface);
  std::printf("nodes %zu tets %zu\n", body.nodes.size(), body.tets.size());
}

}  // namespace viscera::templates
