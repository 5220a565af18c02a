#include "studio/ui/deformation_panel.h"

#include <vtkActor.h>
#include <vtkMapper.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>

#include "simulator/physics/organ_motility.h"
#include "studio/document/organ_commands.h"
#include "studio/ui/scene_view.h"
#include "textures/active_deformation_specs.h"

namespace viscera::studio {
namespace {

QDoubleSpinBox* spin(QWidget* parent, double low, double high, double value, int decimals) {
  auto* box = new QDoubleSpinBox(parent);
  box->setRange(low, high);
  box->setDecimals(decimals);
  box->setValue(value);
  return box;
}

/// The polydata an object's actor draws, or null.
vtkPolyData* actor_polydata(SceneView& view, const QString& id) {
  vtkActor* actor = view.object_actor(id);
  if (actor == nullptr || actor->GetMapper() == nullptr) return nullptr;
  return vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0));
}

}  // namespace

DeformationPanel::DeformationPanel(ScenarioDocument& document, SceneView& view, QWidget* parent)
    : OrganPanel(document, parent), view_(view) {
  auto* layout = new QVBoxLayout(this);
  label_ = new QLabel(this);
  label_->setWordWrap(true);
  layout->addWidget(label_);

  auto* motility = new QGroupBox(tr("Organ motility"), this);
  auto* form = new QFormLayout(motility);
  amplitude_mm_ = spin(this, 0.0, 50.0, 2.0, 2);
  form->addRow(tr("Amplitude mean (mm)"), amplitude_mm_);
  amplitude_variance_mm2_ = spin(this, 0.0, 100.0, 0.0, 3);
  form->addRow(tr("Amplitude variance (mm²)"), amplitude_variance_mm2_);
  wave_speed_mm_s_ = spin(this, 0.1, 1000.0, 10.0, 1);
  form->addRow(tr("Wave speed (mm/s)"), wave_speed_mm_s_);
  auto* direction = new QHBoxLayout;
  for (int k = 0; k < 3; ++k) {
    direction_[k] = spin(this, -1.0, 1.0, k == 0 ? 1.0 : 0.0, 2);
    direction_[k]->setSingleStep(0.1);
    direction->addWidget(direction_[k]);
  }
  form->addRow(tr("Wave direction"), direction);
  frequency_ = spin(this, 0.0, 10.0, 0.1, 3);
  form->addRow(tr("Frequency (Hz)"), frequency_);
  frequency_disturbance_ = spin(this, 0.0, 10.0, 0.0, 3);
  form->addRow(tr("Frequency disturbance (Hz)"), frequency_disturbance_);
  interval_mean_ = spin(this, 0.0, 600.0, 0.0, 2);
  interval_mean_->setToolTip(tr("0: no impulsive contractions"));
  form->addRow(tr("Contraction interval (s)"), interval_mean_);
  interval_variance_ = spin(this, 0.0, 1000.0, 0.0, 3);
  form->addRow(tr("Interval variance (s²)"), interval_variance_);
  auto* motility_buttons = new QHBoxLayout;
  preview_button_ = new QPushButton(tr("Preview"), this);
  preview_button_->setCheckable(true);
  auto* apply_motility_button = new QPushButton(tr("Apply motility"), this);
  motility_buttons->addWidget(preview_button_);
  motility_buttons->addWidget(apply_motility_button);
  form->addRow(motility_buttons);
  layout->addWidget(motility);

  auto* pulse = new QGroupBox(tr("Pulse"), this);
  auto* pulse_form = new QFormLayout(pulse);
  tree_ = new QComboBox(this);
  pulse_form->addRow(tr("Vessel tree"), tree_);
  heart_rate_ = spin(this, 20.0, 250.0, 70.0, 0);
  pulse_form->addRow(tr("Heart rate (1/min)"), heart_rate_);
  pulse_velocity_ = spin(this, 0.1, 30.0, 5.0, 2);
  pulse_form->addRow(tr("Pulse velocity (m/s)"), pulse_velocity_);
  wall_force_ = spin(this, 0.0, 10.0, 0.05, 3);
  pulse_form->addRow(tr("Wall force (N)"), wall_force_);
  auto* apply_pulse_button = new QPushButton(tr("Apply pulse"), this);
  pulse_form->addRow(apply_pulse_button);
  layout->addWidget(pulse);
  layout->addStretch(1);

  timer_ = new QTimer(this);
  timer_->setInterval(40);
  connect(timer_, &QTimer::timeout, this,
          [this] { preview_at(static_cast<double>(clock_.elapsed()) / 1000.0); });
  connect(preview_button_, &QPushButton::toggled, this, [this](bool on) {
    if (on && !previewing()) {
      if (!start_preview()) preview_button_->setChecked(false);
    } else if (!on) {
      stop_preview();
    }
  });
  connect(apply_motility_button, &QPushButton::clicked, this, [this] { apply_motility(); });
  connect(apply_pulse_button, &QPushButton::clicked, this, [this] {
    apply_pulse(tree_->currentData().toString(), heart_rate_->value(), pulse_velocity_->value(),
                wall_force_->value());
  });
  refresh();
}

DeformationPanel::~DeformationPanel() {
  timer_->stop();
}

core::MotilitySpec DeformationPanel::motility() const {
  core::MotilitySpec spec;
  spec.amplitude_mean = amplitude_mm_->value() / 1000.0;
  spec.amplitude_variance = amplitude_variance_mm2_->value() * 1e-6;
  spec.wave_speed = wave_speed_mm_s_->value() / 1000.0;
  spec.wave_direction =
      core::Vec3(direction_[0]->value(), direction_[1]->value(), direction_[2]->value());
  spec.frequency = frequency_->value();
  spec.frequency_disturbance = frequency_disturbance_->value();
  spec.contraction_interval_mean = interval_mean_->value();
  spec.contraction_interval_variance = interval_variance_->value();
  return spec;
}

void DeformationPanel::set_motility(const core::MotilitySpec& spec) {
  amplitude_mm_->setValue(spec.amplitude_mean * 1000.0);
  amplitude_variance_mm2_->setValue(spec.amplitude_variance * 1e6);
  wave_speed_mm_s_->setValue(spec.wave_speed * 1000.0);
  for (int k = 0; k < 3; ++k)
    direction_[k]->setValue(spec.wave_direction[k]);
  frequency_->setValue(spec.frequency);
  frequency_disturbance_->setValue(spec.frequency_disturbance);
  interval_mean_->setValue(spec.contraction_interval_mean);
  interval_variance_->setValue(spec.contraction_interval_variance);
}

void DeformationPanel::show_object(const QString& id) {
  if (id != object_id()) stop_preview();
  OrganPanel::show_object(id);
}

void DeformationPanel::refresh() {
  const core::SceneObject* object =
      object_id().isEmpty() ? nullptr : document_.scenario().find_object(object_id().toStdString());
  tree_->clear();
  int deformations = 0;
  if (object != nullptr) {
    for (const auto& tree : document_.scenario().vessel_trees) {
      if (tree.host_object == object->id)
        tree_->addItem(QString::fromStdString(tree.id), QString::fromStdString(tree.id));
    }
    for (const auto& d : document_.scenario().active_deformations)
      deformations += d.target_object == object->id ? 1 : 0;
  }
  label_->setText(object == nullptr ? tr("Select an organ to make it move.")
                                    : tr("<b>%1</b> — %2 active deformation(s)")
                                          .arg(QString::fromStdString(object->name))
                                          .arg(deformations));
}

bool DeformationPanel::apply_motility() {
  const std::string id = require_object();
  if (id.empty()) return false;
  try {
    core::ActiveDeformation deformation = textures::make_motility(id + "-motility", id, motility());
    return push([&] { return new SetActiveDeformationCommand(document_, std::move(deformation)); });
  } catch (const std::exception& e) {
    emit failed(QString::fromUtf8(e.what()));
    return false;
  }
}

bool DeformationPanel::apply_pulse(const QString& tree_id, double heart_rate_bpm,
                                   double pulse_velocity, double wall_force) {
  const std::string id = require_object();
  if (id.empty()) return false;
  const auto& trees = document_.scenario().vessel_trees;
  const auto tree = std::find_if(trees.begin(), trees.end(), [&](const auto& t) {
    return t.id == tree_id.toStdString() && t.host_object == id;
  });
  if (tree == trees.end()) {
    emit failed(
        tr("Object %1 has no vessel tree \"%2\".").arg(QString::fromStdString(id), tree_id));
    return false;
  }
  try {
    core::ActiveDeformation deformation = textures::make_pulse(
        tree->id + "-pulse", id, *tree, heart_rate_bpm, pulse_velocity, wall_force);
    return push([&] { return new SetActiveDeformationCommand(document_, std::move(deformation)); });
  } catch (const std::exception& e) {
    emit failed(QString::fromUtf8(e.what()));
    return false;
  }
}

bool DeformationPanel::start_preview() {
  const std::string id = require_object();
  if (id.empty()) return false;
  try {
    (void)sim::OrganMotility(motility(), {core::Vec3::Zero()}, kPreviewSeed);  // checks the spec
  } catch (const std::exception& e) {
    emit failed(QString::fromUtf8(e.what()));
    return false;
  }
  previewed_ = QString::fromStdString(id);
  clock_.start();
  timer_->start();
  preview_button_->setChecked(true);
  return true;
}

bool DeformationPanel::previewing() const {
  return timer_->isActive();
}

void DeformationPanel::preview_at(double t) {
  const core::SceneObject* object = document_.scenario().find_object(previewed_.toStdString());
  vtkPolyData* polydata = actor_polydata(view_, previewed_);
  if (object == nullptr || polydata == nullptr ||
      polydata->GetNumberOfPoints() != static_cast<vtkIdType>(object->surface.vertices.size())) {
    stop_preview();
    return;
  }
  // Built per frame from the editors, so a changed parameter shows at once.
  const sim::OrganMotility motion(motility(), object->surface.vertices, kPreviewSeed);
  const std::vector<core::Vec3> moved = motion.positions(t);
  vtkPoints* points = polydata->GetPoints();
  for (std::size_t i = 0; i < moved.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), moved[i].data());
  points->Modified();
  polydata->Modified();
  view_.render();
}

void DeformationPanel::stop_preview() {
  const bool was = timer_->isActive();
  timer_->stop();
  if (preview_button_->isChecked()) preview_button_->setChecked(false);
  if (!was || previewed_.isEmpty()) return;
  // Back at rest: the object's own surface.
  const core::SceneObject* object = document_.scenario().find_object(previewed_.toStdString());
  vtkPolyData* polydata = actor_polydata(view_, previewed_);
  if (object != nullptr && polydata != nullptr &&
      polydata->GetNumberOfPoints() == static_cast<vtkIdType>(object->surface.vertices.size())) {
    vtkPoints* points = polydata->GetPoints();
    for (std::size_t i = 0; i < object->surface.vertices.size(); ++i)
      points->SetPoint(static_cast<vtkIdType>(i), object->surface.vertices[i].data());
    points->Modified();
    polydata->Modified();
    view_.render();
  }
  previewed_.clear();
}

void DeformationPanel::hideEvent(QHideEvent* event) {
  stop_preview();
  OrganPanel::hideEvent(event);
}

}  // namespace viscera::studio
