#pragma once
/// \file interrupt.hpp
/// Stopping a long computation from outside. The core's long loops (increments of a path,
/// Newton and MGDCM iterations, energy minimisation, iterative kinematics) call
/// `check_interrupt()` once per pass. A host installs the check: the Python module's runs
/// Python's signal handlers, so Ctrl-C stops a solver call with KeyboardInterrupt. The check
/// reports an interrupt by throwing (any exception); the core is exception-safe, so the
/// call unwinds and nothing of it is kept. Without a check installed (C++ programs, the
/// unit tests) `check_interrupt()` does nothing.

#include <atomic>
#include <chrono>

namespace kresling {

/// A host's check: returns normally, or throws to stop the computation.
using InterruptCheck = void (*)();

namespace detail {
inline std::atomic<InterruptCheck> interrupt_check{nullptr};
}  // namespace detail

/// Install `check` (nullptr: none). The check may be called from any thread that runs the
/// core, at most about every 10 ms per thread.
inline void set_interrupt_check(InterruptCheck check) { detail::interrupt_check.store(check); }

/// Call the installed check, unless this thread called it less than 10 ms ago (a check
/// may take a lock, the Python one takes the GIL; a loop pass may take microseconds).
inline void check_interrupt() {
  const InterruptCheck check = detail::interrupt_check.load(std::memory_order_relaxed);
  if (check == nullptr) return;
  thread_local std::chrono::steady_clock::time_point next{};
  const auto now = std::chrono::steady_clock::now();
  if (now < next) return;
  next = now + std::chrono::milliseconds(10);
  check();
}

}  // namespace kresling
