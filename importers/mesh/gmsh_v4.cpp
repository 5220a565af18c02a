// Format 4.1 sections (gmsh 4.8 manual §9.1), and the ASCII 4.0 of gmsh 4.0 (2018), which differs
// in four places: points carry a bounding box, the section headers have no tag range, blocks
// name the entity tag before its dimension, and each node's tag precedes its coordinates. In
// binary files the counts and tags of nodes and elements are 64-bit (the header's data size 8),
// entity dimensions and tags 32-bit.
#include "importers/mesh/gmsh_sections.h"

namespace viscera::importers {
namespace {

std::string item(const char* what, std::uint64_t index, std::uint64_t count) {
  return std::string(what) + " " + std::to_string(index + 1) + " of " + std::to_string(count);
}

/// Reads one field: binary in the file's order, or an ASCII token.
class Fields {
 public:
  Fields(GmshScanner& scanner, bool binary) : scanner_(scanner), binary_(binary) {}
  int integer() {
    return binary_ ? scanner_.binary<std::int32_t>() : checked_int(scanner_.integer());
  }
  std::uint64_t size() {
    if (binary_) return scanner_.binary<std::uint64_t>();
    const std::int64_t value = scanner_.integer();
    if (value < 0) scanner_.fail("a negative count or tag");
    return static_cast<std::uint64_t>(value);
  }
  double real() { return binary_ ? scanner_.binary<double>() : scanner_.real(); }
  /// Smallest size of one field of each kind, for checking claimed counts.
  std::size_t min_size_bytes() const { return binary_ ? 8 : 2; }

 private:
  int checked_int(std::int64_t value) {
    if (value < INT32_MIN || value > INT32_MAX) scanner_.fail("an integer out of range");
    return static_cast<int>(value);
  }
  GmshScanner& scanner_;
  bool binary_;
};

/// The header of $Nodes and $Elements: block count, item count, smallest and largest tag. The
/// counts are checked against the rest of the file before anything is allocated for them.
struct SectionHeader {
  std::uint64_t blocks = 0;
  std::uint64_t items = 0;
};

SectionHeader read_header(GmshScanner& scanner, Fields& fields, bool v40, const char* items,
                          std::size_t item_fields, const char* blocks) {
  SectionHeader header;
  header.blocks = fields.size();
  header.items = fields.size();
  if (!v40) {
    fields.size();  // smallest tag
    fields.size();  // largest tag
  }
  scanner.check_claim(header.items, item_fields * fields.min_size_bytes(), items);
  scanner.check_claim(header.blocks, 4 * fields.min_size_bytes(), blocks);
  return header;
}

void finish_section(GmshScanner& scanner, const char* end) {
  scanner.at("");
  scanner.expect_line(end);
}

}  // namespace

void read_v4_entities(GmshScanner& scanner, const GmshFile& file,
                      std::map<std::pair<int, int>, int>& entity_physicals) {
  scanner.enter("$Entities");
  Fields fields(scanner, file.binary);
  std::uint64_t counts[4];
  for (auto& count : counts)
    count = fields.size();
  for (int dimension = 0; dimension < 4; ++dimension) {
    const std::uint64_t count = counts[dimension];
    scanner.check_claim(count, 4 * fields.min_size_bytes(), "entities");
    for (std::uint64_t e = 0; e < count; ++e) {
      scanner.at(item(dimension == 0   ? "point"
                      : dimension == 1 ? "curve"
                      : dimension == 2 ? "surface"
                                       : "volume",
                      e, count));
      const int tag = fields.integer();
      const bool box = dimension > 0 || file.version < 4.1;  // 4.0 boxes points too
      for (int c = 0; c < (box ? 6 : 3); ++c)
        fields.real();  // point or bounding box
      const std::uint64_t physical_count = fields.size();
      scanner.check_claim(physical_count, fields.min_size_bytes() / 2, "physical tags");
      for (std::uint64_t p = 0; p < physical_count; ++p) {
        const int physical = fields.integer();
        if (p == 0) entity_physicals[{dimension, tag}] = physical;
      }
      if (dimension > 0) {
        const std::uint64_t bounding = fields.size();
        scanner.check_claim(bounding, fields.min_size_bytes() / 2, "bounding entities");
        for (std::uint64_t b = 0; b < bounding; ++b)
          fields.integer();
      }
    }
  }
  finish_section(scanner, "$EndEntities");
}

void read_v4_nodes(GmshScanner& scanner, GmshFile& file) {
  scanner.enter("$Nodes");
  Fields fields(scanner, file.binary);
  const bool v40 = file.version < 4.1;
  const auto [block_count, node_count] =
      read_header(scanner, fields, v40, "nodes", 4, "node blocks");
  file.node_tags.reserve(node_count);
  file.nodes.reserve(node_count);
  for (std::uint64_t b = 0; b < block_count; ++b) {
    scanner.at(item("node block", b, block_count));
    int dimension = fields.integer();
    if (v40) dimension = fields.integer();  // 4.0: entity tag, then dimension
    if (!v40) fields.integer();             // 4.1: dimension, then entity tag
    const int parametric = fields.integer();
    const std::uint64_t count = fields.size();
    if (count > node_count - file.nodes.size())
      scanner.fail("the blocks hold more nodes than the header says");
    const int extra = parametric != 0 ? dimension : 0;
    scanner.check_claim(count, static_cast<std::size_t>(4 + extra) * fields.min_size_bytes(),
                        "nodes");
    for (std::uint64_t n = 0; n < count && !v40; ++n)
      file.node_tags.push_back(static_cast<std::int64_t>(fields.size()));
    for (std::uint64_t n = 0; n < count; ++n) {
      if (v40) file.node_tags.push_back(static_cast<std::int64_t>(fields.size()));
      const double x = fields.real(), y = fields.real(), z = fields.real();
      for (int p = 0; p < extra; ++p)
        fields.real();  // parametric coordinates on the entity
      file.nodes.emplace_back(x, y, z);
    }
  }
  if (file.nodes.size() != node_count)
    scanner.fail("the blocks hold fewer nodes than the header says");
  finish_section(scanner, "$EndNodes");
}

void read_v4_elements(GmshScanner& scanner, GmshFile& file,
                      const std::map<std::pair<int, int>, int>& entity_physicals) {
  scanner.enter("$Elements");
  Fields fields(scanner, file.binary);
  const bool v40 = file.version < 4.1;
  const auto [block_count, element_count] =
      read_header(scanner, fields, v40, "elements", 2, "element blocks");
  std::uint64_t total = 0;
  for (std::uint64_t b = 0; b < block_count; ++b) {
    scanner.at(item("element block", b, block_count));
    GmshElementBlock block;
    block.dimension = fields.integer();
    block.entity = fields.integer();
    if (v40) std::swap(block.dimension, block.entity);  // 4.0: entity tag, then dimension
    block.type = fields.integer();
    const std::uint64_t count = fields.size();
    block.nodes_per_element = gmsh_nodes_per_element(block.type);
    if (block.nodes_per_element == 0) {
      scanner.fail("element type " + std::to_string(block.type) +
                   " is not a gmsh element type this reader knows (1-31)");
    }
    if (count > element_count - total)
      scanner.fail("the blocks hold more elements than the header says");
    scanner.check_claim(
        count, static_cast<std::size_t>(1 + block.nodes_per_element) * fields.min_size_bytes(),
        "elements");
    const auto physical = entity_physicals.find({block.dimension, block.entity});
    block.physical = physical == entity_physicals.end() ? 0 : physical->second;
    block.nodes.reserve(count * static_cast<std::uint64_t>(block.nodes_per_element));
    block.tags.reserve(count);
    for (std::uint64_t e = 0; e < count; ++e) {
      block.tags.push_back(static_cast<std::int64_t>(fields.size()));
      for (int n = 0; n < block.nodes_per_element; ++n)
        block.nodes.push_back(static_cast<std::int64_t>(fields.size()));
    }
    total += count;
    file.blocks.push_back(std::move(block));
  }
  if (total != element_count) scanner.fail("the blocks hold fewer elements than the header says");
  finish_section(scanner, "$EndElements");
}

}  // namespace viscera::importers
