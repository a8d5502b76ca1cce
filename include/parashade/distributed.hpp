#pragma once
// One frame across MPI ranks (docs/distributed.md). No MPI in this header: host/distributed/ holds the
// MPI code; without MPI (CMake found none) the functions below refuse with a usage error.
//
// sort-last: the planner's strategies assign the scene's faces to ranks by modeled cost; each rank
// prepares (prepare_frame) and renders only its share as a planned frame, whose depth keys (depth,
// scene face) and colours are composited by MPI_Alltoall + MPI_Reduce_local (a min-key operator: a
// reduce-scatter) and MPI_Gather to rank 0. sort-first: bands of tile rows sized by the ranks' measured speed, gathered
// with MPI_Gatherv. Either way the image is the one-process render's, byte for byte.
#include <cstdint>
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
#include "parashade/render_outputs.hpp"
#include "parashade/render_step.hpp"
#include "parashade/renderer.hpp"
#include "parashade/scene.hpp"

namespace parashade {

enum class Distribute { sort_last, sort_first };

// --rank-timeout's default: seconds a rank may wait in one MPI call for the others before the job is ended
// (a stopped or hung rank); longer than any wait of a healthy job (rank 0 reading and scattering a large
// scene, or computing the error figures of a 4096x4096 frame while the others wait to finish).
constexpr double kDefaultRankTimeoutSeconds = 600;

// "sort-last" or "sort-first"; throws UsageError naming the value.
Distribute parse_distribute(const std::string& name);
const char* distribute_name(Distribute d);
DeviceMode distribute_device_mode(Distribute d);
// True when this build has MPI (CMake found it).
bool mpi_built();

// What each rank measured in one frame (sent to rank 0 as doubles).
struct RankFigures {
  double faces = 0, records = 0, pixels = 0, won_pixels = 0, modeled_clocks = 0;
  double prepare_ms = 0, render_ms = 0, frame_ms = 0, composite_ms = 0, bytes_sent = 0;
  double band_first = 0, band_rows = 0, record_bytes = 0;
  double pack_ms = 0;  // sort-last: keys and colours into the composite's buffer (local, per pixel)
  double gather_ms = 0;  // the composite's gather to rank 0 (sort-last: after the reduce-scatter)
};

// What rank 0 gathered over the timed frames (render_step.hpp's RenderResult::distributed).
struct DistributedFigures {
  Distribute mode = Distribute::sort_last;
  int ranks = 1, threads_per_rank = 1;
  std::uint64_t faces = 0;       // the scene's
  bool scatter_scene = false;    // --read-scene rank-0
  Partition rank_partition = Partition::lpt;
  double planning_ms = 0;        // sort-last: faces to ranks, on rank 0
  std::vector<std::vector<RankFigures>> frames;  // per timed frame, every rank's
  std::vector<double> peak_rss_mib;               // per rank
  // Per rank, the median over the timed frames of each figure (sort-first: the last frame's band).
  std::vector<RankFigures> rank_medians() const;
};

struct DistributedRender {
  Distribute mode = Distribute::sort_last;
  // The render every rank makes (options checked against the table for the mode before the call, tile
  // given); rank 0 computes the error figures when it asks for them and writes `outputs`.
  RenderRequest request;
  RenderOutputs outputs;
  Partition rank_partition = Partition::lpt;  // sort-last: faces to ranks (round-robin, lpt, dynamic)
  int rank_batch = 64;                // dynamic: consecutive faces per batch
  int setup_clocks = 1;               // the planner's cost model
  bool quiet = false;
  // false: every rank reads the scene file; true (--read-scene rank-0): rank 0 reads it and scatters the
  // sort-last shares (MPI_Scatterv) or broadcasts the whole scene to sort-first ranks
  bool scatter_scene = false;
  double rank_timeout = kDefaultRankTimeoutSeconds;  // --rank-timeout: seconds, 0 for none
};

// Runs under mpirun (MPI_Init here, MPI_Finalize before returning). Every rank returns the same exit
// code; a failure on any rank stops every rank, rank 0 prints each failing rank's message, no image
// or report is written. On rank 0, `result` gets the composited frame's result (with its distributed
// figures) and `lines` what the pictures hold, after the outputs were written.
int run_distributed_render(const DistributedRender& job, RenderResult* result, std::vector<std::string>* lines);

// The ranks of a sharded sweep (`mpirun -np N parashade scaling --mpi`): each rank runs its share of the
// cases, rank 0 merges. join() initializes MPI (UsageError when built without it); MPI is finalized
// when the group is destroyed.
class RankGroup {
 public:
  // `rank_timeout`: as DistributedRender's, off by default (a rank's whole share is one wait).
  static std::unique_ptr<RankGroup> join(double rank_timeout = 0);
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
