#pragma once
/// Adds a library model to the document as one undoable step (issue 9 §7): its objects,
/// the materials and textures new to the scenario, the texture maps and the connections between
/// the added objects. Undo takes all of them out again.

#include <QUndoCommand>

#include "studio/document/asset_payloads.h"
#include "studio/document/scenario_document.h"

namespace viscera::studio {

class AddModelCommand : public QUndoCommand {
 public:
  /// Throws core::UsageError when an id of `parts` is already taken in the document (parts
  /// from model_parts_from_asset never are) or `parts` has no object.
  AddModelCommand(ScenarioDocument& document, ModelParts parts, const QString& label);
  void redo() override;
  void undo() override;

 private:
  ScenarioDocument& document_;
  ModelParts parts_;
};

}  // namespace viscera::studio
