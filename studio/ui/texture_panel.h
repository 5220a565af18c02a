#pragma once
/// The texture panel (issue 9 §5; seed 001 §3.3, seed 000 §7): a preset of
/// data/textures/presets.json, a seed and a size, a live preview of the synthesised albedo
/// (textures::synthesize_texture at preview size), and "Apply", which bakes the texture onto the
/// selected object as `viscera bake --preset --object` does and pushes one undoable command.

#include <QImage>

#include "studio/document/organ_authoring.h"
#include "studio/ui/organ_panel.h"

class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTimer;

namespace viscera::studio {

class TexturePanel : public OrganPanel {
  Q_OBJECT

 public:
  explicit TexturePanel(ScenarioDocument& document, QWidget* parent = nullptr);

  /// Bakes `request` onto the shown object off the UI thread and applies it as one command.
  /// Returns false (after failed()) without an object, for a bad preset or size, or when
  /// cancelled.
  bool apply_texture(const TextureRequest& request);
  /// Applies what the editors show.
  bool apply();
  /// The request the editors show.
  TextureRequest request() const;
  /// Shows `request` in the editors (the preview follows).
  void set_request(const TextureRequest& request);
  /// The albedo preview of the editors' preset and seed (at most 256 × 256 pixels, RGB).
  QImage preview() const { return preview_; }
  /// Synthesises the preview now instead of after the editors settle.
  void update_preview();

  /// Largest preview side in pixels.
  static constexpr int kPreviewSize = 256;

 private:
  void refresh() override;

  QLabel* object_label_ = nullptr;
  QComboBox* preset_ = nullptr;
  QSpinBox* seed_ = nullptr;
  QComboBox* size_ = nullptr;
  QLabel* preview_label_ = nullptr;
  QPushButton* apply_ = nullptr;
  QTimer* preview_timer_ = nullptr;
  QImage preview_;
};

}  // namespace viscera::studio
