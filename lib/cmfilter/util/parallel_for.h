// SPDX-License-Identifier: Apache-2.0
// A minimal static-schedule parallel loop over [0, count) on std::thread.
// threads <= 0 uses every core this process may use (available_cores.h:
// its affinity mask and cgroup quota); threads == 1 runs inline.
#pragma once

#include "cmfilter/util/available_cores.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace cmfilter {

inline int resolve_thread_count(int threads)
{
    if (threads > 0) return threads;
    return available_cores();
}

template <typename Body>
void parallel_for(int count, int threads, Body&& body)
{
    const int n = std::min(resolve_thread_count(threads), std::max(count, 1));
    if (n <= 1) {
        for (int i = 0; i < count; ++i) body(i);
        return;
    }
    std::atomic<int> next{0};
    auto worker = [&] {
        for (int i = next++; i < count; i = next++) body(i);
    };
    std::vector<std::thread> pool;
    pool.reserve(n - 1);
    for (int t = 0; t < n - 1; ++t) pool.emplace_back(worker);
    worker();
    for (auto& th : pool) th.join();
}

}  // namespace cmfilter
