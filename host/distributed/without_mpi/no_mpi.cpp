// Built when CMake found no MPI: --distribute is refused, everything else works as before.
#include "parashade/distributed.hpp"

#include "parashade/errors.hpp"

namespace parashade {

bool mpi_built() { return false; }

int run_distributed_render(const DistributedRender&, RenderResult*, std::vector<std::string>*) {
  throw UsageError("--distribute needs MPI, and this parashade was built without it (install Open MPI: "
                   "scripts/install-deps.sh, then configure again)");
}

std::unique_ptr<RankGroup> RankGroup::join(double) {
  throw UsageError("--mpi needs MPI, and this parashade was built without it (install Open MPI: "
                   "scripts/install-deps.sh, then configure again)");
}

}  // namespace parashade
