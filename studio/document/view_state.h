#pragma once
/// What the studio shows of a document (issue 23 §2, §4): which objects and vessel trees are
/// hidden and each object's opacity. It is part of the document — saved in the package as
/// kViewStateFile beside the texture maps, changed only through SetViewStateCommand — so the
/// scene tree, the 3D view and the saved package read one model and agree after every command,
/// undo, redo and reopen. The simulator ignores the file.

#include <QUndoCommand>
#include <map>
#include <set>
#include <string>

#include "studio/document/scenario_document.h"

namespace viscera::studio {

/// Package path of the view state.
inline constexpr const char* kViewStateFile = "studio/view.json";

/// Visibility key of a vessel tree (objects use their own id).
std::string vessel_tree_key(const std::string& tree_id);

struct ViewState {
  std::set<std::string> hidden;           ///< object ids and vessel_tree_key()s not drawn
  std::map<std::string, double> opacity;  ///< object id → opacity in (0, 1); absent: opaque

  bool visible(const std::string& key) const { return !hidden.contains(key); }
  /// 1 for an object without an entry.
  double opacity_of(const std::string& id) const;
  bool operator==(const ViewState&) const = default;
};

/// The view state kept in `files` (empty: everything shown, opaque). Throws core::InputError
/// naming kViewStateFile and the place when the file is not the expected JSON.
ViewState view_state_of(const PackageFiles& files);
/// Writes `state` into `files` as kViewStateFile (removes it when nothing is hidden or
/// translucent, so untouched packages stay as they were).
void store_view_state(PackageFiles& files, const ViewState& state);

/// Replaces the document's view state; undoable. Successive opacity edits of one object merge
/// into one step (a slider drag).
class SetViewStateCommand : public QUndoCommand {
 public:
  /// `merge_key` non-empty: consecutive commands with the same key merge.
  SetViewStateCommand(ScenarioDocument& document, ViewState state, const QString& text,
                      std::string merge_key = {});
  void redo() override;
  void undo() override;
  int id() const override { return merge_key_.empty() ? -1 : 0x5643; }
  bool mergeWith(const QUndoCommand* other) override;

 private:
  void apply(const ViewState& state);

  ScenarioDocument& document_;
  ViewState before_, after_;
  std::string merge_key_;
};

}  // namespace viscera::studio
