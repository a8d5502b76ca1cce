#pragma once
// The environment variables that tune parashade's host (docs/environment.md), read and checked in one
// place: a value that is set but not of the variable's form is a usage error (exit 2) naming the variable,
// its value and what it takes, never ignored. Unset or empty: the default.
#include <optional>
#include <string>

namespace parashade {

// PARASHADE_HOST_THREADS: the host stages' threads, a whole number from 1 to kMaxHostThreads.
constexpr long kMaxHostThreads = 1024;
std::optional<unsigned> host_threads_variable();

// PARASHADE_HOST_SPIN_US: how long an idle host worker spins before it blocks, 0 to 1000000 µs (default 0).
int host_spin_variable();

// PARASHADE_KERNEL_WERROR: 1 turns kernel build warnings into errors, 0 (the default) does not.
bool kernel_werror_variable();

// Every variable above and PARASHADE_MEMORY_LIMIT (memory_budget.hpp), checked at once: the command line
// calls this before any work, so that a bad value stops every command alike, before a scene is read.
void check_environment();

}  // namespace parashade
