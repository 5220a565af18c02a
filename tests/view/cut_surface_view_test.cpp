// A cut organ in the endoscopic view (issue 17 §2): the body's visible surface as the cut left
// it replaces the package's, and the faces the cut laid open are coloured from the organ's solid
// texture — the same texture its skin was baked from, so the inside continues the skin.

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/mesh/surface_embedding.h"
#include "simulator/cutting/cut_surface.h"
#include "simulator/cutting/hybrid_cut.h"
#include "simulator/session/manual_control.h"
#include "simulator/view/cut_face_colours.h"
#include "simulator/view/endoscopic_view.h"
#include "simulator/view/scene_surfaces.h"
#include "tests/view/view_fixtures.h"

namespace viscera {
namespace {

/// The first pathology of the patient with a textured surface embedded in its tets.
const core::SceneObject& textured_pathology(const core::Scenario& scenario) {
  for (const core::SceneObject& object : scenario.objects) {
    if (object.role == core::ObjectRole::Pathology && !object.body.tets.empty() &&
        object.embedding.tet.size() == object.surface.vertices.size() &&
        scenario.textures.contains(object.texture))
      return object;
  }
  throw std::runtime_error("the patient has no textured pathology");
}

/// The median over a surface's vertices of the mean |skin albedo − solid texture| (0…255): the
/// skin's baked map read at each vertex's UV against the inside's colour at its rest point.
double median_skin_difference(const core::SurfaceMesh& skin, vtkImageData* albedo,
                              const view::CutFaceColours& inside) {
  int dims[3];
  albedo->GetDimensions(dims);
  const auto colours = inside.at(skin.vertices);
  std::vector<double> difference;
  for (std::size_t v = 0; v < skin.vertices.size(); ++v) {
    const int i =
        std::clamp(static_cast<int>(std::lround(skin.uvs[v].x() * (dims[0] - 1))), 0, dims[0] - 1);
    const int j =
        std::clamp(static_cast<int>(std::lround(skin.uvs[v].y() * (dims[1] - 1))), 0, dims[1] - 1);
    double sum = 0.0;
    for (int c = 0; c < 3; ++c)
      sum += std::abs(albedo->GetScalarComponentAsDouble(i, j, 0, c) -
                      255.0 * colours[v][static_cast<std::size_t>(c)]);
    difference.push_back(sum / 3.0);
  }
  std::nth_element(difference.begin(), difference.begin() + difference.size() / 2,
                   difference.end());
  return difference[difference.size() / 2];
}

TEST(CutSurfaceView, the_cut_faces_show_the_organs_solid_texture_and_the_skin_keeps_its_own) {
  const auto& patient = testing::hysteroscopy_patient();
  const core::SceneObject& object = textured_pathology(patient.scenario);
  const core::TextureSpec& spec = patient.scenario.textures.at(object.texture);
  view::ViewOptions options;
  options.width = 320;
  options.height = 180;
  options.offscreen = true;
  view::EndoscopicView view(patient.scenario, patient.package, options);

  // The solid texture the view colours cuts with is the one the skin was baked from: read at
  // the skin, it gives the baked map back (0.35 of 255 measured; another seed gives 5.6).
  const view::CutFaceColours inside(spec.preset, spec.seed);
  vtkImageData* albedo = view.surfaces().texture_of(object.id);
  ASSERT_NE(albedo, nullptr);
  ASSERT_EQ(object.surface.uvs.size(), object.surface.vertices.size());
  EXPECT_LT(median_skin_difference(object.surface, albedo, inside), 2.0);

  // Halve the pathology through its centre, at rest.
  core::Vec3 centre = core::Vec3::Zero();
  for (const core::Vec3& p : object.body.nodes)
    centre += p / static_cast<double>(object.body.nodes.size());
  const core::Vec3 normal = core::Vec3(0.2, 0.3, 1.0).normalized();
  const auto change = sim::cutting::hybrid_cut(
      object.body, object.body.nodes,
      sim::cutting::planar_cut_surface(centre, normal, normal.unitOrthogonal(), 0.05, 0.05, 4),
      object.surface, object.embedding);
  ASSERT_TRUE(change.changed);
  auto cut = std::make_shared<sim::CutVisibleSurface>();
  cut->mesh = change.visual;
  cut->embedding = change.visual_embedding;
  cut->tets = change.mesh.tets;

  sim::SessionSnapshot snapshot;
  snapshot.optics_angle = patient.scenario.session.instrument.optics_angle;
  snapshot.instrument = sim::starting_pose(patient.scenario, snapshot.optics_angle);
  sim::BodyPositions body;
  body.name = object.id;
  body.positions = change.current;
  body.cut_surface = cut;
  snapshot.bodies.push_back(body);
  vtkPolyData* faces = view.surfaces().cut_faces_of(object.id);
  ASSERT_NE(faces, nullptr);
  EXPECT_EQ(faces->GetNumberOfPolys(), 0);
  view.update(snapshot);
  ASSERT_EQ(faces->GetNumberOfPolys(), static_cast<vtkIdType>(change.visual_cut_triangles.size()));
  ASSERT_EQ(faces->GetNumberOfPoints(), static_cast<vtkIdType>(cut->mesh.vertices.size()));

  // Each cut-face corner: where its tet puts it, coloured by the solid texture at its
  // material point.
  const auto& flag = cut->mesh.vertex_attributes.at("cut_face");
  const auto at = core::embedded_positions(cut->embedding, cut->tets, change.current);
  std::vector<core::Vec3> material;
  std::vector<vtkIdType> corners;
  for (std::size_t v = 0; v < flag.size(); ++v) {
    if (flag[v] != 1.0) continue;
    corners.push_back(static_cast<vtkIdType>(v));
    material.push_back(cut->mesh.vertices[v]);
  }
  ASSERT_FALSE(corners.empty());
  const auto expected = inside.at(material);
  vtkDataArray* colours = faces->GetPointData()->GetScalars();
  ASSERT_NE(colours, nullptr);
  for (std::size_t k = 0; k < corners.size(); ++k) {
    double shown[3];
    faces->GetPoint(corners[k], shown);
    EXPECT_LT((core::Vec3(shown[0], shown[1], shown[2]) - at[static_cast<std::size_t>(corners[k])])
                  .norm(),
              1e-6);  // float points
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(colours->GetComponent(corners[k], c),
                std::round(255.0 * expected[k][static_cast<std::size_t>(c)]));
  }
  // The same surface again changes nothing; the view still renders.
  view.update(snapshot);
  EXPECT_EQ(faces->GetNumberOfPolys(), static_cast<vtkIdType>(change.visual_cut_triangles.size()));
  EXPECT_NE(view.capture(), nullptr);
}

}  // namespace
}  // namespace viscera
