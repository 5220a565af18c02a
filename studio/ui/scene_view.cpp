#include "studio/ui/scene_view.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellPicker.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkPlaneCollection.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPropPicker.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

#include <QMouseEvent>
#include <algorithm>
#include <cmath>

#include "core/package/vtk_mesh_io.h"
#include "studio/ui/vessel_actor.h"

namespace viscera::studio {
namespace {

std::array<double, 3> role_colour(core::ObjectRole role) {
  switch (role) {
    case core::ObjectRole::Organ:
      return {0.86, 0.52, 0.50};
    case core::ObjectRole::Pathology:
      return {0.93, 0.80, 0.55};
    case core::ObjectRole::Vessel:
      return {0.70, 0.12, 0.12};
    case core::ObjectRole::Fixture:
      return {0.62, 0.62, 0.66};
    case core::ObjectRole::Instrument:
      return {0.80, 0.82, 0.86};
  }
  return {0.8, 0.8, 0.8};
}

/// The albedo map of the object's texture as a VTK texture, or null.
vtkSmartPointer<vtkTexture> albedo_texture(const core::Scenario& scenario,
                                           const core::SceneObject& object,
                                           const PackageFiles& files) {
  const auto spec = scenario.textures.find(object.texture);
  if (object.surface.uvs.empty() || spec == scenario.textures.end()) return nullptr;
  const auto map = spec->second.maps.find("albedo");
  if (map == spec->second.maps.end()) return nullptr;
  const auto bytes = files.find(map->second);
  if (bytes == files.end() || bytes->second.empty()) return nullptr;
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  reader->SetMemoryBuffer(bytes->second.data());
  reader->SetMemoryBufferLength(static_cast<vtkIdType>(bytes->second.size()));
  reader->Update();
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(reader->GetOutput());
  texture->InterpolateOn();
  texture->RepeatOn();
  return texture;
}

/// The 12 edges of an axis-aligned box as line cells.
vtkSmartPointer<vtkPolyData> box_outline(const double b[6]) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  for (int k = 0; k < 8; ++k) {
    points->InsertNextPoint(b[(k & 1) ? 1 : 0], b[(k & 2) ? 3 : 2], b[(k & 4) ? 5 : 4]);
  }
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  for (int a = 0; a < 8; ++a) {
    for (const int bit : {1, 2, 4}) {
      if ((a & bit) == 0) {
        const vtkIdType edge[2] = {a, a | bit};
        lines->InsertNextCell(2, edge);
      }
    }
  }
  auto outline = vtkSmartPointer<vtkPolyData>::New();
  outline->SetPoints(points);
  outline->SetLines(lines);
  return outline;
}

}  // namespace

SceneView::SceneView(QWidget* parent) : QVTKOpenGLNativeWidget(parent) {
  auto window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  setRenderWindow(window);
  renderer_ = vtkSmartPointer<vtkRenderer>::New();
  renderer_->SetBackground(0.16, 0.18, 0.22);
  renderer_->SetBackground2(0.42, 0.46, 0.54);
  renderer_->GradientBackgroundOn();
  window->AddRenderer(renderer_);
  // Translucent organs over opaque pathologies need ordered blending.
  window->SetAlphaBitPlanes(1);
  renderer_->SetUseDepthPeeling(1);
  renderer_->SetMaximumNumberOfPeels(8);
  clip_plane_ = vtkSmartPointer<vtkPlane>::New();
}

void SceneView::show_scenario(const core::Scenario& scenario, const PackageFiles& files,
                              bool frame) {
  for (const auto& [id, actor] : actors_)
    renderer_->RemoveActor(actor);
  actors_.clear();
  clipped_.clear();
  for (const auto& object : scenario.objects) {
    if (object.surface.triangles.empty()) continue;
    auto polydata = vtkSmartPointer<vtkPolyData>::New();
    core::surface_to_polydata(object.surface, {}, *polydata);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(polydata);
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    const auto colour = role_colour(object.role);
    if (auto texture = albedo_texture(scenario, object, files)) {
      actor->SetTexture(texture);
      actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
    } else {
      actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
    }
    actor->GetProperty()->SetSpecular(0.25);
    actor->GetProperty()->SetSpecularPower(20.0);
    // The inside of a wall cut open by the clipping plane: the tissue colour, darker.
    auto inside = vtkSmartPointer<vtkProperty>::New();
    inside->SetColor(0.55 * colour[0], 0.55 * colour[1], 0.55 * colour[2]);
    inside->SetSpecular(0.0);
    actor->SetBackfaceProperty(inside);
    const QString id = QString::fromStdString(object.id);
    renderer_->AddActor(actor);
    actors_[id] = actor;
    if (object.role == core::ObjectRole::Organ || object.role == core::ObjectRole::Vessel)
      clipped_.insert(id);
  }
  for (const auto& [id, actor] : vessel_actors_)
    renderer_->RemoveActor(actor);
  vessel_actors_.clear();
  for (const auto& tree : scenario.vessel_trees) {
    if (auto actor = vessel_tree_actor(tree)) {
      renderer_->AddActor(actor);
      vessel_actors_[QString::fromStdString(tree.id)] = actor;
    }
  }
  ViewState state;
  try {
    state = view_state_of(files);
  } catch (const std::exception&) {
    // Checked when the package was opened; a document never holds a bad one.
  }
  if (!actors_.contains(selected_)) selected_.clear();
  update_clipping();
  if (frame) reset_camera();
  apply_view_state(state);
}

void SceneView::apply_view_state(const ViewState& state) {
  for (const auto& [id, actor] : actors_) {
    actor->SetVisibility(state.visible(id.toStdString()));
    actor->GetProperty()->SetOpacity(state.opacity_of(id.toStdString()));
  }
  for (const auto& [id, actor] : vessel_actors_)
    actor->SetVisibility(state.visible(vessel_tree_key(id.toStdString())));
  update_outline();
  render();
}

double SceneView::object_opacity(const QString& id) const {
  const auto actor = actors_.find(id);
  return actor == actors_.end() ? 0.0 : actor->second->GetProperty()->GetOpacity();
}

bool SceneView::vessel_tree_visible(const QString& tree_id) const {
  const auto actor = vessel_actors_.find(tree_id);
  return actor != vessel_actors_.end() && actor->second->GetVisibility() != 0;
}

void SceneView::set_clip_plane(const core::Vec3& origin, const core::Vec3& normal) {
  const core::Vec3 n = normal.normalized();
  clip_plane_->SetOrigin(origin.x(), origin.y(), origin.z());
  clip_plane_->SetNormal(n.x(), n.y(), n.z());
  update_clipping();
  render();
}

void SceneView::set_clip_across(int axis, double fraction, bool keep_low) {
  double box[6] = {1, -1, 1, -1, 1, -1};
  bool any = false;
  for (const auto& [id, actor] : actors_) {
    const double* b = actor->GetMapper()->GetBounds();
    for (int k = 0; k < 3; ++k) {
      box[2 * k] = any ? std::min(box[2 * k], b[2 * k]) : b[2 * k];
      box[2 * k + 1] = any ? std::max(box[2 * k + 1], b[2 * k + 1]) : b[2 * k + 1];
    }
    any = true;
  }
  if (!any) return;
  const int a = std::clamp(axis, 0, 2);
  core::Vec3 origin(0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3]), 0.5 * (box[4] + box[5]));
  origin[a] = box[2 * a] + std::clamp(fraction, 0.0, 1.0) * (box[2 * a + 1] - box[2 * a]);
  core::Vec3 normal = core::Vec3::Zero();
  normal[a] = keep_low ? -1.0 : 1.0;
  set_clip_plane(origin, normal);
}

void SceneView::set_clipping(bool on) {
  clipping_ = on;
  update_clipping();
  render();
}

void SceneView::update_clipping() {
  const auto clip = [this](vtkActor* actor) {
    vtkMapper* mapper = actor->GetMapper();
    mapper->RemoveAllClippingPlanes();
    if (clipping_) mapper->AddClippingPlane(clip_plane_);
  };
  for (const auto& [id, actor] : actors_) {
    if (clipped_.contains(id)) {
      clip(actor);
    } else {
      actor->GetMapper()->RemoveAllClippingPlanes();
    }
  }
  for (const auto& [id, actor] : vessel_actors_)
    clip(actor);
}

bool SceneView::view_from_cervix(const core::Scenario& scenario) {
  const core::Landmark* internal = nullptr;
  const core::Landmark* fundus = nullptr;
  for (const auto& mark : scenario.landmarks) {
    if (mark.id == "cervix-internal-os") internal = &mark;
    if (mark.id == "fundus") fundus = &mark;
  }
  if (internal == nullptr) return false;
  // The cavity's centre: the mean of the host surface's vertices marked as cavity wall.
  core::Vec3 target = core::Vec3::Zero();
  int count = 0;
  if (const core::SceneObject* host = scenario.find_object(internal->object)) {
    const auto cavity = host->surface.vertex_attributes.find("cavity");
    if (cavity != host->surface.vertex_attributes.end()) {
      for (std::size_t v = 0; v < cavity->second.size(); ++v) {
        if (cavity->second[v] == 1.0) {
          target += host->surface.vertices[v];
          ++count;
        }
      }
    }
  }
  if (count > 0) {
    target /= count;
  } else if (fundus != nullptr) {
    target = fundus->position;
  } else {
    return false;
  }
  const core::Vec3 eye = internal->position;
  const core::Vec3 axis = (target - eye).normalized();
  core::Vec3 up = core::Vec3::UnitY() - core::Vec3::UnitY().dot(axis) * axis;
  if (up.norm() < 1e-6) up = axis.unitOrthogonal();
  vtkCamera* camera = renderer_->GetActiveCamera();
  camera->SetPosition(eye.x(), eye.y(), eye.z());
  camera->SetFocalPoint(target.x(), target.y(), target.z());
  camera->SetViewUp(up.x(), up.y(), up.z());
  camera->SetViewAngle(70.0);
  renderer_->ResetCameraClippingRange();
  camera->SetClippingRange(1e-4, 0.5);
  render();
  return true;
}

void SceneView::set_image_planes(const std::vector<vtkProp3D*>& planes) {
  for (const auto& plane : image_planes_)
    renderer_->RemoveViewProp(plane);
  image_planes_.clear();
  for (vtkProp3D* plane : planes) {
    plane->SetPickable(false);
    renderer_->AddViewProp(plane);
    image_planes_.emplace_back(plane);
  }
  render();
}

void SceneView::reset_camera() {
  renderer_->ResetCamera();
  vtkCamera* camera = renderer_->GetActiveCamera();
  const double* focal = camera->GetFocalPoint();
  const double distance = camera->GetDistance();
  camera->SetViewAngle(30.0);
  const double direction[3] = {0.45, -0.8, 0.4};
  const double length = std::sqrt(0.45 * 0.45 + 0.8 * 0.8 + 0.4 * 0.4);
  camera->SetPosition(focal[0] + distance * direction[0] / length,
                      focal[1] + distance * direction[1] / length,
                      focal[2] + distance * direction[2] / length);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer_->ResetCamera();
}

void SceneView::render() {
  renderWindow()->Render();
  update();
}

bool SceneView::object_visible(const QString& id) const {
  const auto actor = actors_.find(id);
  return actor != actors_.end() && actor->second->GetVisibility() != 0;
}

void SceneView::select_object(const QString& id) {
  selected_ = actors_.contains(id) ? id : QString();
  update_outline();
  renderWindow()->Render();
  update();
}

int SceneView::textured_object_count() const {
  int count = 0;
  for (const auto& [id, actor] : actors_)
    count += actor->GetTexture() != nullptr ? 1 : 0;
  return count;
}

void SceneView::update_outline() {
  if (outline_ != nullptr) renderer_->RemoveActor(outline_);
  outline_ = nullptr;
  const auto actor = actors_.find(selected_);
  if (actor == actors_.end() || actor->second->GetVisibility() == 0) return;
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(box_outline(actor->second->GetBounds()));
  outline_ = vtkSmartPointer<vtkActor>::New();
  outline_->SetMapper(mapper);
  outline_->SetPickable(false);
  outline_->GetProperty()->SetColor(1.0, 0.85, 0.2);
  outline_->GetProperty()->SetLineWidth(2.0);
  outline_->GetProperty()->LightingOff();
  renderer_->AddActor(outline_);
}

QString SceneView::object_at(const QPoint& position) {
  const double ratio = devicePixelRatioF();
  const double x = position.x() * ratio;
  const double y = (height() - 1 - position.y()) * ratio;
  auto picker = vtkSmartPointer<vtkPropPicker>::New();
  if (picker->Pick(x, y, 0.0, renderer_) == 0) return {};
  vtkActor* picked = picker->GetActor();
  for (const auto& [id, actor] : actors_) {
    if (actor.GetPointer() == picked) return id;
  }
  return {};
}

std::optional<std::pair<QString, core::Vec3>> SceneView::surface_point_at(const QPoint& position) {
  const double ratio = devicePixelRatioF();
  auto picker = vtkSmartPointer<vtkCellPicker>::New();
  picker->SetTolerance(0.0005);
  if (picker->Pick(position.x() * ratio, (height() - 1 - position.y()) * ratio, 0.0, renderer_) ==
      0)
    return std::nullopt;
  for (const auto& [id, actor] : actors_) {
    if (actor.GetPointer() == picker->GetActor()) {
      const double* p = picker->GetPickPosition();
      return std::make_pair(id, core::Vec3(p[0], p[1], p[2]));
    }
  }
  return std::nullopt;
}

vtkActor* SceneView::object_actor(const QString& id) const {
  const auto actor = actors_.find(id);
  return actor == actors_.end() ? nullptr : actor->second.GetPointer();
}

void SceneView::mousePressEvent(QMouseEvent* event) {
  press_position_ = event->pos();
  QVTKOpenGLNativeWidget::mousePressEvent(event);
}

void SceneView::mouseReleaseEvent(QMouseEvent* event) {
  QVTKOpenGLNativeWidget::mouseReleaseEvent(event);
  if (event->button() == Qt::LeftButton &&
      (event->pos() - press_position_).manhattanLength() <= 3) {
    // Both picks first: selecting fills the side panels, which can resize this view and move
    // what lies under the cursor.
    const QString id = object_at(event->pos());
    const auto hit = surface_point_at(event->pos());
    select_object(id);
    emit object_picked(id);
    if (hit) emit surface_clicked(hit->first, hit->second);
  }
}

}  // namespace viscera::studio
