// scratch.hpp - scratch folders of a test process under the system's
// temporary folder, removed with their contents when the process exits, and
// reading a file back whole.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace ggxtest {

namespace fs = std::filesystem;

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
// `tag`, removed with everything in it when the process exits.
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
