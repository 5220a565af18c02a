#include "importers/mesh/gmsh_file.h"

#include <array>
#include <fstream>
#include <sstream>

#include "importers/mesh/gmsh_sections.h"

namespace viscera::importers {
namespace {

struct ElementShape {
  int nodes;
  int dimension;
};

/// Element types 1–31 of the gmsh manual (§9.1): nodes per element and dimension.
constexpr std::array<ElementShape, 32> kShapes = {{
    {0, -1},                                                        // 0: unused
    {2, 1},  {3, 2},  {4, 2},  {4, 3},  {8, 3},  {6, 3},  {5, 3},   // 1–7
    {3, 1},  {6, 2},  {9, 2},  {10, 3}, {27, 3}, {18, 3}, {14, 3},  // 8–14
    {1, 0},  {8, 2},  {20, 3}, {15, 3}, {13, 3},                    // 15–19
    {9, 2},  {10, 2}, {12, 2}, {15, 2}, {15, 2}, {21, 2},           // 20–25
    {4, 1},  {5, 1},  {6, 1},  {20, 3}, {35, 3}, {56, 3},           // 26–31
}};

std::string read_bytes(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path))
    throw core::InputError("no such file", {path.string(), "", ""});
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in.good() && !in.eof())
    throw core::InputError("cannot read the file", {path.string(), "", ""});
  return bytes.str();
}

/// "$MeshFormat": version, file type (0 ASCII, 1 binary) and data size, then for binary files
/// the integer 1 written in the writer's byte order.
void read_mesh_format(GmshScanner& scanner, GmshFile& file) {
  scanner.enter("$MeshFormat");
  file.version = scanner.real();
  const std::int64_t type = scanner.integer();
  const std::int64_t data_size = scanner.integer();
  scanner.line();
  if (type != 0 && type != 1)
    scanner.fail("file type " + std::to_string(type) + " is neither ASCII (0) nor binary (1)");
  file.binary = type == 1;
  const bool v2 = file.version >= 2.0 && file.version < 3.0;
  const bool v4 = file.version >= 4.0 && file.version < 5.0;
  if (v4 && file.version < 4.1 && file.binary) {
    // gmsh itself wrote 4.0 in binary only in 2018 and no longer can: no file to check against.
    scanner.fail(
        "binary format 4.0 is not read (ASCII 4.0, 2.x and 4.1 are; gmsh writes 4.1 with -format "
        "msh41)");
  }
  if (!v2 && !v4) {
    std::ostringstream shown;
    shown << file.version;
    scanner.fail("format version " + shown.str() +
                 " is not read (2.x, 4.0 and 4.1 are; gmsh writes 4.1 with -format msh41)");
  }
  if (data_size != 8) scanner.fail("data size " + std::to_string(data_size) + " is not 8");
  if (file.binary) {
    const auto one = scanner.binary<std::int32_t>();
    if (one == 0x01000000) {
      scanner.set_swap(true);
    } else if (one != 1) {
      scanner.fail("the byte-order mark is not 1");
    }
    scanner.line();
  }
  scanner.expect_line("$EndMeshFormat");
}

void read_physical_names(GmshScanner& scanner, GmshFile& file) {
  scanner.enter("$PhysicalNames");
  const std::int64_t count = scanner.integer();
  scanner.check_claim(static_cast<std::uint64_t>(std::max<std::int64_t>(count, 0)), 6,
                      "physical names");
  for (std::int64_t i = 0; i < count; ++i) {
    scanner.at("name " + std::to_string(i + 1) + " of " + std::to_string(count));
    const int dimension = static_cast<int>(scanner.integer());
    const int tag = static_cast<int>(scanner.integer());
    std::string name(scanner.line());
    const auto first = name.find('"'), last = name.rfind('"');
    if (first == std::string::npos || last == first) scanner.fail("the name is not quoted");
    file.physical_names[{dimension, tag}] = name.substr(first + 1, last - first - 1);
  }
  scanner.at("");
  scanner.expect_line("$EndPhysicalNames");
}

}  // namespace

int gmsh_nodes_per_element(int type) {
  return type > 0 && type < static_cast<int>(kShapes.size())
             ? kShapes[static_cast<std::size_t>(type)].nodes
             : 0;
}

int gmsh_element_dimension(int type) {
  return type > 0 && type < static_cast<int>(kShapes.size())
             ? kShapes[static_cast<std::size_t>(type)].dimension
             : -1;
}

GmshFile read_gmsh_file(const std::filesystem::path& path) {
  GmshScanner scanner(read_bytes(path), path.string());
  GmshFile file;
  scanner.enter("the first line");
  if (scanner.at_end() || scanner.next_line() != "$MeshFormat")
    scanner.fail("not a gmsh file: it does not start with $MeshFormat");
  read_mesh_format(scanner, file);
  const bool v2 = file.version < 3.0;
  std::map<std::pair<int, int>, int> entity_physicals;
  bool has_nodes = false, has_elements = false;
  while (!scanner.at_end()) {
    scanner.enter("");
    scanner.at("");
    const std::string section(scanner.line());
    if (section.empty()) continue;
    if (section == "$PhysicalNames") {
      read_physical_names(scanner, file);
    } else if (section == "$Entities" && !v2) {
      read_v4_entities(scanner, file, entity_physicals);
    } else if (section == "$Nodes") {
      if (has_nodes) scanner.fail("a second $Nodes section");
      v2 ? read_v2_nodes(scanner, file) : read_v4_nodes(scanner, file);
      has_nodes = true;
    } else if (section == "$Elements") {
      if (has_elements) scanner.fail("a second $Elements section");
      v2 ? read_v2_elements(scanner, file) : read_v4_elements(scanner, file, entity_physicals);
      has_elements = true;
    } else if (section.size() > 1 && section.front() == '$' && section.rfind("$End", 0) != 0) {
      scanner.enter(section);
      scanner.skip_past("$End" + section.substr(1));
    } else {
      scanner.fail("unexpected line \"" + section.substr(0, 40) + "\" between sections");
    }
  }
  scanner.enter("");
  if (!has_nodes) scanner.fail("the file has no $Nodes section");
  if (!has_elements) scanner.fail("the file has no $Elements section");
  return file;
}

}  // namespace viscera::importers
