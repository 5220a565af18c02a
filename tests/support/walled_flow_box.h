#pragma once
// A flow grid walled all round, for the fluid tests and benchmarks: nx×ny×nz cells of edge
// `cell_size` m whose outermost layer is solid at rest, the rest fluid, faces up to date.

#include "simulator/fluid/flow_grid.h"

namespace viscera::test {

inline sim::fluid::FlowGrid walled_flow_box(int nx, int ny, int nz, double cell_size) {
  sim::fluid::FlowGrid grid(nx, ny, nz, cell_size);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        if (i == 0 || j == 0 || k == 0 || i == nx - 1 || j == ny - 1 || k == nz - 1)
          grid.set_cell(i, j, k, sim::fluid::FlowCell::Solid);
  grid.update_faces();
  return grid;
}

}  // namespace viscera::test
