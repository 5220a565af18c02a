#include "studio/cli/mpi_ranks.h"

#include <mpi.h>

#include <cstdlib>
#include <cstring>

#include "core/error.h"

namespace viscera::cli {
namespace {

bool started_by_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw core::Error(std::string("MPI: ") + what + " failed");
}

}  // namespace

MpiRanks::MpiRanks() {
  if (!started_by_launcher()) return;
  int already = 0;
  MPI_Initialized(&already);
  if (!already) check(MPI_Init(nullptr, nullptr), "MPI_Init");
  initialised_ = !already;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiRanks::~MpiRanks() {
  if (initialised_) MPI_Finalize();
}

std::vector<std::string> MpiRanks::gather(const std::string& text) const {
  if (size_ == 1) return {text};
  const int length = static_cast<int>(text.size());
  std::vector<int> lengths(static_cast<std::size_t>(size_), 0);
  check(MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD),
        "MPI_Gather");
  std::vector<int> offsets(static_cast<std::size_t>(size_), 0);
  int total = 0;
  for (int r = 0; r < size_; ++r) {
    offsets[static_cast<std::size_t>(r)] = total;
    total += lengths[static_cast<std::size_t>(r)];
  }
  std::string all(rank_ == 0 ? static_cast<std::size_t>(total) : 0, '\0');
  check(MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(),
                    MPI_CHAR, 0, MPI_COMM_WORLD),
        "MPI_Gatherv");
  if (rank_ != 0) return {};
  std::vector<std::string> parts;
  for (int r = 0; r < size_; ++r) {
    parts.push_back(all.substr(static_cast<std::size_t>(offsets[static_cast<std::size_t>(r)]),
                               static_cast<std::size_t>(lengths[static_cast<std::size_t>(r)])));
  }
  return parts;
}

int MpiRanks::broadcast(int value) const {
  if (size_ > 1) check(MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Bcast");
  return value;
}

MpiSharedCounter::MpiSharedCounter(const MpiRanks& ranks) : shared_(ranks.size() > 1) {
  if (!shared_) return;
  static_assert(sizeof(MPI_Win) <= sizeof(void*));
  MPI_Win window = MPI_WIN_NULL;
  const MPI_Aint bytes = ranks.rank() == 0 ? static_cast<MPI_Aint>(sizeof(std::uint64_t)) : 0;
  check(MPI_Win_allocate(bytes, static_cast<int>(sizeof(std::uint64_t)), MPI_INFO_NULL,
                         MPI_COMM_WORLD, &base_, &window),
        "MPI_Win_allocate");
  if (ranks.rank() == 0) {
    check(MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, window), "MPI_Win_lock");
    *base_ = 0;
    check(MPI_Win_unlock(0, window), "MPI_Win_unlock");
  }
  std::memcpy(&window_, &window, sizeof window);
  // Nobody takes from the counter before rank 0 has set it.
  check(MPI_Barrier(MPI_COMM_WORLD), "MPI_Barrier");
}

MpiSharedCounter::~MpiSharedCounter() {
  if (!shared_) return;
  MPI_Win window = MPI_WIN_NULL;
  std::memcpy(&window, &window_, sizeof window);
  MPI_Win_free(&window);
}

std::uint64_t MpiSharedCounter::fetch_and_increment() {
  if (!shared_) return local_++;
  MPI_Win window = MPI_WIN_NULL;
  std::memcpy(&window, &window_, sizeof window);
  const std::uint64_t one = 1;
  std::uint64_t before = 0;
  check(MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, window), "MPI_Win_lock");
  check(MPI_Fetch_and_op(&one, &before, MPI_UINT64_T, 0, 0, MPI_SUM, window), "MPI_Fetch_and_op");
  check(MPI_Win_unlock(0, window), "MPI_Win_unlock");
  return before;
}

}  // namespace viscera::cli
