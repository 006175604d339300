// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_PARALLEL_PARTS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_PARALLEL_PARTS_H

// Loops split into consecutive parts, run on the standard library's threads when the caller
// asks for CGAL::Parallel_tag. The parts are fixed by the caller, not by the number of
// threads, so that a sum taken part by part and then over the parts in order gives the same
// result on every machine, with one thread or many.

#include <CGAL/tags.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <future>
#include <system_error>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The threads a loop may use: one for CGAL::Sequential_tag, the hardware's for
// CGAL::Parallel_tag (at least one).
template <typename ConcurrencyTag>
unsigned thread_count()
{
  static_assert(std::is_same<ConcurrencyTag, CGAL::Sequential_tag>::value ||
                    std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "the concurrency tag is CGAL::Sequential_tag or CGAL::Parallel_tag");
  if(std::is_same<ConcurrencyTag, CGAL::Sequential_tag>::value)
    return 1;
  return std::max(1u, std::thread::hardware_concurrency());
}

// Part `part` of [0, count) split into `parts` consecutive ranges of sizes differing by at most one.
inline std::pair<std::size_t, std::size_t> part_range(std::size_t count, std::size_t parts, std::size_t part)
{
  auto bound = [&](std::size_t p) { return count / parts * p + count % parts * p / parts; };
  return {bound(part), bound(part + 1)};
}

// Calls body(part, begin, end) for each of the `parts` consecutive ranges of [0, count), on
// up to `threads` threads (the caller's among them), each part once. When parts throw, the
// exception of the first of them (by part) is rethrown once all parts are done.
template <typename Body>
void for_each_part(std::size_t count, std::size_t parts, unsigned threads, const Body& body)
{
  parts = std::max<std::size_t>(parts, 1);
  std::vector<std::exception_ptr> failure(parts);
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for(std::size_t part; (part = next.fetch_add(1)) < parts;)
    {
      try
      {
        const auto [begin, end] = part_range(count, parts, part);
        body(part, begin, end);
      }
      catch(...)
      {
        failure[part] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> helpers;
  const std::size_t helper_count = std::min<std::size_t>(parts, threads) - 1;
  try
  {
    for(std::size_t t = 0; t < helper_count; ++t)
      helpers.emplace_back(work);
  }
  catch(const std::system_error&) // no more threads: the ones started and the caller do it all
  {
  }
  work();
  for(std::thread& helper : helpers)
    helper.join();
  for(const std::exception_ptr& e : failure)
    if(e)
      std::rethrow_exception(e);
}

// The parts a loop over `count` independent indices is split into: one per thread, or one
// alone when the loop is too short to pay for starting threads.
inline std::size_t index_parts(std::size_t count, unsigned threads)
{
  return threads <= 1 || count < 4096 ? 1 : std::size_t(threads);
}

// Calls f(i) for every i in [0, count), on up to `threads` threads, a range of indices each.
// f must write nothing that another index writes.
template <typename Function>
void for_each_index(std::size_t count, unsigned threads, const Function& f)
{
  for_each_part(count, index_parts(count, threads), threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    for(std::size_t i = begin; i < end; ++i)
      f(i);
  });
}

// Starts f() beside the caller's work: on a thread of its own when `threads` allows more
// than one (and one can be started), otherwise when the result is asked for. The future's
// get() waits for f, gives what it returned and rethrows what it threw.
template <typename Function>
std::future<std::invoke_result_t<Function>> start_beside(unsigned threads, Function f)
{
  if(threads > 1)
    try
    {
      return std::async(std::launch::async, std::move(f));
    }
    catch(const std::system_error&) // no thread to start: f runs when asked for
    {
    }
  return std::async(std::launch::deferred, std::move(f));
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_PARALLEL_PARTS_H
