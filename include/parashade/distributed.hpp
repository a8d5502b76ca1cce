#pragma once
// One frame across MPI ranks (docs/distributed.md). No MPI in this header: host/distributed/ holds the
// MPI code; without MPI (CMake found none) the functions below refuse with a usage error.
//
// sort-last: the planner's strategies assign the scene's faces to ranks by modeled cost; each rank
// prepares (prepare_frame) and renders only its share as a planned frame, whose depth keys (depth,
// scene face) and colours are composited by MPI_Alltoall + MPI_Reduce_local (a min-key operator: a
// reduce-scatter) and MPI_Gather to rank 0. sort-first: bands of tile rows sized by the ranks' measured speed, gathered
// with MPI_Gatherv. Either way the image is the one-process render's, byte for byte.
#include <functional>
#include <memory>
#include <vector>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "parashade/combinations.hpp"
#include "parashade/errors.hpp"
#include "parashade/image.hpp"
#include "parashade/planner.hpp"
#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"

namespace parashade {

enum class Distribute { sort_last, sort_first };

// "sort-last" or "sort-first"; throws UsageError naming the value.
Distribute parse_distribute(const std::string& name);
const char* distribute_name(Distribute d);
DeviceMode distribute_device_mode(Distribute d);
// True when this build has MPI (CMake found it).
bool mpi_built();

struct DistributedRender {
  Distribute mode = Distribute::sort_last;
  RenderOptions options;              // checked against the table for the mode before the call
  Partition rank_partition = Partition::lpt;  // sort-last: faces to ranks (round-robin, lpt, dynamic)
  int rank_batch = 64;                // dynamic: consecutive faces per batch
  int setup_clocks = 1;               // the planner's cost model
  std::string device, output, report, scene_file;
  int frames = 1, warmup = 0;
  bool quiet = false, no_error = false;
  // false: every rank reads the scene file; true (--read-scene rank-0): rank 0 reads it and scatters the
  // sort-last shares (MPI_Scatterv) or broadcasts the whole scene to sort-first ranks
  bool scatter_scene = false;
  std::function<Scene()> load_scene;                 // the ranks that read the scene call this
  std::function<void()> check_destinations;          // rank 0, before the work
  // rank 0, unless no_error: the error figures of the composited image against the full scene
  std::function<nlohmann::json(const Scene&, const RenderedImage&, std::vector<std::string>& lines)> error_figures;
};

// Runs under mpirun (MPI_Init here, MPI_Finalize before returning). Every rank returns the same exit
// code; a failure on any rank stops every rank, rank 0 prints each failing rank's message, no image
// or report is written.
int run_distributed_render(const DistributedRender& job);

// The ranks of a sharded sweep (`mpirun -np N parashade scaling --mpi`): each rank runs its share of the
// cases, rank 0 merges. join() initializes MPI (UsageError when built without it); MPI is finalized
// when the group is destroyed.
class RankGroup {
 public:
  static std::unique_ptr<RankGroup> join();
  virtual ~RankGroup() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Runs `f` on this rank and agrees with every rank: when any failed, rank 0 prints each failing rank's
  // message and every rank throws StoppedRanks with the largest exit code.
  virtual void step(const std::function<void()>& f) = 0;
  // Every rank's text, in rank order, on rank 0 (MPI_Gatherv); empty on the others.
  virtual std::vector<std::string> gather(const std::string& mine) = 0;
};

// group->step(f) in a sharded run, plain f() without one (a sweep run without --mpi has no group).
inline void step_in(RankGroup* group, const std::function<void()>& f) {
  if (group) group->step(f);
  else f();
}

// What every rank throws after a failed step (rank 0 has printed why); main exits with `code`.
struct StoppedRanks : Error {
  explicit StoppedRanks(int code) : Error(ExitCode(code), "") {}
};

}  // namespace parashade
