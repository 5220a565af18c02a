#pragma once
/// Text for XML and HTML documents that Viscera writes (VTK multiblock files, session reports).

#include <string>
#include <string_view>

namespace viscera::core {

/// `text` with &, <, > and " replaced by their entities, safe inside element text and
/// double-quoted attribute values.
std::string xml_escaped(std::string_view text);

}  // namespace viscera::core
