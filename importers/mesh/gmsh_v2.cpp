// Format 2.x sections (gmsh 4.8 manual §9.2, "MSH file format version 2").
#include <map>
#include <tuple>

#include "importers/mesh/gmsh_sections.h"

namespace viscera::importers {
namespace {

std::string item(const char* what, std::int64_t index, std::int64_t count) {
  return std::string(what) + " " + std::to_string(index + 1) + " of " + std::to_string(count);
}

/// The count on the line after the section name.
std::int64_t section_count(GmshScanner& scanner, const char* what, std::size_t min_bytes_each) {
  const std::int64_t count = scanner.integer();
  if (count < 0) scanner.fail("negative " + std::string(what) + " count");
  scanner.check_claim(static_cast<std::uint64_t>(count), min_bytes_each, what);
  scanner.line();
  return count;
}

/// Blocks keyed by (type, elementary tag, physical tag), in order of first appearance.
class BlockIndex {
 public:
  explicit BlockIndex(GmshFile& file) : file_(file) {}
  GmshElementBlock& block(int type, int entity, int physical) {
    const auto key = std::make_tuple(type, entity, physical);
    auto found = index_.find(key);
    if (found == index_.end()) {
      GmshElementBlock block;
      block.type = type;
      block.dimension = gmsh_element_dimension(type);
      block.entity = entity;
      block.physical = physical;
      block.nodes_per_element = gmsh_nodes_per_element(type);
      file_.blocks.push_back(std::move(block));
      found = index_.emplace(key, file_.blocks.size() - 1).first;
    }
    return file_.blocks[found->second];
  }

 private:
  GmshFile& file_;
  std::map<std::tuple<int, int, int>, std::size_t> index_;
};

int checked_type(GmshScanner& scanner, std::int64_t type) {
  if (gmsh_nodes_per_element(static_cast<int>(type)) == 0) {
    scanner.fail("element type " + std::to_string(type) +
                 " is not a gmsh element type this reader knows (1-31)");
  }
  return static_cast<int>(type);
}

}  // namespace

void read_v2_nodes(GmshScanner& scanner, GmshFile& file) {
  scanner.enter("$Nodes");
  const std::int64_t count = section_count(scanner, "nodes", file.binary ? 28 : 8);
  file.node_tags.reserve(static_cast<std::size_t>(count));
  file.nodes.reserve(static_cast<std::size_t>(count));
  for (std::int64_t i = 0; i < count; ++i) {
    scanner.at(item("node", i, count));
    if (file.binary) {
      file.node_tags.push_back(scanner.binary<std::int32_t>());
      const double x = scanner.binary<double>(), y = scanner.binary<double>(),
                   z = scanner.binary<double>();
      file.nodes.emplace_back(x, y, z);
    } else {
      file.node_tags.push_back(scanner.integer());
      const double x = scanner.real(), y = scanner.real(), z = scanner.real();
      file.nodes.emplace_back(x, y, z);
    }
  }
  scanner.at("");
  scanner.expect_line("$EndNodes");
}

void read_v2_elements(GmshScanner& scanner, GmshFile& file) {
  scanner.enter("$Elements");
  const std::int64_t count = section_count(scanner, "elements", file.binary ? 12 : 8);
  BlockIndex blocks(file);
  std::int64_t read = 0;
  if (file.binary) {
    // Records come in runs that share a type and a tag count: a 3-integer header, then per
    // element its number, its tags and its nodes, all 32-bit.
    while (read < count) {
      scanner.at(item("element", read, count));
      const int type = checked_type(scanner, scanner.binary<std::int32_t>());
      const std::int64_t run = scanner.binary<std::int32_t>();
      const std::int64_t tag_count = scanner.binary<std::int32_t>();
      if (run <= 0 || run > count - read || tag_count < 0 || tag_count > 64)
        scanner.fail("a malformed element header");
      const int per = gmsh_nodes_per_element(type);
      scanner.check_claim(static_cast<std::uint64_t>(run),
                          4 * static_cast<std::size_t>(1 + tag_count + per), "elements");
      for (std::int64_t e = 0; e < run; ++e, ++read) {
        const std::int64_t number = scanner.binary<std::int32_t>();
        int physical = 0, entity = 0;
        for (std::int64_t t = 0; t < tag_count; ++t) {
          const int tag = scanner.binary<std::int32_t>();
          if (t == 0) physical = tag;
          if (t == 1) entity = tag;
        }
        auto& block = blocks.block(type, entity, physical);
        block.tags.push_back(number);
        for (int n = 0; n < per; ++n)
          block.nodes.push_back(scanner.binary<std::int32_t>());
      }
    }
  } else {
    for (; read < count; ++read) {
      scanner.at(item("element", read, count));
      const std::int64_t number = scanner.integer();
      const int type = checked_type(scanner, scanner.integer());
      const std::int64_t tag_count = scanner.integer();
      if (tag_count < 0 || tag_count > 64) scanner.fail("a malformed tag count");
      int physical = 0, entity = 0;
      for (std::int64_t t = 0; t < tag_count; ++t) {
        const auto tag = static_cast<int>(scanner.integer());
        if (t == 0) physical = tag;
        if (t == 1) entity = tag;
      }
      auto& block = blocks.block(type, entity, physical);
      block.tags.push_back(number);
      for (int n = 0; n < block.nodes_per_element; ++n)
        block.nodes.push_back(scanner.integer());
    }
  }
  scanner.at("");
  scanner.expect_line("$EndElements");
}

}  // namespace viscera::importers
