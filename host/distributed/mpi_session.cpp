#include "mpi_session.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <thread>
#include <vector>

namespace parashade::distributed {
namespace {

void set_default_env(const char* name, const std::string& value) {
  if (!std::getenv(name)) setenv(name, value.c_str(), 1);
}

// Whether a launcher started this process as a rank: the variables Open MPI's mpirun, MPICH's Hydra
// (mpiexec) and PMIx or PMI (srun) give every rank. Read before MPI_Init: a singleton's init may set some.
bool started_by_launcher() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMI_RANK", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(v)) return true;
  return false;
}

}  // namespace

MpiSession::MpiSession(double rank_timeout) {
  const bool launched = started_by_launcher();
  int ready = 0;
  MPI_Initialized(&ready);
  if (!ready) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    initialized_here_ = true;
  }
  MPI_Comm_set_errhandler(comm, MPI_ERRORS_ARE_FATAL);
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  // Outside mpirun the job is one rank: the distributed path (MPI start-up, compositing, the rank
  // protocol) for nothing, several times slower than the command without --distribute or --mpi.
  if (size == 1 && !launched)
    std::cerr << "parashade: warning: not started by mpirun: --distribute and --mpi run as a single MPI rank, "
                 "several times slower than without them; start 'mpirun -np N parashade ...' for N ranks "
                 "(docs/distributed.md)\n";
  MPI_Comm local;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &local);
  MPI_Comm_size(local, &local_size);
  MPI_Comm_free(&local);
  // Ranks on one host share its cores: each gets its part for PoCL's workers and the host stages, and
  // PoCL's pinning (docs/pipeline.md) is off, or every rank would pin its workers to the same cores.
  // Before the first OpenCL call; the environment's own settings win.
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  threads_per_rank = std::max(1, int(cores) / std::max(1, local_size));
  set_default_env("POCL_MAX_PTHREAD_COUNT", std::to_string(threads_per_rank));
  set_default_env("PARASHADE_HOST_THREADS", std::to_string(threads_per_rank));
  if (local_size > 1) set_default_env("POCL_AFFINITY", "0");
  watchdog_.start(comm, rank, size, rank_timeout);
}

MpiSession::~MpiSession() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (initialized_here_ && !finalized) collective([] { MPI_Finalize(); });  // waits for every rank
  watchdog_.stop();
}

void MpiSession::agree(int code, const std::string& message) {
  int worst = 0;
  collective([&] { MPI_Allreduce(&code, &worst, 1, MPI_INT, MPI_MAX, comm); });
  if (worst == 0) return;
  // Every rank's message to rank 0 (a fixed-size slot each), which prints one line per distinct cause.
  constexpr int kSlot = 2048;
  std::vector<char> mine(kSlot, '\0');
  if (code != 0) std::strncpy(mine.data(), message.empty() ? "failed" : message.c_str(), kSlot - 1);
  std::vector<char> all(rank == 0 ? std::size_t(kSlot) * size : 0);
  collective([&] { MPI_Gather(mine.data(), kSlot, MPI_CHAR, all.data(), kSlot, MPI_CHAR, 0, comm); });
  if (rank == 0) {
    std::vector<std::pair<std::string, std::vector<int>>> causes;
    for (int r = 0; r < size; ++r) {
      const std::string m(&all[std::size_t(r) * kSlot]);
      if (m.empty()) continue;
      auto it = std::find_if(causes.begin(), causes.end(), [&](const auto& c) { return c.first == m; });
      if (it == causes.end()) causes.push_back({m, {r}});
      else it->second.push_back(r);
    }
    for (const auto& [m, ranks] : causes) {
      std::string who = ranks.size() == 1 ? "rank " : "ranks ";
      for (std::size_t i = 0; i < ranks.size(); ++i) who += (i ? ", " : "") + std::to_string(ranks[i]);
      std::cerr << "parashade: error: " << who << " of " << size << ": " << m << "\n";
    }
    std::cerr << "parashade: every rank stopped; nothing written\n";
  }
  throw RanksStopped{worst};
}

}  // namespace parashade::distributed
