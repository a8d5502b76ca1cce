#pragma once
// MPI for one command: init and finalize, PoCL's threads divided between the ranks of a host, and
// failure agreement: a step that fails on any rank stops every rank (no rank waits in a collective for
// one that gave up), rank 0 names each failing rank and its cause.
#include <exception>
#include <string>
#include <utility>

#include <mpi.h>

#include "parashade/errors.hpp"
#include "rank_watchdog.hpp"

namespace parashade::distributed {

// Every rank leaves with this code after a failed step (rank 0 printed why).
struct RanksStopped {
  int code;
};

class MpiSession {
 public:
  // `rank_timeout`: seconds a rank may wait in one MPI call for the others before the watchdog ends the
  // whole job (0: never). A rank stopped (kill -STOP) or hung used to leave every other rank waiting forever.
  explicit MpiSession(double rank_timeout);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  MPI_Comm comm = MPI_COMM_WORLD;
  int rank = 0, size = 1;
  int local_size = 1;       // ranks on this host
  int threads_per_rank = 1; // the host's cores / local_size (PoCL's and the host stages' threads)

  // Runs `f` on this rank, then agrees with every rank: when any failed, rank 0 prints each failing
  // rank's message ("rank R of N: ...") and every rank throws RanksStopped with the largest exit code.
  template <typename F>
  void step(F&& f) {
    int code = 0;
    std::string message;
    try {
      f();
    } catch (const Error& e) {
      code = int(e.code());
      message = e.what();
    } catch (const std::bad_alloc&) {
      code = int(ExitCode::bad_input);
      message = "out of host memory";
    } catch (const std::exception& e) {
      code = int(ExitCode::internal);
      message = std::string("internal error: ") + e.what();
    }
    agree(code, message);
  }

  // Runs `f`, a blocking MPI call, watched: when it waits longer than the rank timeout, the watchdog prints
  // "rank R of N waited S s for the other ranks (--rank-timeout S) ..." and ends the job (MPI_Abort, exit 4).
  template <typename F>
  void collective(F&& f) {
    const Watched watched(watchdog_);
    f();
  }

 private:
  // While alive, this rank waits in MPI since the time it was made.
  struct Watched {
    explicit Watched(RankWatchdog& w) : w_(w) { w_.waiting(true); }
    ~Watched() { w_.waiting(false); }
    RankWatchdog& w_;
  };
  void agree(int code, const std::string& message);
  bool initialized_here_ = false;
  RankWatchdog watchdog_;
};

}  // namespace parashade::distributed
