#pragma once
/// The MPI side of `viscera generate` (DESIGN.md §8): under `mpirun -n K` every rank takes a
/// disjoint share of the batch and rank 0 gathers the records; started without a launcher the
/// program is one rank and MPI is not initialised at all, so the same binary runs anywhere.

#include <cstdint>
#include <string>
#include <vector>

namespace viscera::cli {

/// MPI_COMM_WORLD for the lifetime of the object, when the process was started by an MPI
/// launcher (OpenMPI's OMPI_COMM_WORLD_SIZE, or PMI_SIZE / PMIX_RANK of MPICH and Slurm);
/// otherwise a single rank 0 of 1.
class MpiRanks {
 public:
  MpiRanks();
  ~MpiRanks();
  MpiRanks(const MpiRanks&) = delete;
  MpiRanks& operator=(const MpiRanks&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  /// Collects every rank's `text` on rank 0, in rank order (other ranks get an empty list).
  std::vector<std::string> gather(const std::string& text) const;
  /// Rank 0's `value` on every rank.
  int broadcast(int value) const;

 private:
  bool initialised_ = false;
  int rank_ = 0;
  int size_ = 1;
};

/// A counter held by rank 0 that every rank increments atomically, for handing out work
/// dynamically: MPI one-sided MPI_Fetch_and_op under a shared lock on a window of rank 0
/// (passive target: rank 0 need not call MPI while the others take from it). Collective:
/// construct and destroy it on every rank. With one rank it is a plain counter.
class MpiSharedCounter {
 public:
  explicit MpiSharedCounter(const MpiRanks& ranks);
  ~MpiSharedCounter();
  MpiSharedCounter(const MpiSharedCounter&) = delete;
  MpiSharedCounter& operator=(const MpiSharedCounter&) = delete;

  /// The counter's value before this call's increment: 0, 1, 2, … over all ranks, each once.
  std::uint64_t fetch_and_increment();

 private:
  bool shared_ = false;
  std::uint64_t local_ = 0;
  std::uint64_t* base_ = nullptr;
  void* window_ = nullptr;  ///< MPI_Win (an opaque pointer in OpenMPI and MPICH alike)
};

}  // namespace viscera::cli
