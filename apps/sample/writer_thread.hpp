// writer_thread.hpp - a SampleWriter's appends moved to a thread of their
// own, so that the device draws and the host converts the next chunk while
// the previous one is written.  At most two chunks wait; their buffers come
// back for reuse, so a long run allocates two buffers in all.  An error of
// the writer is rethrown by the next call here (append, finish).
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "sample_writer.hpp"

namespace ggxapp {

class WriterThread {
public:
    explicit WriterThread(SampleWriter& writer);
    ~WriterThread();  // stops the thread; what is still queued is dropped

    // A buffer to fill with rows: a returned one when there is one.
    std::vector<float> take_buffer();
    // Queues rows (row-major) for writing, in call order; waits while two are queued.
    void append(std::vector<float> rows);
    // Waits until everything queued is written.
    void finish();

private:
    void run();
    void rethrow_error();

    SampleWriter& writer_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<std::vector<float>> queued_;
    std::vector<std::vector<float>> spare_;
    bool writing_ = false, stopping_ = false;
    std::exception_ptr error_;
    std::thread thread_;
};

} // namespace ggxapp
