#include "parashade/environment.hpp"

#include <cstdlib>
#include <regex>

#include "parashade/errors.hpp"
#include "parashade/memory_budget.hpp"

namespace parashade {
namespace {

// The variable's value, nullopt when unset or empty.
std::optional<std::string> value_of(const char* name) {
  const char* v = std::getenv(name);
  if (!v || !*v) return std::nullopt;
  return std::string(v);
}

// A whole number in [lo, hi] (digits only: no sign, no spaces, no unit), else a usage error naming it.
std::optional<long> integer_variable(const char* name, long lo, long hi, const std::string& meaning) {
  const std::optional<std::string> v = value_of(name);
  if (!v) return std::nullopt;
  if (std::regex_match(*v, std::regex("[0-9]{1,9}"))) {
    const long n = std::stol(*v);
    if (n >= lo && n <= hi) return n;
  }
  throw UsageError(std::string(name) + "='" + *v + "' is not " + meaning + ": a whole number from " + std::to_string(lo) +
                   " to " + std::to_string(hi) + " (unset it for the default)");
}

}  // namespace

std::optional<unsigned> host_threads_variable() {
  const auto n = integer_variable("PARASHADE_HOST_THREADS", 1, kMaxHostThreads, "a number of host threads");
  return n ? std::optional<unsigned>(unsigned(*n)) : std::nullopt;
}

int host_spin_variable() {
  return int(integer_variable("PARASHADE_HOST_SPIN_US", 0, 1000000, "a spin time in microseconds").value_or(0));
}

bool kernel_werror_variable() {
  const std::optional<std::string> v = value_of("PARASHADE_KERNEL_WERROR");
  if (!v || *v == "0") return false;
  if (*v == "1") return true;
  throw UsageError("PARASHADE_KERNEL_WERROR='" + *v + "' is not a switch: 1 (kernel build warnings are errors) or 0 "
                   "(unset it for the default, 0)");
}

void check_environment() {
  host_threads_variable();
  host_spin_variable();
  kernel_werror_variable();
  host_memory_limit();
}

}  // namespace parashade
