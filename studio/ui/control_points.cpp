#include "studio/ui/control_points.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkHandleWidget.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSphereHandleRepresentation.h>

#include <QFileDialog>
#include <QLabel>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>
#include <fstream>

#include "core/error.h"
#include "core/materials/shipped_materials.h"
#include "studio/document/model_objects.h"
#include "studio/ui/scene_view.h"

namespace viscera::studio {
namespace {

/// Radius of the handle spheres: 2 % of the control net's extent.
double handle_radius(const std::vector<core::Vec3>& points) {
  core::Vec3 low = points.front(), high = points.front();
  for (const auto& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return std::max(0.02 * (high - low).norm(), 1e-4);
}

}  // namespace

ControlPointPanel::ControlPointPanel(ScenarioDocument& document, SceneView& view, QWidget* parent)
    : OrganPanel(document, parent), view_(view) {
  auto* layout = new QVBoxLayout(this);
  label_ = new QLabel(this);
  label_->setWordWrap(true);
  layout->addWidget(label_);
  auto* import = new QPushButton(tr("Import model JSON…"), this);
  layout->addWidget(import);
  layout->addStretch(1);
  connect(import, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Import a model"), QString(),
                                                      tr("Viscera models (*.json);;All files (*)"));
    if (!path.isEmpty()) import_model(path.toStdString());
  });
  refresh();
}

ControlPointPanel::~ControlPointPanel() {
  clear_handles();
}

void ControlPointPanel::clear_handles() {
  for (auto& handle : handles_) {
    handle->Off();
    handle->RemoveAllObservers();
  }
  handles_.clear();
  points_.clear();
  handles_for_.clear();
}

void ControlPointPanel::refresh() {
  const std::string id = object_id().toStdString();
  std::optional<core::ModelDocument> model;
  std::string key;
  if (!id.empty()) {
    const auto file = document_.files().find(model_file_path(id));
    if (file != document_.files().end()) {
      key = id + "\n" + file->second;
      try {
        model = object_model(document_.files(), id);
      } catch (const core::Error&) {
        model.reset();
      }
    }
  }
  if (!model) {
    clear_handles();
    label_->setText(tr("Select a model object (import one below) to drag its control points."));
    return;
  }
  label_->setText(tr("<b>%1</b> — %2 control points of a %3; drag a sphere in the 3D view.")
                      .arg(QString::fromStdString(model->name))
                      .arg(core::model_control_points(*model).size())
                      .arg(QString::fromStdString(core::to_string(model->kind))));
  if (key == handles_for_) return;
  clear_handles();
  handles_for_ = key;
  points_ = core::model_control_points(*model);
  vtkRenderWindowInteractor* interactor = view_.interactor();
  const double radius = handle_radius(points_);
  for (const auto& point : points_) {
    auto representation = vtkSmartPointer<vtkSphereHandleRepresentation>::New();
    representation->SetSphereRadius(radius);
    representation->GetProperty()->SetColor(0.2, 0.8, 0.3);
    representation->GetSelectedProperty()->SetColor(1.0, 0.9, 0.2);
    double p[3] = {point.x(), point.y(), point.z()};
    representation->SetWorldPosition(p);
    auto widget = vtkSmartPointer<vtkHandleWidget>::New();
    widget->SetInteractor(interactor);
    widget->SetCurrentRenderer(view_.renderer());
    widget->SetRepresentation(representation);
    auto callback = vtkSmartPointer<vtkCallbackCommand>::New();
    callback->SetClientData(this);
    callback->SetCallback([](vtkObject* caller, unsigned long, void* self, void*) {
      static_cast<ControlPointPanel*>(self)->on_interaction_end(caller);
    });
    widget->AddObserver(vtkCommand::EndInteractionEvent, callback);
    widget->On();
    handles_.push_back(widget);
  }
  view_.render();
}

core::Vec3 ControlPointPanel::handle_position(int index) const {
  double p[3];
  vtkHandleWidget* widget = handles_.at(static_cast<std::size_t>(index));
  static_cast<vtkHandleRepresentation*>(widget->GetRepresentation())->GetWorldPosition(p);
  return {p[0], p[1], p[2]};
}

void ControlPointPanel::on_interaction_end(vtkObject* caller) {
  for (std::size_t i = 0; i < handles_.size(); ++i) {
    if (handles_[i].GetPointer() != caller) continue;
    const core::Vec3 to = handle_position(static_cast<int>(i));
    if ((to - points_[i]).norm() <= 1e-12) return;
    // Rebuild after VTK's event handling has returned, not inside it.
    const int index = static_cast<int>(i);
    QTimer::singleShot(0, this, [this, index, to] { move_control_point(index, to); });
    return;
  }
}

bool ControlPointPanel::move_control_point(int index, const core::Vec3& position) {
  const std::string id = require_object();
  if (id.empty()) return false;
  std::optional<core::ModelDocument> model;
  try {
    model = object_model(document_.files(), id);
    if (!model) throw core::UsageError("object \"" + id + "\" is not a model object");
    core::move_model_control_point(*model, index, position);
  } catch (const std::exception& e) {
    emit failed(QString::fromUtf8(e.what()));
    handles_for_.clear();  // put the handles back where the model has them
    refresh();
    return false;
  }
  const std::string material = document_.scenario().find_object(id)->material;
  core::SceneObject rebuilt;
  if (!run(tr("Rebuilding %1").arg(QString::fromStdString(id)), [&](core::Progress& progress) {
        rebuilt = build_studio_model_object(*model, material, progress);
      })) {
    handles_for_.clear();
    refresh();
    return false;
  }
  return push([&] { return new MoveControlPointCommand(document_, *model, rebuilt, index); });
}

QString ControlPointPanel::add_model(const core::ModelDocument& model) {
  std::string material_id;
  std::optional<core::Material> material;
  if (!model.material) {
    const auto& materials = document_.scenario().materials;
    if (materials.empty()) {
      material = core::shipped_material("myometrium");
      material_id = material->id;
    } else {
      material_id = materials.begin()->first;
    }
  } else {
    material = model.material;
  }
  core::SceneObject object;
  try {
    core::check_model(model);
  } catch (const std::exception& e) {
    emit failed(QString::fromUtf8(e.what()));
    return {};
  }
  if (!run(tr("Building %1").arg(QString::fromStdString(model.id)), [&](core::Progress& progress) {
        object = build_studio_model_object(model, material_id, progress);
      }))
    return {};
  if (!push([&] { return new AddModelObjectCommand(document_, model, object, material); }))
    return {};
  emit created(QString::fromStdString(model.id));
  return QString::fromStdString(model.id);
}

QString ControlPointPanel::import_model(const std::filesystem::path& path) {
  try {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw core::InputError("cannot read the file", {path.string(), "", ""});
    nlohmann::json json;
    try {
      json = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
      throw core::InputError(std::string("not JSON: ") + e.what(), {path.string(), "", ""});
    }
    return add_model(core::model_from_json(json, path.string()));
  } catch (const std::exception& e) {
    emit failed(QString::fromUtf8(e.what()));
    return {};
  }
}

}  // namespace viscera::studio
