#include "studio/document/view_state.h"

#include <nlohmann/json.hpp>

#include "core/error.h"

namespace viscera::studio {

std::string vessel_tree_key(const std::string& tree_id) {
  return "vessel-tree/" + tree_id;
}

double ViewState::opacity_of(const std::string& id) const {
  const auto it = opacity.find(id);
  return it == opacity.end() ? 1.0 : it->second;
}

ViewState view_state_of(const PackageFiles& files) {
  ViewState state;
  const auto file = files.find(kViewStateFile);
  if (file == files.end()) return state;
  const auto fail = [](const std::string& pointer, const std::string& what) {
    throw core::InputError(what, {kViewStateFile, pointer, ""});
  };
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(file->second);
  } catch (const nlohmann::json::parse_error& e) {
    fail("", std::string("not JSON: ") + e.what());
  }
  if (!json.is_object()) fail("", "the view state must be a JSON object");
  if (json.contains("hidden")) {
    if (!json["hidden"].is_array()) fail("/hidden", "\"hidden\" must be a list of ids");
    for (std::size_t i = 0; i < json["hidden"].size(); ++i) {
      if (!json["hidden"][i].is_string())
        fail("/hidden/" + std::to_string(i), "a hidden id must be a string");
      state.hidden.insert(json["hidden"][i].get<std::string>());
    }
  }
  if (json.contains("opacity")) {
    if (!json["opacity"].is_object()) fail("/opacity", "\"opacity\" must map ids to numbers");
    for (const auto& [id, value] : json["opacity"].items()) {
      if (!value.is_number() || value.get<double>() < 0.0 || value.get<double>() > 1.0)
        fail("/opacity/" + id, "an opacity must be a number in [0, 1]");
      if (value.get<double>() < 1.0) state.opacity[id] = value.get<double>();
    }
  }
  return state;
}

void store_view_state(PackageFiles& files, const ViewState& state) {
  if (state.hidden.empty() && state.opacity.empty()) {
    files.erase(kViewStateFile);
    return;
  }
  nlohmann::json json = {{"hidden", state.hidden}, {"opacity", nlohmann::json::object()}};
  for (const auto& [id, value] : state.opacity)
    json["opacity"][id] = value;
  files[kViewStateFile] = json.dump(2) + "\n";
}

SetViewStateCommand::SetViewStateCommand(ScenarioDocument& document, ViewState state,
                                         const QString& text, std::string merge_key)
    : document_(document),
      before_(view_state_of(document.files())),
      after_(std::move(state)),
      merge_key_(std::move(merge_key)) {
  setText(text);
}

void SetViewStateCommand::redo() {
  apply(after_);
}

void SetViewStateCommand::undo() {
  apply(before_);
}

bool SetViewStateCommand::mergeWith(const QUndoCommand* other) {
  const auto* next = dynamic_cast<const SetViewStateCommand*>(other);
  if (next == nullptr || next->merge_key_ != merge_key_) return false;
  after_ = next->after_;
  return true;
}

void SetViewStateCommand::apply(const ViewState& state) {
  store_view_state(document_.edit_files(), state);
  document_.notify_changed(ChangeKind::View);
}

}  // namespace viscera::studio
