#pragma once
// A level's passes split into one contiguous block per thread, on threads of the standard
// library started for one refinement (core depends on Eigen and the standard library only).
// The streaming drivers compute every element of a pass by the same operations in the same
// order whatever the split, so a refinement gives the same bits on one thread as on many; only
// where the blocks start changes.

#include <atomic>
#include <barrier>
#include <cstddef>
#include <exception>
#include <functional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "crossdiv/error.h"

namespace crossdiv::detail {

class ParallelBlocks {
public:
    /// Starts `threads` - 1 workers, which wait (blocked, not spinning) for each run().
    /// @throws InputError when `threads` < 1.
    explicit ParallelBlocks(int threads)
        : threads_(check(threads)), start_(threads), done_(threads) {
        for (int id = 1; id < threads; ++id) workers_.emplace_back([this, id] { work(static_cast<size_t>(id)); });
    }
    ~ParallelBlocks() {
        if (workers_.empty()) return;
        stop_ = true;
        start_.arrive_and_wait();
        for (std::thread& t : workers_) t.join();
    }
    ParallelBlocks(const ParallelBlocks&) = delete;
    ParallelBlocks& operator=(const ParallelBlocks&) = delete;

    /// How many blocks a pass over n elements is cut into: one per thread, and one when n is
    /// below kMinParallel (waking the workers would cost more than the pass).
    size_t blocks(size_t n) const { return workers_.empty() || n < kMinParallel ? 1 : static_cast<size_t>(threads_); }

    /// f(b) for b = 0 .. blocks - 1, block b on thread b mod threads, all at once (in turn when
    /// one). Waking the workers costs tens of microseconds on a virtual machine, so a driver
    /// runs every independent pass of a level inside one call, each block taking its share of
    /// each (block_range). An exception in a block is rethrown here once every block is done.
    template <class F>
    void run(size_t blocks, F&& f) {
        if (blocks <= 1 || workers_.empty()) {
            for (size_t b = 0; b < blocks; ++b) f(b);
            return;
        }
        job_ = [&f](size_t b) { f(b); };
        blocks_ = blocks;
        start_.arrive_and_wait();
        blocks_of(0);
        done_.arrive_and_wait();
        job_ = nullptr;
        for (std::exception_ptr& e : errors_)
            if (e) std::rethrow_exception(std::exchange(e, nullptr));
    }

    /// A pass on `blocks` threads cut into kChunksPerBlock chunks per block, handed out in turn
    /// (chunk(b, c, chunks) for every chunk c; b: the thread's block, for its scratch), beside a
    /// task that block 0 runs first (appending a result that one thread writes, say): taking
    /// chunks as it comes free, it takes fewer of them.
    template <class Task, class Chunk>
    void run_chunks_beside(size_t blocks, Task&& task, Chunk&& chunk) {
        const size_t chunks = kChunksPerBlock * blocks;
        std::atomic<size_t> next{0};
        run(blocks, [&](size_t b) {
            if (b == 0) task();
            for (size_t c; (c = next.fetch_add(1)) < chunks;) chunk(b, c, chunks);
        });
    }

    /// Block b of `blocks` equal blocks of [0, n).
    static std::pair<size_t, size_t> block_range(size_t n, size_t b, size_t blocks) {
        return {n * b / blocks, n * (b + 1) / blocks};
    }

private:
    static constexpr size_t kMinParallel = 8192;
    static constexpr size_t kChunksPerBlock = 8;

    static int check(int threads) {
        if (threads < 1) throw InputError("threads must be >= 1, got " + std::to_string(threads));
        return threads;
    }

    /// The blocks of thread `id`, an exception kept for run() to rethrow.
    void blocks_of(size_t id) {
        try {
            for (size_t b = id; b < blocks_; b += static_cast<size_t>(threads_)) job_(b);
        } catch (...) {
            errors_[id] = std::current_exception();
        }
    }

    void work(size_t id) {
        for (;;) {
            start_.arrive_and_wait();  // the barrier orders the job's data before the work
            if (stop_) return;
            blocks_of(id);
            done_.arrive_and_wait();  // and the work before the caller reads its results
        }
    }

    int threads_;
    std::barrier<> start_, done_;
    std::vector<std::thread> workers_;
    std::function<void(size_t)> job_;
    size_t blocks_ = 0;
    bool stop_ = false;
    std::vector<std::exception_ptr> errors_ = std::vector<std::exception_ptr>(static_cast<size_t>(threads_));
};

}  // namespace crossdiv::detail
