// The rank watchdog (rank_watchdog.hpp).
#include "rank_watchdog.hpp"

#include <pthread.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "parashade/errors.hpp"

namespace parashade::distributed {
namespace {

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

void RankWatchdog::start(MPI_Comm comm, int rank, int size, double seconds) {
  if (!(seconds > 0) || thread_.joinable()) return;
  comm_ = comm, rank_ = rank, size_ = size, seconds_ = seconds;
  thread_ = std::thread([this] { watch(); });
  // Named, so a test (tests/mpi/mpi_test.py) sees from /proc when the watching has begun.
  pthread_setname_np(thread_.native_handle(), "rank-watchdog");
}

void RankWatchdog::stop() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void RankWatchdog::waiting(bool in_call) { since_ns_.store(in_call ? std::max<std::int64_t>(1, now_ns()) : 0); }

void RankWatchdog::watch() {
  // Looks a few times per timeout (at most every second), so a wait ends within about 1.25 timeouts.
  const auto period = std::chrono::duration<double>(std::min(1.0, seconds_ / 4));
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, period, [this] { return stopping_; })) {
    const std::int64_t since = since_ns_.load();
    if (since == 0) continue;
    const double waited = double(now_ns() - since) * 1e-9;
    if (waited > seconds_) end_job(waited);
  }
}

void RankWatchdog::end_job(double waited) const {
  std::fprintf(stderr,
               "parashade: error: rank %d of %d waited %.0f s in MPI for the other ranks (--rank-timeout %g): a rank is "
               "stopped or hung; ending the job\n",
               rank_, size_, waited, seconds_);
  // From this thread while the main one waits in MPI: MPI_Abort only asks the runtime to end every rank.
  MPI_Abort(comm_, int(ExitCode::device));
  std::_Exit(int(ExitCode::device));
}

}  // namespace parashade::distributed
