#include "exporters/gmsh_msh_writer.h"

#include <algorithm>
#include <charconv>
#include <map>

#include "exporters/staged_output.h"

namespace viscera::exporters {
namespace {

/// Appends numbers in their shortest exact form.
class Text {
 public:
  Text& operator<<(double value) {
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    text_.append(buffer, end);
    return *this;
  }
  Text& operator<<(std::size_t value) {
    char buffer[24];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    text_.append(buffer, end);
    return *this;
  }
  Text& operator<<(int value) {
    char buffer[16];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    text_.append(buffer, end);
    return *this;
  }
  Text& operator<<(const std::string& text) {
    text_ += text;
    return *this;
  }
  Text& operator<<(const char* text) {
    text_ += text;
    return *this;
  }
  const std::string& str() const { return text_; }

 private:
  std::string text_;
};

struct Entity {
  int dimension = 3;
  int tag = 0;
  int physical = 0;
  std::string name;
  std::size_t part = 0;
  int label = 0;
};

void bounding_box(Text& out, const std::vector<core::Vec3>& nodes) {
  core::BoundingBox box;
  for (const auto& p : nodes)
    box.add(p);
  if (box.empty()) box.add(core::Vec3::Zero());
  out << box.min.x() << " " << box.min.y() << " " << box.min.z() << " " << box.max.x() << " "
      << box.max.y() << " " << box.max.z();
}

}  // namespace

void write_gmsh_msh41(const std::vector<MshPart>& parts, const std::filesystem::path& path,
                      const std::string& shown) {
  // Entities: per part one volume per label (ordered), then one surface if it has triangles.
  std::vector<Entity> entities;
  int volume_tags = 0, surface_tags = 0, volume_physicals = 0, surface_physicals = 0;
  std::vector<std::vector<std::size_t>> part_volumes(parts.size());
  std::vector<int> part_surface(parts.size(), 0);
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const MshPart& part = parts[p];
    if (part.tets != nullptr && !part.tets->empty()) {
      std::map<int, int> labels;
      for (std::size_t t = 0; t < part.tets->size(); ++t)
        labels[part.tet_labels != nullptr ? (*part.tet_labels)[t] : 0];
      for (const auto& [label, unused] : labels) {
        Entity entity{
            3,
            ++volume_tags,
            ++volume_physicals,
            labels.size() == 1 ? part.name : part.name + "/label " + std::to_string(label),
            p,
            label};
        part_volumes[p].push_back(entities.size());
        entities.push_back(entity);
      }
    }
    if (part.triangles != nullptr && !part.triangles->empty()) {
      part_surface[p] = ++surface_tags;
      entities.push_back({2, surface_tags, ++surface_physicals, part.name + "/surface", p, 0});
    }
  }
  // Readers label tets by physical tag: when the labels are positive and no two volumes share
  // one, they are the physical tags, so labels survive a round trip.
  std::map<int, int> label_use;
  for (const auto& e : entities) {
    if (e.dimension == 3) ++label_use[e.label];
  }
  const bool labels_as_tags = std::all_of(label_use.begin(), label_use.end(), [](const auto& use) {
    return use.first > 0 && use.second == 1;
  });
  if (labels_as_tags) {
    for (auto& e : entities) {
      if (e.dimension == 3) e.physical = e.label;
    }
  }

  Text out;
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  out << "$PhysicalNames\n" << entities.size() << "\n";
  for (const auto& e : entities)
    out << e.dimension << " " << e.physical << " \"" << e.name << "\"\n";
  out << "$EndPhysicalNames\n";
  out << "$Entities\n0 0 " << surface_tags << " " << volume_tags << "\n";
  for (const auto& e : entities) {
    if (e.dimension != 2) continue;
    out << e.tag << " ";
    bounding_box(out, *parts[e.part].nodes);
    out << " 1 " << e.physical << " 0\n";
  }
  for (const auto& e : entities) {
    if (e.dimension != 3) continue;
    out << e.tag << " ";
    bounding_box(out, *parts[e.part].nodes);
    out << " 1 " << e.physical;
    const int surface = part_surface[e.part];
    out << (surface != 0 ? " 1 " : " 0");
    if (surface != 0) out << surface;
    out << "\n";
  }
  out << "$EndEntities\n";

  // Nodes: one block per part, classified on its first entity.
  std::size_t node_count = 0, blocks = 0;
  for (const auto& part : parts) {
    node_count += part.nodes->size();
    blocks += part.nodes->empty() ? 0 : 1;
  }
  out << "$Nodes\n"
      << blocks << " " << node_count << " " << (node_count > 0 ? std::size_t{1} : std::size_t{0})
      << " " << node_count << "\n";
  std::vector<std::size_t> first_tag(parts.size());
  std::size_t next = 1;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    first_tag[p] = next;
    const auto& nodes = *parts[p].nodes;
    if (nodes.empty()) continue;
    const bool volume = !part_volumes[p].empty();
    const int tag = volume ? entities[part_volumes[p].front()].tag : part_surface[p];
    out << (volume ? 3 : 2) << " " << tag << " 0 " << nodes.size() << "\n";
    for (std::size_t i = 0; i < nodes.size(); ++i)
      out << next + i << "\n";
    for (const auto& x : nodes)
      out << x.x() << " " << x.y() << " " << x.z() << "\n";
    next += nodes.size();
  }
  out << "$EndNodes\n";

  // Elements: per volume entity its tets, per surface entity its triangles.
  std::size_t element_count = 0;
  for (const auto& part : parts) {
    element_count += (part.tets != nullptr ? part.tets->size() : 0) +
                     (part.triangles != nullptr ? part.triangles->size() : 0);
  }
  out << "$Elements\n"
      << entities.size() << " " << element_count << " "
      << (element_count > 0 ? std::size_t{1} : std::size_t{0}) << " " << element_count << "\n";
  // Element tags keep each part's order (its tets, then its triangles) whatever entity holds
  // them, so readers that order elements by tag get the mesh back as it was.
  std::vector<std::size_t> first_element(parts.size());
  std::size_t next_element = 1;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    first_element[p] = next_element;
    next_element += (parts[p].tets != nullptr ? parts[p].tets->size() : 0) +
                    (parts[p].triangles != nullptr ? parts[p].triangles->size() : 0);
  }
  for (const auto& e : entities) {
    const MshPart& part = parts[e.part];
    const std::size_t base = first_tag[e.part];
    std::size_t element = first_element[e.part];
    if (e.dimension == 3) {
      std::size_t count = 0;
      for (std::size_t t = 0; t < part.tets->size(); ++t)
        count += (part.tet_labels != nullptr ? (*part.tet_labels)[t] : 0) == e.label;
      out << 3 << " " << e.tag << " 4 " << count << "\n";
      for (std::size_t t = 0; t < part.tets->size(); ++t) {
        if ((part.tet_labels != nullptr ? (*part.tet_labels)[t] : 0) != e.label) continue;
        const auto& tet = (*part.tets)[t];
        out << element + t;
        for (const int n : tet)
          out << " " << base + static_cast<std::size_t>(n);
        out << "\n";
      }
    } else {
      out << 2 << " " << e.tag << " 2 " << part.triangles->size() << "\n";
      element += part.tets != nullptr ? part.tets->size() : 0;
      for (const auto& tri : *part.triangles) {
        out << element++;
        for (const int n : tri)
          out << " " << base + static_cast<std::size_t>(n);
        out << "\n";
      }
    }
  }
  out << "$EndElements\n";
  write_bytes(out.str(), path, shown);
}

}  // namespace viscera::exporters
