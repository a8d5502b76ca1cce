#include "parashade/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace parashade {
namespace {

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
    {
      std::lock_guard<std::mutex> lock(mutex_);
      body_ = &body;
      count_ = count;
      next_.store(0);
      error_ = nullptr;
      busy_ = workers_.size();
      ++generation_;
    }
    wake_.notify_all();
    drain();
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return busy_ == 0; });
    body_ = nullptr;
    if (error_) std::rethrow_exception(error_);
  }

 private:
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
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
        if (stop_) return;
        seen = generation_;
      }
      drain();
      std::lock_guard<std::mutex> lock(mutex_);
      if (--busy_ == 0) done_.notify_one();
    }
  }

  std::vector<std::thread> workers_;
  std::mutex job_mutex_, mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(std::size_t)>* body_ = nullptr;
  std::size_t count_ = 0;
  std::atomic<std::size_t> next_{0};
  std::size_t busy_ = 0;
  std::uint64_t generation_ = 0;
  bool stop_ = false;
  std::exception_ptr error_;
};

unsigned default_threads() {
  if (const char* env = std::getenv("PARASHADE_HOST_THREADS")) {
    const int n = std::atoi(env);
    if (n >= 1) return unsigned(n);
  }
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

}  // namespace parashade
