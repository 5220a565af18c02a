#include "studio/document/add_model_command.h"

#include <algorithm>

#include "core/error.h"

namespace viscera::studio {

AddModelCommand::AddModelCommand(ScenarioDocument& document, ModelParts parts, const QString& label)
    : document_(document), parts_(std::move(parts)) {
  const core::Scenario& s = document.scenario();
  if (parts_.objects.empty()) throw core::UsageError("the model has no object to add");
  for (const auto& o : parts_.objects)
    if (s.find_object(o.id) != nullptr)
      throw core::UsageError("the scenario already has an object \"" + o.id + "\"");
  for (const auto& m : parts_.materials)
    if (s.materials.contains(m.id))
      throw core::UsageError("the scenario already has a material \"" + m.id + "\"");
  for (const auto& t : parts_.textures)
    if (s.textures.contains(t.id))
      throw core::UsageError("the scenario already has a texture \"" + t.id + "\"");
  setText(QObject::tr("Add %1").arg(label));
}

void AddModelCommand::redo() {
  core::Scenario& s = document_.edit_scenario();
  for (const auto& m : parts_.materials)
    s.materials[m.id] = m;
  for (const auto& t : parts_.textures)
    s.textures[t.id] = t;
  for (const auto& [path, bytes] : parts_.files)
    document_.edit_files()[path] = bytes;
  s.objects.insert(s.objects.end(), parts_.objects.begin(), parts_.objects.end());
  s.connections.insert(s.connections.end(), parts_.connections.begin(), parts_.connections.end());
  document_.notify_changed(ChangeKind::Everything);
}

void AddModelCommand::undo() {
  core::Scenario& s = document_.edit_scenario();
  const auto added = [&](const std::string& id) {
    return std::any_of(parts_.objects.begin(), parts_.objects.end(),
                       [&](const auto& o) { return o.id == id; });
  };
  std::erase_if(s.objects, [&](const auto& o) { return added(o.id); });
  std::erase_if(s.connections, [&](const auto& c) {
    return std::any_of(parts_.connections.begin(), parts_.connections.end(),
                       [&](const auto& p) { return p.id == c.id; });
  });
  for (const auto& m : parts_.materials)
    s.materials.erase(m.id);
  for (const auto& t : parts_.textures)
    s.textures.erase(t.id);
  for (const auto& [path, bytes] : parts_.files)
    document_.edit_files().erase(path);
  document_.notify_changed(ChangeKind::Everything);
}

}  // namespace viscera::studio
