#pragma once
/// Seeds of a batch's patients (issue 6 §4): patient k of a batch depends only on (template,
/// batch seed, k), however the batch is split between processes, ranks or array jobs — each
/// patient's seed is a hash of those three, never a draw from a stream other patients share.

#include <cstdint>
#include <string>

namespace viscera::templates {

/// The first 8 bytes (big-endian) of SHA-256 of
/// "viscera-generate/1/<template>/<batch_seed>/<k>/<attempt>". Attempt 0 is the first draw of
/// patient k; a draw that fails validation is redrawn with attempt + 1.
std::uint64_t patient_seed(const std::string& template_name, std::uint64_t batch_seed,
                           std::uint64_t k, std::uint64_t attempt);

}  // namespace viscera::templates
