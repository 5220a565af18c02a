#include "studio/document/primitive_objects.h"

#include <cctype>
#include <cmath>

#include "core/error.h"
#include "core/mesh/surface_embedding.h"
#include "core/meshing/tet_mesher.h"
#include "core/primitives/ball_primitive.h"
#include "core/primitives/flat_primitive.h"
#include "core/primitives/pipe_primitive.h"

namespace viscera::studio {

std::string to_string(PrimitiveKind kind) {
  switch (kind) {
    case PrimitiveKind::Ball:
      return "ball";
    case PrimitiveKind::Flat:
      return "flat";
    case PrimitiveKind::Pipe:
      return "pipe";
  }
  return "object";
}

std::string unique_object_id(const core::Scenario& scenario, const std::string& base) {
  if (scenario.find_object(base) == nullptr) return base;
  for (int n = 2;; ++n) {
    const std::string id = base + "-" + std::to_string(n);
    if (scenario.find_object(id) == nullptr) return id;
  }
}

namespace {

core::SurfaceMesh primitive_surface(const PrimitiveRequest& r) {
  switch (r.kind) {
    case PrimitiveKind::Ball:
      return core::tessellate_ball(core::make_ball(r.center, r.size, 0, 3));
    case PrimitiveKind::Flat: {
      const core::Vec3 u(r.size, 0.0, 0.0);
      const core::Vec3 v(0.0, r.size, 0.0);
      return core::tessellate_flat(
          core::make_flat(r.center - 0.5 * (u + v), u, v, 4, 4, r.size / 10.0));
    }
    case PrimitiveKind::Pipe: {
      core::PipePrimitive pipe;
      const core::Vec3 half(0.5 * r.length, 0.0, 0.0);
      pipe.points = {r.center - half, r.center, r.center + half};
      pipe.radii = {r.size, r.size, r.size};
      pipe.start_cap = core::PipeCap::Round;
      pipe.end_cap = core::PipeCap::Round;
      core::check_pipe(pipe, "pipe");
      return core::tessellate_pipe(pipe);
    }
  }
  throw core::UsageError("unknown primitive kind");
}

}  // namespace

core::SceneObject build_primitive_object(const PrimitiveRequest& request, const std::string& id,
                                         const core::Material& material, core::Progress& progress) {
  if (!(request.size > 0.0) || !std::isfinite(request.size)) {
    throw core::UsageError("the size of a " + to_string(request.kind) + " must be positive");
  }
  if (request.kind == PrimitiveKind::Pipe && !(request.length > 0.0)) {
    throw core::UsageError("the length of a pipe must be positive");
  }
  if (!(request.cell_size > 0.0)) throw core::UsageError("the cell size must be positive");
  progress.begin_stage("building the " + to_string(request.kind) + " surface", 1);
  core::SceneObject object;
  object.id = id;
  object.name = to_string(request.kind);
  object.name[0] = static_cast<char>(std::toupper(object.name[0]));
  if (id != to_string(request.kind)) object.name += " " + id.substr(id.rfind('-') + 1);
  object.role = core::ObjectRole::Organ;
  object.material = material.id;
  object.surface = primitive_surface(request);
  progress.step();

  core::TetMeshingOptions meshing;
  meshing.cell_size = request.cell_size;
  object.body = core::mesh_closed_surface(object.surface, meshing, progress);
  object.body.node_mass = core::lumped_node_masses(object.body, material.density);
  object.body.fixed.assign(object.body.nodes.size(), 0);
  object.embedding = core::embed_points(object.surface.vertices, object.body);
  object.body_kind = core::BodyKind::TetMesh;
  return object;
}

}  // namespace viscera::studio
