#include "simulator/dynamics/body_model.h"

#include "core/error.h"

namespace viscera::sim {

void assign_layer_materials(BodyModel& model, const core::SceneObject& object,
                            const core::Material& base,
                            const std::map<std::string, core::Material>& materials) {
  model.materials = {base};
  model.tet_material.assign(model.mesh.tets.size(), 0);
  if (object.layer_materials.empty() || model.mesh.tet_labels.size() != model.mesh.tets.size())
    return;
  std::map<int, int> index_of_label;
  for (const auto& [label, id] : object.layer_materials) {
    const auto it = materials.find(id);
    if (it == materials.end())
      throw core::InputError(
          "unknown layer material id \"" + id + "\" for tet label " + std::to_string(label),
          {"", "", "object " + object.id});
    index_of_label[label] = static_cast<int>(model.materials.size());
    model.materials.push_back(it->second);
  }
  for (std::size_t t = 0; t < model.mesh.tets.size(); ++t) {
    const auto it = index_of_label.find(model.mesh.tet_labels[t]);
    if (it != index_of_label.end()) model.tet_material[t] = it->second;
  }
}

std::vector<double> node_distance_stiffness(const BodyModel& model,
                                            std::span<const core::Vec3> rest) {
  std::vector<double> stiffness(rest.size(), 0.0);
  for (std::size_t t = 0; t < model.mesh.tets.size(); ++t) {
    const auto& tet = model.mesh.tets[t];
    const double share =
        core::signed_volume(rest[tet[0]], rest[tet[1]], rest[tet[2]], rest[tet[3]]) / 6.0;
    const double k = model.material_of(static_cast<int>(t)).distance_stiffness * share;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        const double length2 = (rest[tet[b]] - rest[tet[a]]).squaredNorm();
        if (!(length2 > 0.0)) continue;
        stiffness[tet[a]] += k / length2 / 3.0;
        stiffness[tet[b]] += k / length2 / 3.0;
      }
  }
  return stiffness;
}

}  // namespace viscera::sim
