// atomic_file.hpp - an output file written under a temporary name in the
// same folder and renamed onto its final name only when commit() is called,
// so no half-written file ever carries the final name.
#pragma once

#include <cstdio>
#include <string>

namespace ggxapp {

class AtomicFile {
public:
    // Opens "<path>.tmp-<pid>" for writing; throws std::runtime_error naming the path.
    explicit AtomicFile(std::string path);
    ~AtomicFile();  // removes the temporary file unless committed
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    void write(const void* data, std::size_t bytes);
    void commit();  // flush, close and rename onto the final path
    const std::string& path() const { return path_; }

private:
    std::string path_, temp_path_;
    std::FILE* file_ = nullptr;
};

// Writes `text` to `path` through an AtomicFile.
void write_text_file(const std::string& path, const std::string& text);

// Makes an interrupted or aborted run (SIGINT, SIGTERM, SIGHUP, SIGABRT) remove the temporary
// files of the AtomicFiles still open before it ends with that signal (and
// so does a library that calls exit() mid-run), and
// makes a write past the file-size limit fail with EFBIG (an error message)
// rather than kill the process (SIGXFSZ).  Called once by main().
void install_interrupt_cleanup();

} // namespace ggxapp
