#pragma once
// The watchdog of one MPI rank (issue 46, item 11): a thread that ends the whole job when this rank has
// waited in one MPI call longer than the rank timeout (--rank-timeout SECONDS: render --distribute, default
// 600; tune --mpi and scaling --mpi, default 0, off). A rank stopped by kill -STOP, or hung, used to leave every
// other rank waiting in a collective forever; mpirun never ended.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>

#include <mpi.h>

namespace parashade::distributed {

class RankWatchdog {
 public:
  RankWatchdog() = default;
  ~RankWatchdog() { stop(); }
  RankWatchdog(const RankWatchdog&) = delete;
  RankWatchdog& operator=(const RankWatchdog&) = delete;

  // Starts watching (after MPI_Init): seconds 0 or less watches nothing.
  void start(MPI_Comm comm, int rank, int size, double seconds);
  void stop();
  // The main thread enters (true) or leaves (false) a blocking MPI call.
  void waiting(bool in_call);

 private:
  void watch();
  [[noreturn]] void end_job(double waited) const;

  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0, size_ = 1;
  double seconds_ = 0;
  std::atomic<std::int64_t> since_ns_{0};  // steady clock when the current wait began; 0: not waiting
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace parashade::distributed
