#include "studio/ui/texture_panel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>

#include "studio/document/organ_commands.h"
#include "textures/texture_preset.h"
#include "textures/texture_synthesis.h"

namespace viscera::studio {

TexturePanel::TexturePanel(ScenarioDocument& document, QWidget* parent)
    : OrganPanel(document, parent) {
  auto* layout = new QVBoxLayout(this);
  object_label_ = new QLabel(this);
  layout->addWidget(object_label_);
  auto* form = new QFormLayout;
  preset_ = new QComboBox(this);
  for (const auto& name : textures::texture_preset_names()) {
    preset_->addItem(QString::fromStdString(name), QString::fromStdString(name));
    preset_->setItemData(preset_->count() - 1,
                         QString::fromStdString(textures::find_texture_preset(name).description),
                         Qt::ToolTipRole);
  }
  form->addRow(tr("Preset"), preset_);
  seed_ = new QSpinBox(this);
  seed_->setRange(0, 1'000'000'000);
  seed_->setValue(1);
  form->addRow(tr("Seed"), seed_);
  size_ = new QComboBox(this);
  for (const int side : {128, 256, 512, 1024, 2048})
    size_->addItem(tr("%1 × %1 px").arg(side), side);
  size_->setCurrentIndex(size_->findData(512));
  form->addRow(tr("Map size"), size_);
  layout->addLayout(form);
  preview_label_ = new QLabel(this);
  preview_label_->setFixedSize(kPreviewSize, kPreviewSize);
  preview_label_->setAlignment(Qt::AlignCenter);
  layout->addWidget(preview_label_, 0, Qt::AlignHCenter);
  apply_ = new QPushButton(tr("Apply to the selected object"), this);
  layout->addWidget(apply_);
  layout->addStretch(1);

  preview_timer_ = new QTimer(this);
  preview_timer_->setSingleShot(true);
  preview_timer_->setInterval(150);
  connect(preview_timer_, &QTimer::timeout, this, &TexturePanel::update_preview);
  const auto later = [this] { preview_timer_->start(); };
  connect(preset_, qOverload<int>(&QComboBox::currentIndexChanged), this, later);
  connect(seed_, qOverload<int>(&QSpinBox::valueChanged), this, later);
  connect(size_, qOverload<int>(&QComboBox::currentIndexChanged), this, later);
  connect(apply_, &QPushButton::clicked, this, [this] { apply(); });
  update_preview();
  refresh();
}

TextureRequest TexturePanel::request() const {
  TextureRequest r;
  r.preset = preset_->currentData().toString().toStdString();
  r.seed = static_cast<std::uint64_t>(seed_->value());
  r.width = r.height = size_->currentData().toInt();
  return r;
}

void TexturePanel::set_request(const TextureRequest& request) {
  preset_->setCurrentIndex(preset_->findData(QString::fromStdString(request.preset)));
  seed_->setValue(static_cast<int>(request.seed));
  const int size = size_->findData(request.width);
  if (size >= 0) size_->setCurrentIndex(size);
}

void TexturePanel::update_preview() {
  preview_timer_->stop();
  const TextureRequest r = request();
  if (r.preset.empty()) return;
  // The preview is the texture itself at a smaller size: the presets' lengths are in texture
  // widths, so the same tissue shows at every size.
  textures::TextureOptions options;
  options.seed = r.seed;
  options.width = options.height = std::min(kPreviewSize, r.width);
  options.normal_and_specular = false;
  const textures::TextureMaps maps =
      textures::synthesize_texture(textures::find_texture_preset(r.preset), options);
  const textures::Image8& albedo = maps.albedo;
  QImage image(albedo.width, albedo.height, QImage::Format_RGB888);
  for (int y = 0; y < albedo.height; ++y) {
    std::copy_n(albedo.pixels.data() + static_cast<std::size_t>(y) * albedo.width * 3,
                static_cast<std::size_t>(albedo.width) * 3, image.scanLine(y));
  }
  preview_ = image;
  preview_label_->setPixmap(QPixmap::fromImage(
      preview_.scaled(kPreviewSize, kPreviewSize, Qt::KeepAspectRatio, Qt::SmoothTransformation)));
}

void TexturePanel::refresh() {
  const core::SceneObject* object =
      object_id().isEmpty() ? nullptr : document_.scenario().find_object(object_id().toStdString());
  apply_->setEnabled(object != nullptr);
  object_label_->setText(object == nullptr
                             ? tr("Select an object to texture it.")
                             : tr("<b>%1</b> — texture %2")
                                   .arg(QString::fromStdString(object->name),
                                        object->texture.empty()
                                            ? tr("none")
                                            : QString::fromStdString(object->texture)));
}

bool TexturePanel::apply() {
  return apply_texture(request());
}

bool TexturePanel::apply_texture(const TextureRequest& request) {
  const std::string id = require_object();
  if (id.empty()) return false;
  TexturedObject textured;
  const core::Scenario& scenario = document_.scenario();
  if (!run(tr("Baking %1").arg(QString::fromStdString(request.preset)),
           [&](core::Progress& progress) {
             textured = bake_object_texture(scenario, id, request, progress);
           }))
    return false;
  return push([&] { return new ApplyTextureCommand(document_, std::move(textured)); });
}

}  // namespace viscera::studio
