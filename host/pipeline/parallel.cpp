#include "parashade/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "parashade/environment.hpp"

namespace parashade {
namespace {

// How long an idle worker (and run() waiting for the workers) spins before blocking, in µs:
// PARASHADE_HOST_SPIN_US if set, else 0 (block at once). Spinning 20 or 50 µs did not pay on the 2-core
// VM with PoCL's 2 compute units: teapot/bunny host stages 1.31/3.82 ms without, 1.62/4.43 ms with 50 µs
// (6 interleaved rounds, quiet).
int spin_microseconds() {
  static const int us = host_spin_variable();
  return us;
}

class Pool {
 public:
  explicit Pool(unsigned threads) {
    for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this] { work(); });
  }
  ~Pool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (auto& w : workers_) w.join();
  }

  void run(std::size_t count, const std::function<void(std::size_t)>& body) {
    if (workers_.empty() || count < 2) {
      for (std::size_t i = 0; i < count; ++i) body(i);
      return;
    }
    std::lock_guard<std::mutex> one_job(job_mutex_);  // one parallel_for at a time
    bool wake;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      body_ = &body;
      count_ = count;
      next_.store(0, std::memory_order_relaxed);
      error_ = nullptr;
      busy_.store(workers_.size(), std::memory_order_relaxed);
      resting_.store(false, std::memory_order_relaxed);
      generation_.fetch_add(1, std::memory_order_release);  // a spinning worker starts here
      wake = sleeping_ > 0;
    }
    if (wake) wake_.notify_all();
    drain();
    // The workers finish their last items about now: spin a little before blocking.
    if (!spin_until([this] { return busy_.load(std::memory_order_acquire) == 0; })) {
      std::unique_lock<std::mutex> lock(mutex_);
      done_waiting_ = true;
      done_.wait(lock, [this] { return busy_.load(std::memory_order_acquire) == 0; });
      done_waiting_ = false;
    }
    body_ = nullptr;
    if (error_) std::rethrow_exception(error_);
  }

  void rest() { resting_.store(true, std::memory_order_relaxed); }

 private:
  // Calls ready() for up to kSpin; true once it holds. Spinning stays short: PoCL's kernel threads
  // run on the same cores, and a frame's successive parallel_for calls come within a few µs.
  template <typename Ready>
  static bool spin_until(Ready ready) {
    if (ready()) return true;
    const int us = spin_microseconds();
    if (us == 0) return false;
    const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(us);
    for (unsigned i = 1;; ++i) {
      for (int k = 0; k < 16; ++k) {
        if (ready()) return true;
        pause();
      }
      if ((i & 7) == 0 && std::chrono::steady_clock::now() >= until) return ready();
    }
  }
  static void pause() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }

  void drain() {
    for (std::size_t i; (i = next_.fetch_add(1)) < count_;) {
      try {
        (*body_)(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!error_) error_ = std::current_exception();
        next_.store(count_);
      }
    }
  }

  void work() {
    std::uint64_t seen = 0;
    for (;;) {
      if (!spin_until([&] { return generation_.load(std::memory_order_acquire) != seen || resting_.load(std::memory_order_relaxed); }) ||
          generation_.load(std::memory_order_acquire) == seen) {
        std::unique_lock<std::mutex> lock(mutex_);
        ++sleeping_;
        wake_.wait(lock, [&] { return stop_ || generation_.load(std::memory_order_relaxed) != seen; });
        --sleeping_;
      }
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stop_) return;
        seen = generation_.load(std::memory_order_relaxed);
      }
      drain();
      if (busy_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (done_waiting_) done_.notify_one();
      }
    }
  }

  std::vector<std::thread> workers_;
  std::mutex job_mutex_, mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(std::size_t)>* body_ = nullptr;
  std::size_t count_ = 0;
  std::atomic<std::size_t> next_{0};
  std::atomic<std::size_t> busy_{0};
  std::atomic<std::uint64_t> generation_{0};
  std::atomic<bool> resting_{false};  // rest(): idle workers block at once instead of spinning
  unsigned sleeping_ = 0;      // workers blocked on wake_ (under mutex_)
  bool done_waiting_ = false;  // run() blocked on done_ (under mutex_)
  bool stop_ = false;
  std::exception_ptr error_;
};

unsigned default_threads() {
  if (const std::optional<unsigned> n = host_threads_variable()) return *n;
  return std::max(1u, std::thread::hardware_concurrency());
}

unsigned chosen_threads = 0;  // 0: default_threads()
std::unique_ptr<Pool> the_pool;
// The first parallel_for calls may come from several threads at once (SplitRenderer's devices): the
// pool is made under a lock, else two are made and one is destroyed while the other thread uses it.
std::mutex pool_mutex;

Pool& pool() {
  std::lock_guard<std::mutex> lock(pool_mutex);
  if (!the_pool) the_pool = std::make_unique<Pool>(host_threads());
  return *the_pool;
}

}  // namespace

unsigned host_threads() { return chosen_threads ? chosen_threads : default_threads(); }

void set_host_threads(unsigned threads) {
  std::lock_guard<std::mutex> lock(pool_mutex);
  chosen_threads = std::max(1u, threads);
  the_pool.reset();
}

void parallel_for(std::size_t count, const std::function<void(std::size_t)>& body) { pool().run(count, body); }

void parallel_rest() {
  std::lock_guard<std::mutex> lock(pool_mutex);
  if (the_pool) the_pool->rest();
}

}  // namespace parashade
