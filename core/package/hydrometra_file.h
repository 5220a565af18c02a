#pragma once
/// objects/<id>/hydrometra.bin of a scenario package: an organ's hydrometra pressure states
/// (core/scenario/hydrometra_states.h, seed 000 §2.1) as little-endian binary, so the ~100
/// states × every body node take 24 bytes per node and state and read back bit for bit:
///
///   offset  size        field
///   0       8           magic "VHYDRO01"
///   8       4  u32      state count S
///   12      4  u32      node count N
///   16      8  f64      residual of the sweep, N
///   24      8·S f64     pressures, Pa, strictly increasing
///   …       24·S·N f64  displacements, m, state-major, x y z per node
///
/// The same states give the same bytes (no time stamps, no padding).

#include <string>

#include "core/scenario/hydrometra_states.h"

namespace viscera::core {

/// The file name inside a package of object `object_id`'s states.
std::string hydrometra_file_of(const std::string& object_id);

/// The bytes of `states`.
std::string hydrometra_bytes(const HydrometraStates& states);

/// Parses bytes written by hydrometra_bytes; throws InputError naming `file` for a wrong
/// magic, a size that does not match the header, or invalid states (check_hydrometra_states).
HydrometraStates read_hydrometra_bytes(const std::string& bytes, const std::string& file);

}  // namespace viscera::core
