#pragma once
/// The MPI side of `viscera generate` (DESIGN.md §8): under `mpirun -n K` every rank takes a
/// disjoint share of the batch and rank 0 gathers the records; started without a launcher the
/// program is one rank and MPI is not initialised at all, so the same binary runs anywhere.

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

}  // namespace viscera::cli
