#pragma once
/// Image volume subcommands (DESIGN.md §9):
///   viscera volume info PATH [--json] [--max-memory MIB]
///       format, size, spacing/origin in mm (patient LPS), direction, scalar type, value range,
///       notes, and the other DICOM series of a folder.
///   viscera volume convert IN -o OUT.vti|.nii|.nii.gz|.mha [--json] [--max-memory MIB]
/// IN is any file or DICOM folder importers::read_volume() reads. Exit code 3 with one line
/// naming the file on unreadable input; nothing is written then.

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Adds `volume info` and `volume convert` to `app`.
void add_volume_commands(CLI::App& app);

}  // namespace viscera::cli
