#include "studio/ui/slice_views.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkImageSliceMapper.h>
#include <vtkInteractorStyleImage.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QSlider>
#include <algorithm>
#include <cmath>

#include "core/image/image_volume_io.h"

namespace viscera::studio {

const std::array<WindowLevelPreset, 3>& ct_window_presets() {
  static const std::array<WindowLevelPreset, 3> presets = {{
      {"CT soft tissue", 400.0, 40.0},
      {"CT bone", 2000.0, 400.0},
      {"CT lung", 1500.0, -600.0},
  }};
  return presets;
}

namespace {

constexpr const char* kViewNames[3] = {"Sagittal", "Coronal", "Axial"};

vtkSmartPointer<vtkImageSlice> make_slice(int axis, vtkImageProperty* property) {
  auto mapper = vtkSmartPointer<vtkImageSliceMapper>::New();
  mapper->SetOrientation(axis);
  auto slice = vtkSmartPointer<vtkImageSlice>::New();
  slice->SetMapper(mapper);
  slice->SetProperty(property);
  return slice;
}

}  // namespace

SliceViews::SliceViews(QWidget* parent) : QWidget(parent) {
  property_ = vtkSmartPointer<vtkImageProperty>::New();
  property_->SetInterpolationTypeToLinear();
  auto* layout = new QGridLayout(this);
  for (int axis = 0; axis < 3; ++axis) {
    auto* view = new QVTKOpenGLNativeWidget(this);
    auto window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
    view->setRenderWindow(window);
    view->setMinimumSize(160, 160);
    renderers_[axis] = vtkSmartPointer<vtkRenderer>::New();
    renderers_[axis]->SetBackground(0.0, 0.0, 0.0);
    window->AddRenderer(renderers_[axis]);
    auto style = vtkSmartPointer<vtkInteractorStyleImage>::New();
    window->GetInteractor()->SetInteractorStyle(style);
    slices_[axis] = make_slice(axis, property_);
    planes_3d_[axis] = make_slice(axis, property_);
    renderers_[axis]->AddViewProp(slices_[axis]);
    views_[axis] = view;
    view->installEventFilter(this);

    auto* slider = new QSlider(Qt::Horizontal, this);
    slider->setEnabled(false);
    sliders_[axis] = slider;
    connect(slider, &QSlider::valueChanged, this, [this, axis](int value) {
      if (!updating_) set_slice(axis, value);
    });
    layout->addWidget(new QLabel(tr(kViewNames[axis]), this), 0, axis);
    layout->addWidget(view, 1, axis);
    layout->addWidget(slider, 2, axis);
  }
  auto* controls = new QHBoxLayout;
  auto* presets = new QComboBox(this);
  presets->addItem(tr("Full range"));
  for (const auto& preset : ct_window_presets())
    presets->addItem(tr(preset.name));
  window_box_ = new QDoubleSpinBox(this);
  level_box_ = new QDoubleSpinBox(this);
  window_box_->setRange(1e-6, 1e9);
  level_box_->setRange(-1e9, 1e9);
  controls->addWidget(new QLabel(tr("Preset"), this));
  controls->addWidget(presets);
  controls->addWidget(new QLabel(tr("Window"), this));
  controls->addWidget(window_box_);
  controls->addWidget(new QLabel(tr("Level"), this));
  controls->addWidget(level_box_);
  controls->addStretch(1);
  layout->addLayout(controls, 3, 0, 1, 3);

  const auto apply_boxes = [this] {
    if (!updating_) set_window_level(window_box_->value(), level_box_->value());
  };
  connect(window_box_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, apply_boxes);
  connect(level_box_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, apply_boxes);
  connect(presets, qOverload<int>(&QComboBox::activated), this, [this](int index) {
    if (image_ == nullptr) return;
    if (index == 0) {
      double range[2];
      image_->GetScalarRange(range);
      set_window_level(std::max(range[1] - range[0], 1e-6), 0.5 * (range[0] + range[1]));
    } else {
      const auto& preset = ct_window_presets()[static_cast<std::size_t>(index - 1)];
      set_window_level(preset.window, preset.level);
    }
  });
}

void SliceViews::set_volume(const core::ImageVolume& volume) {
  // The image keeps index geometry (spacing only); origin and direction go into the slices'
  // user matrix, so the planes sit in world space whatever the renderer makes of directions.
  core::ImageVolume local = volume;
  local.origin = core::Vec3::Zero();
  local.direction = core::Mat3::Identity();
  image_ = vtkSmartPointer<vtkImageData>::New();
  core::volume_to_image_data(local, *image_);
  dims_ = volume.dims;
  matrix_ = vtkSmartPointer<vtkMatrix4x4>::New();
  vtkMatrix4x4* matrix = matrix_;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      matrix->SetElement(r, c, volume.direction(r, c));
    matrix->SetElement(r, 3, volume.origin[r]);
  }
  for (int axis = 0; axis < 3; ++axis) {
    for (auto* slice : {slices_[axis].GetPointer(), planes_3d_[axis].GetPointer()}) {
      slice->GetMapper()->SetInputData(image_);
      slice->SetUserMatrix(matrix);
    }
    updating_ = true;
    sliders_[axis]->setRange(0, std::max(0, dims_[axis] - 1));
    sliders_[axis]->setEnabled(true);
    updating_ = false;
    set_slice(axis, dims_[axis] / 2);
  }
  double range[2];
  image_->GetScalarRange(range);
  set_window_level(std::max(range[1] - range[0], 1e-6), 0.5 * (range[0] + range[1]));
  for (int axis = 0; axis < 3; ++axis) {
    vtkRenderer* renderer = renderers_[axis];
    renderer->ResetCamera();
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    // Look along the slice normal; sagittal and coronal with the volume's +z up.
    const double* focal = camera->GetFocalPoint();
    const double distance = camera->GetDistance();
    double normal[3] = {0.0, 0.0, 0.0};
    normal[axis] = axis == 2 ? 1.0 : (axis == 0 ? 1.0 : -1.0);
    const double local_normal[4] = {normal[0], normal[1], normal[2], 0.0};
    double world_normal[4];
    matrix->MultiplyPoint(local_normal, world_normal);
    camera->SetPosition(focal[0] + distance * world_normal[0],
                        focal[1] + distance * world_normal[1],
                        focal[2] + distance * world_normal[2]);
    const core::Vec3 up = axis == 2 ? volume.direction.col(1) : volume.direction.col(2);
    camera->SetViewUp(up.x(), up.y(), up.z());
    renderer->ResetCamera();
    // Fill the view with the slice: half its larger in-plane extent, plus a margin.
    double extent = 0.0;
    for (int other = 0; other < 3; ++other) {
      if (other != axis) extent = std::max(extent, (dims_[other] - 1) * volume.spacing[other]);
    }
    camera->SetParallelScale(0.55 * std::max(extent, 1e-9));
  }
  render_all();
}

void SliceViews::set_slice(int axis, int index) {
  if (image_ == nullptr || axis < 0 || axis > 2) return;
  index = std::clamp(index, 0, std::max(0, dims_[axis] - 1));
  for (auto* slice : {slices_[axis].GetPointer(), planes_3d_[axis].GetPointer()}) {
    static_cast<vtkImageSliceMapper*>(slice->GetMapper())->SetSliceNumber(index);
  }
  updating_ = true;
  sliders_[axis]->setValue(index);
  updating_ = false;
  render_all();
}

int SliceViews::slice(int axis) const {
  return static_cast<vtkImageSliceMapper*>(slices_[axis]->GetMapper())->GetSliceNumber();
}

void SliceViews::set_window_level(double window_width, double level_value) {
  property_->SetColorWindow(window_width);
  property_->SetColorLevel(level_value);
  updating_ = true;
  window_box_->setValue(window_width);
  level_box_->setValue(level_value);
  updating_ = false;
  render_all();
}

double SliceViews::window() const {
  return property_->GetColorWindow();
}
double SliceViews::level() const {
  return property_->GetColorLevel();
}

QImage SliceViews::grab_view(int axis) {
  views_[axis]->renderWindow()->Render();
  return views_[axis]->grabFramebuffer();
}

std::optional<core::Vec3> SliceViews::world_at(int axis, const QPoint& position) const {
  if (image_ == nullptr || axis < 0 || axis > 2) return std::nullopt;
  QVTKOpenGLNativeWidget* view = views_[axis];
  vtkRenderer* renderer = renderers_[axis];
  const double ratio = view->devicePixelRatioF();
  const int* size = view->renderWindow()->GetSize();
  const double x = position.x() * ratio;
  const double y = size[1] - 1 - position.y() * ratio;  // VTK's display origin is bottom-left
  // The pick ray through the pixel, intersected with the slice plane in the world.
  core::Vec3 ends[2];
  for (int e = 0; e < 2; ++e) {
    renderer->SetDisplayPoint(x, y, e);
    renderer->DisplayToWorld();
    const double* w = renderer->GetWorldPoint();
    ends[e] = core::Vec3(w[0], w[1], w[2]) / (w[3] != 0.0 ? w[3] : 1.0);
  }
  double local[4] = {0.0, 0.0, 0.0, 1.0};
  local[axis] = slice(axis) * image_->GetSpacing()[axis];
  double on_plane[4];
  matrix_->MultiplyPoint(local, on_plane);
  const core::Vec3 normal(matrix_->GetElement(0, axis), matrix_->GetElement(1, axis),
                          matrix_->GetElement(2, axis));
  const core::Vec3 ray = ends[1] - ends[0];
  const double along = normal.dot(ray);
  if (std::abs(along) < 1e-15) return std::nullopt;
  const double t = normal.dot(core::Vec3(on_plane[0], on_plane[1], on_plane[2]) - ends[0]) / along;
  return core::Vec3(ends[0] + t * ray);
}

QPoint SliceViews::position_of(int axis, const core::Vec3& point) const {
  QVTKOpenGLNativeWidget* view = views_[axis];
  vtkRenderer* renderer = renderers_[axis];
  renderer->SetWorldPoint(point.x(), point.y(), point.z(), 1.0);
  renderer->WorldToDisplay();
  const double* d = renderer->GetDisplayPoint();
  const double ratio = view->devicePixelRatioF();
  const int* size = view->renderWindow()->GetSize();
  return {static_cast<int>(std::lround(d[0] / ratio)),
          static_cast<int>(std::lround((size[1] - 1 - d[1]) / ratio))};
}

bool SliceViews::eventFilter(QObject* watched, QEvent* event) {
  const auto found = std::find(views_.begin(), views_.end(), watched);
  if (found == views_.end()) return QWidget::eventFilter(watched, event);
  const int axis = static_cast<int>(found - views_.begin());
  if (event->type() == QEvent::MouseButtonPress) {
    press_position_ = static_cast<QMouseEvent*>(event)->pos();
  } else if (event->type() == QEvent::MouseButtonRelease) {
    auto* mouse = static_cast<QMouseEvent*>(event);
    if (mouse->button() == Qt::LeftButton &&
        (mouse->pos() - press_position_).manhattanLength() <= 3) {
      if (const auto point = world_at(axis, mouse->pos())) emit point_clicked(axis, *point);
    }
  }
  return false;  // VTK's interaction (window/level drag) sees the event too
}

void SliceViews::render_all() {
  for (auto* view : views_) {
    view->renderWindow()->Render();
    view->update();
  }
  emit changed();
}

}  // namespace viscera::studio
