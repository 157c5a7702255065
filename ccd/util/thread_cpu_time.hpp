#pragma once
// CPU time of the calling thread (POSIX CLOCK_THREAD_CPUTIME_ID), in seconds since an
// unspecified start: only differences mean something. Unlike wall-clock time it does not
// count the time the thread waits for a core, so measurements of small runs stay
// meaningful on a loaded machine (the runner's `cpu_seconds`). Work done on other
// threads is not counted. Returns 0 when the clock is unavailable.
namespace ccd {

double thread_cpu_seconds();

}  // namespace ccd
