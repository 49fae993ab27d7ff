// test_program_binaries.cpp - the on-disk cache of program binaries: a
// variant built in one sampler is loaded from disk by the next, with the
// same bits; a stored file whose key or binary is damaged is not used (the
// program is built from source again, same bits); "off" writes nothing.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include <ggxcl/ggxcl.hpp>

#include "bit_compare.hpp"

namespace fs = std::filesystem;

namespace {

using ggxtest::same_bits;

// Environment variable `name` set to `value` for the life of the object.
struct ScopedEnv {
    ScopedEnv(const char* name, const std::string& value) : name(name)
    {
        const char* old = std::getenv(name);
        had_old = old != nullptr;
        saved = old ? old : "";
        ::setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv()
    {
        if (had_old)
            ::setenv(name, saved.c_str(), 1);
        else
            ::unsetenv(name);
    }
    const char* name;
    bool had_old = false;
    std::string saved;
};

struct CacheSetting : ScopedEnv {
    explicit CacheSetting(const std::string& value) : ScopedEnv("GGXCL_PROGRAM_CACHE", value) {}
};

fs::path fresh_dir(const std::string& tag)
{
    fs::path dir = fs::temp_directory_path() / ("ggx-binaries-" + tag + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    return dir;
}

std::vector<fs::path> files_in(const fs::path& dir)
{
    std::vector<fs::path> files;
    if (fs::exists(dir))
        for (const fs::directory_entry& e : fs::directory_iterator(dir))
            files.push_back(e.path());
    return files;
}

ggxcl::SampleSet draw(ggxcl::Sampler& sampler)
{
    ggxcl::SampleParams p;
    p.method = ggxcl::Method::heitz;
    p.alpha_x = 0.2f;
    p.alpha_y = 0.45f;
    p.view = ggxcl::view_from_angles(70, 10);
    return sampler.generate(p, {3, 100, 5000}, {ggxcl::Field::m, ggxcl::Field::pdf_o});
}

// Flips one byte at `offset` from the end of `file`.
void damage(const fs::path& file, std::uintmax_t offset_from_end)
{
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(std::streamoff(fs::file_size(file) - offset_from_end));
    char c = 0;
    f.read(&c, 1);
    f.seekp(std::streamoff(fs::file_size(file) - offset_from_end));
    c = char(c ^ 0x5a);
    f.write(&c, 1);
}

} // namespace

TEST_CASE("a program built once is loaded from disk by the next sampler, with the same bits")
{
    fs::path dir = fresh_dir("reuse");
    CacheSetting setting(dir.string());
    ggxcl::Sampler first;
    ggxcl::SampleSet built = draw(first);
    CHECK(first.programs_from_disk() == 0);
    REQUIRE(files_in(dir).size() == first.programs_built());
    ggxcl::Sampler second;  // another context: nothing shared in memory
    CHECK(same_bits(built, draw(second)));
    CHECK(second.programs_from_disk() == second.programs_built());
    CHECK(second.programs_built() >= 1);
    fs::remove_all(dir);
}

TEST_CASE("a damaged or foreign cache file is not used; the program is rebuilt from source")
{
    fs::path dir = fresh_dir("damaged");
    CacheSetting setting(dir.string());
    ggxcl::SampleSet built;
    {
        ggxcl::Sampler first;
        built = draw(first);
    }
    std::vector<fs::path> files = files_in(dir);
    REQUIRE(!files.empty());
    SUBCASE("the key stored in the file differs from the one asked for")
    {
        for (const fs::path& f : files) {
            std::fstream s(f, std::ios::in | std::ios::out | std::ios::binary);
            s.seekp(30);  // inside the stored key, past the magic line
            s.put('#');
        }
        ggxcl::Sampler again;
        CHECK(same_bits(built, draw(again)));
        CHECK(again.programs_from_disk() == 0);
    }
    SUBCASE("the binary is cut short")
    {
        for (const fs::path& f : files)
            fs::resize_file(f, fs::file_size(f) - 100);
        ggxcl::Sampler again;
        CHECK(same_bits(built, draw(again)));
        CHECK(again.programs_from_disk() == 0);
    }
    SUBCASE("the binary's bytes are changed")
    {
        for (const fs::path& f : files)
            damage(f, fs::file_size(f) / 3);
        ggxcl::Sampler again;
        CHECK(same_bits(built, draw(again)));
        CHECK(again.programs_from_disk() == 0);
    }
    fs::remove_all(dir);
}

TEST_CASE("by default the cache is under XDG_CACHE_HOME for platforms without their own; off keeps it out")
{
    fs::path root = fresh_dir("default");
    ScopedEnv xdg("XDG_CACHE_HOME", root.string());
    {
        CacheSetting unset("");  // an empty value means the default: platforms without a cache of their own
        ggxcl::Sampler warm;
        draw(warm);
        const std::string platform = cl::Platform(warm.device().getInfo<CL_DEVICE_PLATFORM>()).getInfo<CL_PLATFORM_NAME>();
        const bool own_cache = platform == "Portable Computing Language" || platform.find("NVIDIA") != std::string::npos;
        CAPTURE(platform);
        CHECK(files_in(root / "ggxcl" / "programs").empty() == own_cache);
        ggxcl::Sampler reuse;
        draw(reuse);
        CHECK((reuse.programs_from_disk() >= 1) == !own_cache);
    }
    {
        CacheSetting off("off");
        ggxcl::Sampler sampler;
        draw(sampler);
        CHECK(sampler.programs_from_disk() == 0);
    }
    fs::remove_all(root);
}
