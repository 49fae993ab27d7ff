// scratch.hpp - scratch folders under the system's temporary folder: one of
// a test case's own (ScratchFolder: created fresh, removed with everything in
// it when the case ends, passed or failed), one per process and tag
// (scratch_dir: removed when the process exits), and reading a file back
// whole.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

namespace ggxtest {

namespace fs = std::filesystem;

// A folder of one test case's own: made empty when constructed, removed with
// its contents when destroyed (the case returns, or a REQUIRE throws).  The
// innermost one alive is `current()`, for helpers that write beside the case.
//   TEST_CASE("...") { const ggxtest::ScratchFolder scratch("cli"); ... scratch / "out.npy" ... }
class ScratchFolder {
public:
    explicit ScratchFolder(const std::string& tag) : outer_(innermost())
    {
        static int made = 0;
        dir_ = fs::temp_directory_path() /
               ("ggx-" + tag + "-test-" + std::to_string(::getpid()) + "-" + std::to_string(++made));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        innermost() = this;
    }
    ~ScratchFolder()
    {
        innermost() = outer_;
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;

    const fs::path& path() const { return dir_; }
    fs::path operator/(const fs::path& name) const { return dir_ / name; }

    // The innermost scratch folder alive; throws when there is none.
    static const fs::path& current()
    {
        if (!innermost())
            throw std::logic_error("no ggxtest::ScratchFolder alive: make one at the start of the test case");
        return innermost()->dir_;
    }

private:
    static ScratchFolder*& innermost()
    {
        static ScratchFolder* folder = nullptr;
        return folder;
    }

    fs::path dir_;
    ScratchFolder* outer_;
};

// The scratch folders of this process, removed when it exits.
struct ScratchFolders {
    std::vector<fs::path> made;
    ~ScratchFolders()
    {
        for (const fs::path& dir : made) {
            std::error_code ignored;
            fs::remove_all(dir, ignored);
        }
    }
};

// A folder under the system's temporary one, unique to this process and
// `tag`, removed with everything in it when the process exits.  Cases that
// share a tag share the folder: a case of its own takes a ScratchFolder.
inline fs::path scratch_dir(const std::string& tag)
{
    static ScratchFolders folders;
    fs::path dir = fs::temp_directory_path() / ("ggx-" + tag + "-test-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    folders.made.push_back(dir);
    return dir;
}

inline std::string read_all(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace ggxtest
