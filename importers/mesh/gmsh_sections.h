#pragma once
/// The version-specific sections of a .msh file (gmsh 4.8 manual §9.1, §9.2). Internal to the
/// gmsh reader: each function starts after the section's opening line and stops after its
/// "$End…" line.

#include "importers/mesh/gmsh_file.h"
#include "importers/mesh/gmsh_scanner.h"

namespace viscera::importers {

/// Format 2.x: "$Nodes" with one node per line or record, "$Elements" with per-element tags.
void read_v2_nodes(GmshScanner& scanner, GmshFile& file);
void read_v2_elements(GmshScanner& scanner, GmshFile& file);

/// Format 4.1: "$Entities" (physical tags of each entity), "$Nodes" and "$Elements" by entity
/// block. `entity_physicals` maps (dimension, entity tag) to the entity's first physical tag.
void read_v4_entities(GmshScanner& scanner, const GmshFile& file,
                      std::map<std::pair<int, int>, int>& entity_physicals);
void read_v4_nodes(GmshScanner& scanner, GmshFile& file);
void read_v4_elements(GmshScanner& scanner, GmshFile& file,
                      const std::map<std::pair<int, int>, int>& entity_physicals);

}  // namespace viscera::importers
