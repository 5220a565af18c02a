#include "studio/ui/segmentation_panel.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>
#include <cctype>
#include <cmath>

#include "core/error.h"
#include "core/image/image_volume_io.h"
#include "core/materials/shipped_materials.h"
#include "importers/volume/volume_reader.h"
#include "studio/document/document_commands.h"
#include "studio/document/primitive_objects.h"
#include "studio/ui/background_task.h"

namespace viscera::studio {
namespace {

QDoubleSpinBox* number_box(QWidget* parent, double low, double high, double value, int decimals) {
  auto* box = new QDoubleSpinBox(parent);
  box->setRange(low, high);
  box->setDecimals(decimals);
  box->setValue(value);
  return box;
}

QSpinBox* count_box(QWidget* parent, int low, int high, int value) {
  auto* box = new QSpinBox(parent);
  box->setRange(low, high);
  box->setValue(value);
  return box;
}

/// An object id from a name: lower case, runs of other characters as one '-'.
std::string id_from_name(const std::string& name) {
  std::string id;
  for (const char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      id += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else if (!id.empty() && id.back() != '-') {
      id += '-';
    }
  }
  while (!id.empty() && id.back() == '-')
    id.pop_back();
  return id.empty() ? "organ" : id;
}

/// A label map from a volume file whose voxels are whole numbers 0…65535.
core::LabelMap labels_from_volume(const core::ImageVolume& volume, const std::string& what) {
  core::LabelMap labels;
  labels.image = volume;
  labels.image.scalar_type = core::ScalarType::UInt16;
  labels.image.allocate();
  for (std::size_t v = 0; v < volume.voxel_count(); ++v) {
    const double value = volume.value(v);
    if (value < 0.0 || value > 65535.0 || value != std::floor(value)) {
      throw core::InputError("voxel " + std::to_string(v) + " holds " + std::to_string(value) +
                                 ", not a label 0…65535",
                             {what, "", ""});
    }
    labels.set_label(v, static_cast<std::uint16_t>(value));
  }
  return labels;
}

/// One segmentation step (threshold, growing, opening, …): the label maps before and after.
/// The first redo is the step the panel already made.
class LabelStepCommand : public QUndoCommand {
 public:
  LabelStepCommand(std::function<void(const core::LabelMap&)> apply, core::LabelMap before,
                   core::LabelMap after, const QString& text)
      : apply_(std::move(apply)), before_(std::move(before)), after_(std::move(after)) {
    setText(text);
  }
  void redo() override {
    if (first_) {
      first_ = false;
      return;
    }
    apply_(after_);
  }
  void undo() override { apply_(before_); }

 private:
  std::function<void(const core::LabelMap&)> apply_;
  core::LabelMap before_, after_;
  bool first_ = true;
};

}  // namespace

SegmentationPanel::SegmentationPanel(ScenarioDocument& document, QWidget* parent)
    : QWidget(parent), document_(document) {
  auto* layout = new QVBoxLayout(this);
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  layout->addWidget(status_);
  auto* steps = new QHBoxLayout;
  QAction* undo = history_.createUndoAction(this, tr("Undo step"));
  QAction* redo = history_.createRedoAction(this, tr("Redo step"));
  for (QAction* action : {undo, redo}) {
    auto* button = new QToolButton(this);
    button->setDefaultAction(action);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    steps->addWidget(button);
  }
  steps->addStretch(1);
  layout->addLayout(steps);

  auto* threshold = new QGroupBox(tr("Threshold"), this);
  auto* threshold_form = new QFormLayout(threshold);
  lower_ = number_box(threshold, -1e6, 1e6, 100.0, 2);
  upper_ = number_box(threshold, -1e6, 1e6, 3000.0, 2);
  threshold_label_ = count_box(threshold, 1, 65535, 1);
  auto* apply_threshold = new QPushButton(tr("Apply threshold"), threshold);
  threshold_form->addRow(tr("Lower"), lower_);
  threshold_form->addRow(tr("Upper"), upper_);
  threshold_form->addRow(tr("Label"), threshold_label_);
  threshold_form->addRow(apply_threshold);
  layout->addWidget(threshold);
  connect(apply_threshold, &QPushButton::clicked, this, [this] {
    segment_threshold(lower_->value(), upper_->value(), threshold_label_->value());
  });

  auto* grow = new QGroupBox(tr("Region growing"), this);
  auto* grow_form = new QFormLayout(grow);
  seed_label_ = new QLabel(tr("Click a slice view to place the seed"), grow);
  seed_label_->setWordWrap(true);
  tolerance_ = number_box(grow, 0.0, 1e6, 0.0, 2);
  grow_label_ = count_box(grow, 1, 65535, 1);
  auto* grow_button = new QPushButton(tr("Grow from seed"), grow);
  grow_form->addRow(seed_label_);
  grow_form->addRow(tr("Tolerance"), tolerance_);
  grow_form->addRow(tr("Label"), grow_label_);
  grow_form->addRow(grow_button);
  layout->addWidget(grow);
  connect(grow_button, &QPushButton::clicked, this, [this] { grow_from_seed(); });

  auto* clean = new QGroupBox(tr("Clean up"), this);
  auto* clean_layout = new QGridLayout(clean);
  radius_ = count_box(clean, 1, 20, 1);
  radius_->setSuffix(tr(" voxels"));
  auto* open_button = new QPushButton(tr("Open"), clean);
  auto* close_button = new QPushButton(tr("Close"), clean);
  auto* largest_button = new QPushButton(tr("Keep largest"), clean);
  clean_layout->addWidget(new QLabel(tr("Radius"), clean), 0, 0);
  clean_layout->addWidget(radius_, 0, 1);
  clean_layout->addWidget(open_button, 1, 0);
  clean_layout->addWidget(close_button, 1, 1);
  clean_layout->addWidget(largest_button, 2, 0, 1, 2);
  layout->addWidget(clean);
  connect(open_button, &QPushButton::clicked, this, [this] { open_labels(radius_->value()); });
  connect(close_button, &QPushButton::clicked, this, [this] { close_labels(radius_->value()); });
  connect(largest_button, &QPushButton::clicked, this, [this] { keep_largest(); });

  auto* mesh = new QGroupBox(tr("Mesh organ"), this);
  auto* mesh_form = new QFormLayout(mesh);
  mesh_label_ = count_box(mesh, 1, 65535, 1);
  mesh_label_->setToolTip(tr("Follows the label last thresholded or grown"));
  cell_size_mm_ = number_box(mesh, 0.0, 500.0, 0.0, 1);
  cell_size_mm_->setSpecialValueText(tr("from the tet count"));
  cell_size_mm_->setSuffix(tr(" mm"));
  target_tets_ = count_box(mesh, 100, 5'000'000, 5000);
  target_tets_->setToolTip(
      tr("Tetrahedra wanted; the cell size is searched until the count is "
         "within 10 %% (a few Mesh_3 passes)"));
  triangles_ = count_box(mesh, 100, 5'000'000, 4000);
  name_ = new QLineEdit(mesh);
  name_->setPlaceholderText(tr("Organ"));
  auto* mesh_button = new QPushButton(tr("Mesh organ"), mesh);
  mesh_form->addRow(tr("Label"), mesh_label_);
  mesh_form->addRow(tr("Cell size"), cell_size_mm_);
  mesh_form->addRow(tr("Tets"), target_tets_);
  mesh_form->addRow(tr("Surface triangles"), triangles_);
  mesh_form->addRow(tr("Name"), name_);
  mesh_form->addRow(mesh_button);
  layout->addWidget(mesh);
  connect(mesh_button, &QPushButton::clicked, this, [this] { mesh_segmentation(mesh_request()); });

  layout->addStretch(1);
  update_status();
}

void SegmentationPanel::set_volume(const core::ImageVolume& volume) {
  segmentation_.set_volume(volume);
  history_.clear();
  seed_.reset();
  seed_label_->setText(tr("Click a slice view to place the seed"));
  update_status();
  emit labels_changed();
}

void SegmentationPanel::report(const QString& message) {
  if (error_handler_) error_handler_(message);
}

bool SegmentationPanel::run(const QString& title,
                            const std::function<void(core::Progress&)>& work) {
  const std::exception_ptr error = run_in_background(this, title, work);
  if (!error) return true;
  try {
    std::rethrow_exception(error);
  } catch (const core::CancelledError&) {
  } catch (const std::exception& e) {
    report(QString::fromUtf8(e.what()));
  }
  return false;
}

bool SegmentationPanel::edit(const QString& title, const std::function<void()>& change) {
  // Every Segmentation edit computes its result before it changes the labels, so a failed one
  // leaves them as they were; the modal progress dialog keeps the user out meanwhile.
  core::LabelMap before = segmentation_.labels();
  if (!run(title, [&](core::Progress&) { change(); })) return false;
  if (!(segmentation_.labels() == before)) {
    history_.push(new LabelStepCommand(
        [this](const core::LabelMap& labels) {
          segmentation_.set_labels(labels, "the segmentation history");
          update_status();
          emit labels_changed();
        },
        std::move(before), segmentation_.labels(), title));
  }
  update_status();
  emit labels_changed();
  return true;
}

bool SegmentationPanel::undo_step() {
  if (!history_.canUndo()) return false;
  history_.undo();
  return true;
}

bool SegmentationPanel::redo_step() {
  if (!history_.canRedo()) return false;
  history_.redo();
  return true;
}

bool SegmentationPanel::segment_threshold(double lower, double upper, int label) {
  if (!edit(tr("Thresholding"),
            [&] { segmentation_.threshold(lower, upper, static_cast<std::uint16_t>(label)); }))
    return false;
  mesh_label_->setValue(label);  // Mesh organ meshes the label just made
  return true;
}

void SegmentationPanel::set_seed(const core::Vec3& point) {
  seed_ = point;
  const core::Vec3 mm = 1000.0 * point;
  seed_label_->setText(tr("Seed at (%1, %2, %3) mm")
                           .arg(mm.x(), 0, 'f', 1)
                           .arg(mm.y(), 0, 'f', 1)
                           .arg(mm.z(), 0, 'f', 1));
}

bool SegmentationPanel::grow_region_at(const core::Vec3& point, double tolerance, int label) {
  if (!edit(tr("Growing a region"),
            [&] { segmentation_.grow_at(point, tolerance, static_cast<std::uint16_t>(label)); }))
    return false;
  mesh_label_->setValue(label);  // Mesh organ meshes the label just grown
  return true;
}

bool SegmentationPanel::grow_from_seed() {
  if (!seed_) {
    report(tr("Click a slice view to place the seed of the region first."));
    return false;
  }
  return grow_region_at(*seed_, tolerance_->value(), grow_label_->value());
}

bool SegmentationPanel::open_labels(int radius) {
  return edit(tr("Opening"), [&] { segmentation_.open(radius); });
}

bool SegmentationPanel::close_labels(int radius) {
  return edit(tr("Closing"), [&] { segmentation_.close(radius); });
}

bool SegmentationPanel::keep_largest() {
  return edit(tr("Keeping the largest component"), [&] { segmentation_.keep_largest(); });
}

bool SegmentationPanel::load_label_map(const std::filesystem::path& path) {
  return edit(tr("Reading %1").arg(QString::fromStdString(path.filename().string())), [&] {
    if (!segmentation_.has_volume()) {
      throw core::UsageError("open an image volume before its label map");
    }
    core::LabelMap labels =
        path.extension() == ".vti"
            ? core::read_label_map_vti(path)
            : labels_from_volume(importers::read_volume(path).volume, path.string());
    segmentation_.set_labels(std::move(labels), path.string());
  });
}

OrganMeshRequest SegmentationPanel::mesh_request() const {
  OrganMeshRequest request;
  request.label = static_cast<std::uint16_t>(mesh_label_->value());
  request.cell_size = cell_size_mm_->value() / 1000.0;
  request.target_tets = static_cast<std::size_t>(target_tets_->value());
  request.triangles = static_cast<std::size_t>(triangles_->value());
  request.name = name_->text().trimmed().toStdString();
  return request;
}

QString SegmentationPanel::mesh_segmentation(const OrganMeshRequest& request) {
  const auto& scenario = document_.scenario();
  core::Material material;
  try {
    material = scenario.materials.contains(request.material)
                   ? scenario.materials.at(request.material)
                   : core::shipped_material(request.material);
  } catch (const std::exception& e) {
    report(QString::fromUtf8(e.what()));
    return {};
  }
  const core::LabelMap labels = segmentation_.labels();
  core::SceneObject object;
  if (!run(tr("Meshing label %1").arg(request.label), [&](core::Progress& progress) {
        if (!segmentation_.has_volume()) {
          throw core::UsageError("open an image volume and segment it before meshing");
        }
        object = build_organ_object(labels, request, "organ", material, progress);
      })) {
    return {};
  }
  object.id = unique_object_id(document_.scenario(), id_from_name(object.name));
  const QString id = QString::fromStdString(object.id);
  try {
    document_.undo_stack()->push(new AddObjectCommand(document_, std::move(object), material));
  } catch (const std::exception& e) {
    report(QString::fromUtf8(e.what()));
    return {};
  }
  emit organ_added(id);
  return id;
}

void SegmentationPanel::update_status() {
  if (!segmentation_.has_volume()) {
    status_->setText(tr("Open an image volume to segment it."));
    setEnabled(false);
    return;
  }
  setEnabled(true);
  const auto& volume = segmentation_.volume();
  QString text = tr("%1 × %2 × %3 voxels of %4 × %5 × %6 mm")
                     .arg(volume.dims[0])
                     .arg(volume.dims[1])
                     .arg(volume.dims[2])
                     .arg(1000.0 * volume.spacing.x(), 0, 'g', 4)
                     .arg(1000.0 * volume.spacing.y(), 0, 'g', 4)
                     .arg(1000.0 * volume.spacing.z(), 0, 'g', 4);
  std::map<std::uint16_t, std::size_t> counts;
  const auto& labels = segmentation_.labels();
  for (std::size_t v = 0; v < labels.image.voxel_count(); ++v)
    if (const auto l = labels.label(v); l != 0) ++counts[l];
  const double voxel_ml = volume.spacing.prod() * 1e6;
  for (const auto& [label, count] : counts) {
    text += tr("\nLabel %1: %2 voxels, %3 ml")
                .arg(label)
                .arg(count)
                .arg(static_cast<double>(count) * voxel_ml, 0, 'f', 1);
  }
  status_->setText(text);
}

}  // namespace viscera::studio
