// multi_device.cpp - generate_split: parallel producers, one in-order
// consumer.  The request is validated before the producers start, so that a
// bad one throws before any thread runs; they draw their chunks through the
// public Sampler::generate.
#include "ggxcl/multi_device.hpp"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <map>
#include <mutex>
#include <thread>

#include "ggxcl/error.hpp"
#include "validated_params.hpp"

namespace ggxcl {

namespace {

// Chunks finished by the producers, handed to the consumer in index order.
class ChunkQueue {
public:
    explicit ChunkQueue(std::uint64_t window) : window_(window) {}

    // Blocks while chunk `k` would run more than `window` chunks ahead of the consumer.
    bool wait_for_room(std::uint64_t k)
    {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [&] { return failed_ || k < next_ + window_; });
        return !failed_;
    }

    void put(std::uint64_t k, SampleSet chunk)
    {
        std::lock_guard<std::mutex> lock(mutex_);
        ready_.emplace(k, std::move(chunk));
        changed_.notify_all();
    }

    void fail(std::exception_ptr error)
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!failed_)
            error_ = error;
        failed_ = true;
        changed_.notify_all();
    }

    // The next chunk in order; rethrows a producer's error.
    SampleSet take()
    {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [&] { return failed_ || ready_.count(next_); });
        if (failed_)
            std::rethrow_exception(error_);
        SampleSet chunk = std::move(ready_[next_]);
        ready_.erase(next_++);
        changed_.notify_all();
        return chunk;
    }

private:
    std::mutex mutex_;
    std::condition_variable changed_;
    std::map<std::uint64_t, SampleSet> ready_;
    std::uint64_t next_ = 0, window_;
    bool failed_ = false;
    std::exception_ptr error_;
};

} // namespace

void generate_split(const std::vector<Sampler*>& samplers, const SampleParams& params, const SampleRange& range,
                    FieldSet fields, const Sampler::ChunkSink& sink, std::uint64_t chunk_size)
{
    if (samplers.empty())
        throw InvalidArgument("samplers", "none", "at least one sampler");
    if (chunk_size == 0)
        throw InvalidArgument("chunk size", "0", "at least 1 sample");
    detail::validated_request(params, range, fields, {});
    const std::uint64_t chunks = (range.count + chunk_size - 1) / chunk_size;
    ChunkQueue queue(2 * samplers.size());
    std::vector<std::thread> producers;
    for (std::size_t s = 0; s < samplers.size(); ++s)
        producers.emplace_back([&, s] {
            try {
                for (std::uint64_t k = s; k < chunks && queue.wait_for_room(k); k += samplers.size()) {
                    std::uint64_t start = k * chunk_size, n = std::min(chunk_size, range.count - start);
                    const SampleRange chunk{range.seed, range.first + start, n};
                    queue.put(k, samplers[s]->generate(params, chunk, fields));
                }
            } catch (...) {
                queue.fail(std::current_exception());
            }
        });
    try {
        for (std::uint64_t k = 0; k < chunks; ++k)
            sink(queue.take(), k * chunk_size);
    } catch (...) {
        queue.fail(std::current_exception());
        for (std::thread& t : producers)
            t.join();
        throw;
    }
    for (std::thread& t : producers)
        t.join();
}

} // namespace ggxcl
