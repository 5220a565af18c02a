#include "studio/ui/display_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QVBoxLayout>
#include <cmath>

#include "studio/document/view_state.h"
#include "studio/ui/scene_view.h"

namespace viscera::studio {

DisplayPanel::DisplayPanel(ScenarioDocument& document, SceneView& view, QWidget* parent)
    : QWidget(parent), document_(document), view_(view) {
  auto* layout = new QVBoxLayout(this);
  object_label_ = new QLabel(this);
  object_label_->setWordWrap(true);
  layout->addWidget(object_label_);
  auto* form = new QFormLayout;
  opacity_ = new QSlider(Qt::Horizontal, this);
  opacity_->setRange(5, 100);
  opacity_->setToolTip(tr("Opacity of the selected object in %: lower it to see inside"));
  form->addRow(tr("Opacity"), opacity_);
  layout->addLayout(form);
  connect(opacity_, &QSlider::valueChanged, this, [this](int percent) {
    if (updating_ || object_id_.isEmpty()) return;
    emit opacity_requested(object_id_, percent / 100.0);
  });

  clip_box_ = new QGroupBox(tr("Clipping plane"), this);
  clip_box_->setCheckable(true);
  clip_box_->setChecked(false);
  clip_box_->setToolTip(tr("Cuts every object open along a plane to see inside the organs"));
  auto* clip_form = new QFormLayout(clip_box_);
  clip_axis_ = new QComboBox(clip_box_);
  clip_axis_->addItem(tr("Sagittal (left–right)"));
  clip_axis_->addItem(tr("Coronal (front–back)"));
  clip_axis_->addItem(tr("Axial (along the body)"));
  clip_axis_->setCurrentIndex(1);
  clip_form->addRow(tr("Plane"), clip_axis_);
  clip_position_ = new QSlider(Qt::Horizontal, clip_box_);
  clip_position_->setRange(0, 100);
  clip_position_->setValue(50);
  clip_position_->setToolTip(tr("Where the plane cuts, in % of the scene's extent"));
  clip_form->addRow(tr("Position"), clip_position_);
  clip_flip_ = new QCheckBox(tr("Keep the other side"), clip_box_);
  clip_form->addRow(clip_flip_);
  follow_slices_ = new QCheckBox(tr("With the slices"), clip_box_);
  follow_slices_->setToolTip(
      tr("The plane moves with the image volume's slice of its orientation"));
  clip_form->addRow(follow_slices_);
  layout->addWidget(clip_box_);
  connect(clip_box_, &QGroupBox::toggled, this, [this] { update_clip(); });
  connect(clip_axis_, qOverload<int>(&QComboBox::currentIndexChanged), this,
          [this] { update_clip(); });
  connect(clip_position_, &QSlider::valueChanged, this, [this] { update_clip(); });
  connect(clip_flip_, &QCheckBox::toggled, this, [this] { update_clip(); });

  auto* camera = new QGroupBox(tr("Camera"), this);
  auto* buttons = new QVBoxLayout(camera);
  auto* whole = new QPushButton(tr("Whole scene"), camera);
  connect(whole, &QPushButton::clicked, this, [this] {
    view_.reset_camera();
    view_.render();
  });
  buttons->addWidget(whole);
  auto* cervix = new QPushButton(tr("From the cervix into the cavity"), camera);
  cervix->setToolTip(tr("A hysteroscope's view from the internal os towards the fundus"));
  connect(cervix, &QPushButton::clicked, this, [this] { view_from_cervix(); });
  buttons->addWidget(cervix);
  layout->addWidget(camera);
  layout->addStretch(1);
  refresh();
}

void DisplayPanel::show_object(const QString& id) {
  object_id_ = id;
  refresh();
}

void DisplayPanel::refresh() {
  const core::SceneObject* object =
      object_id_.isEmpty() ? nullptr : document_.scenario().find_object(object_id_.toStdString());
  if (object == nullptr) object_id_.clear();
  updating_ = true;
  opacity_->setEnabled(object != nullptr);
  if (object == nullptr) {
    object_label_->setText(tr("Select an object to change its opacity."));
    opacity_->setValue(100);
  } else {
    object_label_->setText(
        tr("<b>%1</b>")
            .arg(QString::fromStdString(object->name.empty() ? object->id : object->name)));
    const ViewState state = view_state_of(document_.files());
    opacity_->setValue(static_cast<int>(std::lround(100.0 * state.opacity_of(object->id))));
  }
  updating_ = false;
}

void DisplayPanel::set_clipping(bool on, int axis, double fraction, bool keep_low) {
  updating_ = true;
  clip_axis_->setCurrentIndex(axis);
  clip_position_->setValue(static_cast<int>(std::lround(100.0 * fraction)));
  clip_flip_->setChecked(keep_low);
  updating_ = false;
  clip_box_->setChecked(on);
  update_clip();
}

void DisplayPanel::update_clip() {
  if (updating_) return;
  if (follows_slices() && clip_box_->isChecked()) {
    emit slice_plane_requested();
    return;
  }
  view_.set_clip_across(clip_axis_->currentIndex(), clip_position_->value() / 100.0,
                        clip_flip_->isChecked());
  view_.set_clipping(clip_box_->isChecked());
}

bool DisplayPanel::follows_slices() const {
  return follow_slices_->isChecked();
}

void DisplayPanel::set_follows_slices(bool on) {
  follow_slices_->setChecked(on);
}

int DisplayPanel::clip_axis() const {
  return clip_axis_->currentIndex();
}

void DisplayPanel::follow_slice(const core::Vec3& on_slice) {
  if (!follows_slices() || !clip_box_->isChecked()) return;
  core::Vec3 normal = core::Vec3::Zero();
  normal[clip_axis()] = clip_flip_->isChecked() ? -1.0 : 1.0;
  view_.set_clip_plane(on_slice, normal);
  view_.set_clipping(true);
}

bool DisplayPanel::view_from_cervix() {
  if (view_.view_from_cervix(document_.scenario())) return true;
  emit failed(tr("The scenario has no cervix landmarks (\"cervix-internal-os\") to look from."));
  return false;
}

}  // namespace viscera::studio
