// writer_thread.cpp - SampleWriter appends on a thread (see writer_thread.hpp).
#include "writer_thread.hpp"

namespace ggxapp {

WriterThread::WriterThread(SampleWriter& writer) : writer_(writer), thread_([this] { run(); }) {}

WriterThread::~WriterThread()
{
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
        queued_.clear();
    }
    changed_.notify_all();
    thread_.join();
}

std::vector<float> WriterThread::take_buffer()
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (spare_.empty())
        return {};
    std::vector<float> buffer = std::move(spare_.back());
    spare_.pop_back();
    return buffer;
}

void WriterThread::append(std::vector<float> rows)
{
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return queued_.size() < 2 || error_; });
    rethrow_error();
    queued_.push_back(std::move(rows));
    changed_.notify_all();
}

void WriterThread::finish()
{
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return (queued_.empty() && !writing_) || error_; });
    rethrow_error();
}

void WriterThread::rethrow_error()
{
    if (error_)
        std::rethrow_exception(error_);
}

void WriterThread::run()
{
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return !queued_.empty() || stopping_; });
        if (stopping_)
            return;
        std::vector<float> rows = std::move(queued_.front());
        queued_.pop_front();
        writing_ = true;
        lock.unlock();
        std::exception_ptr failure;
        try {
            writer_.append(rows);
        } catch (...) {
            failure = std::current_exception();
        }
        lock.lock();
        writing_ = false;
        spare_.push_back(std::move(rows));
        if (failure) {
            error_ = failure;
            queued_.clear();
        }
        changed_.notify_all();
    }
}

} // namespace ggxapp
