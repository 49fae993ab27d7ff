// test_faults.cpp - runtime faults of the `ggx` tool: each gets a
// clear message on stderr, exit status 1 (or the signal that stopped it),
// and leaves no file behind, neither under the final name nor as a
// temporary:
//  - no OpenCL platform at all (the ICD loader pointed at an empty folder):
//    the message says how to install PoCL; platforms without a device
//    (Mesa's alone): how to enable rusticl or install PoCL (skipped where
//    Mesa's or PoCL's ICD is not installed);
//  - the disk fills up (a file-size limit, RLIMIT_FSIZE, below the output):
//    "File too large", no partial file;
//  - an interrupted run (SIGINT while sampling): no file, temporary removed;
//  - a lost device mid-run (injected): the CL error, no file;
//  - device memory exhausted (injected): the same file as an undisturbed run.
// Each case works in a folder of its own (ggxtest::ScratchFolder).
#include <doctest/doctest.h>

#include <chrono>
#include <csignal>
#include <spawn.h>
#include <sys/resource.h>
#include <thread>
#include <vector>

#include "cli_runner.hpp"
#include "skip.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;

bool folder_empty(const fs::path& dir)
{
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename() != "stderr.txt")
            return false;
    return true;
}

// Where the installed ICDs are: the ICD loader's default folder, or
// $GGX_ICD_VENDORS_DIR (a machine that keeps them elsewhere; a test of the skip).
fs::path installed_icds()
{
    return ggxtest::path_from_env("GGX_ICD_VENDORS_DIR", "/etc/OpenCL/vendors");
}

// Copies those of the ICD files `names` that are installed into `to`; how many.
int copy_installed_icds(const std::vector<std::string>& names, const fs::path& to)
{
    int copied = 0;
    for (const std::string& name : names)
        if (fs::exists(installed_icds() / name)) {
            fs::copy_file(installed_icds() / name, to / name, fs::copy_options::overwrite_existing);
            ++copied;
        }
    return copied;
}

} // namespace

TEST_CASE("platforms without a device are skipped; with none that has one, the message says what to do")
{
    const ggxtest::ScratchFolder scratch("faults");
    // Mesa's two platforms alone: Clover lists no device without an AMD GPU,
    // rusticl none without RUSTICL_ENABLE.
    const fs::path vendors = scratch / "mesa-only";
    fs::create_directories(vendors);
    const std::string where = " in " + installed_icds().string();
    if (!ggxtest::skip_unless(copy_installed_icds({"mesa.icd", "rusticl.icd"}, vendors) > 0,
                              "needs Mesa's OpenCL ICDs (apt-get install mesa-opencl-icd)" + where) ||
        !ggxtest::skip_unless(fs::exists(installed_icds() / "pocl.icd"),
                              "needs PoCL's OpenCL ICD (apt-get install pocl-opencl-icd)" + where))
        return;
    // (No leak check in this child under ASan: Mesa's libraries leak when they are loaded.)
    const std::string env = "env -u RUSTICL_ENABLE ASAN_OPTIONS=detect_leaks=0 OCL_ICD_VENDORS=" + vendors.string();
    ggxtest::Run none = ggxtest::run_ggx(env + " " + ggxtest::ggx_binary() + " devices", scratch / "stderr.txt", false);
    CAPTURE(none.err);
    CHECK(none.status == 1);
    CHECK(none.err.find("no OpenCL platform has a device") != std::string::npos);
    CHECK(none.err.find("RUSTICL_ENABLE=llvmpipe") != std::string::npos);
    CHECK(none.err.find("pocl-opencl-icd") != std::string::npos);
    // With PoCL beside them the empty platforms are skipped without a word.
    copy_installed_icds({"pocl.icd"}, vendors);
    const fs::path listing = scratch / "devices.txt";
    ggxtest::Run some = ggxtest::run_ggx("{ " + env + " " + ggxtest::ggx_binary() + " devices >" + listing.string() +
                                             "; }",
                                         scratch / "stderr.txt", false);
    CAPTURE(some.err);
    CHECK(some.status == 0);
    CHECK(some.err.empty());
    const std::string text = ggxtest::read_all(listing);
    CHECK(text.find("Portable Computing Language") != std::string::npos);
    CHECK(text.find("OpenCL C 1.2") != std::string::npos);  // the versions and limits line
    CHECK(text.find("work-groups up to") != std::string::npos);
}

TEST_CASE("no OpenCL platform: exit 1 and a message that says how to install PoCL")
{
    const ggxtest::ScratchFolder scratch("faults");
    fs::path empty = scratch / "no-icd";
    fs::create_directories(empty);
    for (const std::string& args : {std::string("devices"),
                                    "sample --method caps -n 10 --out " + (scratch / "x.npy").string()}) {
        ggxtest::Run run = ggxtest::run_ggx(
            "env OCL_ICD_VENDORS=" + empty.string() + " " + ggxtest::ggx_binary() + " " + args, scratch / "stderr.txt",
            false);
        CAPTURE(args);
        CAPTURE(run.err);
        CHECK(run.status == 1);
        CHECK(run.err.find("no OpenCL platform") != std::string::npos);
        CHECK(run.err.find("pocl-opencl-icd") != std::string::npos);
    }
    fs::remove_all(empty);
    CHECK(folder_empty(scratch.path()));
}

TEST_CASE("a full disk (file-size limit): exit 1, 'File too large', no partial file")
{
    const ggxtest::ScratchFolder scratch("faults");
    const std::string args = "sample --method caps -n 1e6 --fields m,o --out ";
    // Warm the kernel cache first: PoCL writes its cache under the same limit.
    REQUIRE(ggxtest::run_ggx(args + (scratch / "warm.npy").string(), scratch / "stderr.txt").status == 0);
    fs::remove(scratch / "warm.npy");
    fs::remove(scratch / "warm.json");
    ggxtest::Run run = ggxtest::run_ggx("sh -c 'ulimit -f 4096; exec " + ggxtest::ggx_binary() + " " + args +
                                            (scratch / "big.npy").string() + "'",
                                        scratch / "stderr.txt", false);
    CAPTURE(run.err);
    CHECK(run.status == 1);
    CHECK(run.err.find("File too large") != std::string::npos);
    CHECK(run.err.find("big.npy") != std::string::npos);
    CHECK(folder_empty(scratch.path()));
}

TEST_CASE("an interrupted run (SIGINT) leaves no file and no temporary")
{
    const ggxtest::ScratchFolder scratch("faults");
    std::string out = (scratch / "int.npy").string();
    std::vector<std::string> words = {ggxtest::ggx_binary(), "sample", "--method", "caps", "--precision",
                                      "precise", "-n", "2^27", "--out", out};
    std::vector<char*> argv;
    for (std::string& w : words)
        argv.push_back(w.data());
    argv.push_back(nullptr);
    pid_t pid;
    REQUIRE(::posix_spawn(&pid, words[0].c_str(), nullptr, nullptr, argv.data(), environ) == 0);
    // Wait until the run has opened its temporary output, then interrupt it.
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (folder_empty(scratch.path()) && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    CHECK(!folder_empty(scratch.path()));
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    ::kill(pid, SIGINT);
    int status = 0;
    ::waitpid(pid, &status, 0);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == SIGINT);
    CHECK(folder_empty(scratch.path()));
}

TEST_CASE("a lost device mid-run (GGXCL_INJECT_FAULT=lost-after=1): exit 1, the CL error, no partial file")
{
    const ggxtest::ScratchFolder scratch("faults");
    std::string out = (scratch / "lost.npy").string();
    ggxtest::Run run = ggxtest::run_ggx("env GGXCL_INJECT_FAULT=lost-after=1 " + ggxtest::ggx_binary() +
                                            " sample --method caps -n 2^21 --out " + out,  // two chunks of 2^20
                                        scratch / "stderr.txt", false);
    CAPTURE(run.err);
    CHECK(run.status == 1);
    CHECK(run.err.find("device was lost") != std::string::npos);
    CHECK(run.err.find("CL_DEVICE_NOT_AVAILABLE") != std::string::npos);
    CHECK(folder_empty(scratch.path()));
}

TEST_CASE("device memory exhausted (GGXCL_INJECT_FAULT=alloc-above=...): the same file, in smaller chunks")
{
    const ggxtest::ScratchFolder scratch("faults");
    const std::string args = " sample --method heitz --alpha 0.2,0.5 -n 300001 --fields m,o,weight --out ";
    fs::path plain = scratch / "plain.npy", squeezed = scratch / "squeezed.npy";
    REQUIRE(ggxtest::run_ggx(args + plain.string(), scratch / "stderr.txt").status == 0);
    ggxtest::Run run = ggxtest::run_ggx("env GGXCL_INJECT_FAULT=alloc-above=100000 " + ggxtest::ggx_binary() +
                                            args + squeezed.string(),
                                        scratch / "stderr.txt", false);
    CAPTURE(run.err);
    CHECK(run.status == 0);
    CHECK(ggxtest::read_all(plain) == ggxtest::read_all(squeezed));
    for (const char* name : {"plain.npy", "plain.json", "squeezed.npy", "squeezed.json"})
        fs::remove(scratch / name);
    CHECK(folder_empty(scratch.path()));
}
