#pragma once
/// `viscera segment`: an image volume to a label map (.vti) the mesher takes (DESIGN.md §9).
///
///   viscera segment IN -o LABELS.vti [steps…] [--name LABEL=NAME …] [--json] [--max-memory MIB]
///
/// Steps run in this fixed order, each optional, at least one of the first two required:
///   --threshold LO:HI[=LABEL]    voxels with LO ≤ value ≤ HI (volume units, e.g. HU) get LABEL
///                                (default 1); repeatable, a later window wins where they overlap
///   --grow X,Y,Z[:TOL][=LABEL]   region grown from the voxel nearest to the point X,Y,Z (mm,
///                                patient LPS as `volume info` prints) through 6-connected voxels
///                                within TOL of the seed's value (default 0); repeatable, drawn
///                                over the thresholds
///   --open R, --close R          opening, then closing, with a ball of R voxels (each label)
///   --largest                    keep each label's largest 6-connected component
///   --merge A,B,…=C              labels A, B, … become C (repeatable)
///   --remove L                   label L becomes background (repeatable)
///   --relabel A=B                label A becomes B (repeatable)
/// A result with no labelled voxel is refused (exit 3) and nothing is written.

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Adds `segment` to `app`.
void add_segment_commands(CLI::App& app);

}  // namespace viscera::cli
