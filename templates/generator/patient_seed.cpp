#include "templates/generator/patient_seed.h"

#include "core/sha256.h"

namespace viscera::templates {

std::uint64_t patient_seed(const std::string& template_name, std::uint64_t batch_seed,
                           std::uint64_t k, std::uint64_t attempt) {
  core::Sha256 hash;
  hash.update("viscera-generate/1/" + template_name + "/" + std::to_string(batch_seed) + "/" +
              std::to_string(k) + "/" + std::to_string(attempt));
  const auto digest = hash.digest();
  std::uint64_t seed = 0;
  for (int i = 0; i < 8; ++i)
    seed = (seed << 8) | digest[static_cast<std::size_t>(i)];
  return seed;
}

}  // namespace viscera::templates
