// cmd_merge.cpp - `ggx merge`: joins shards written with consecutive
// --first ranges into the file one run over the whole range writes, byte
// for byte (.npy or .csv), after checking that their sidecars agree on
// everything but the range; or, with --manifest, leaves the shards where
// they are and writes one JSON file that lists them in order.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli_values.hpp"
#include "commands.hpp"
#include "npy_file.hpp"
#include "report_text.hpp"
#include "sidecar_reader.hpp"
#include "sample_job.hpp"

namespace ggxapp {

namespace {

nlohmann::json read_sidecar(const std::string& shard)
{
    std::ifstream in(sidecar_path(shard));
    if (!in)
        throw UsageError("SHARD", shard, "a shard with its .json sidecar beside it");
    return parse_sidecar(in, shard);
}

// What must agree between shards: everything but the range and the device.
nlohmann::json without_range(nlohmann::json doc)
{
    for (const char* key : {"first", "count", "shape", "device"})
        doc.erase(key);
    return doc;
}

// Every shard's sidecar, in order.
std::vector<nlohmann::json> read_sidecars(const std::vector<std::string>& shards)
{
    std::vector<nlohmann::json> docs;
    for (const std::string& shard : shards)
        docs.push_back(read_sidecar(shard));
    return docs;
}

// The merged sidecar: the first shard's, with the whole range, once the
// shards' sidecars (`docs`) are checked to agree and follow each other.
nlohmann::json merged_sidecar(const std::vector<std::string>& shards, const std::vector<nlohmann::json>& docs)
{
    nlohmann::json merged = docs.front();
    std::uint64_t next = merged["first"].get<std::uint64_t>() + merged["count"].get<std::uint64_t>();
    for (std::size_t k = 1; k < shards.size(); ++k) {
        const nlohmann::json& doc = docs[k];
        if (next < merged["first"].get<std::uint64_t>())  // the ranges wrapped around 2^64
            throw UsageError("SHARD", shards[k], "shards whose ranges end before index 2^64");
        if (doc["first"].get<std::uint64_t>() != next)
            throw UsageError("SHARD", shards[k], "the shard starting at --first " + std::to_string(next));
        next += doc["count"].get<std::uint64_t>();
        if (without_range(doc) != without_range(merged))
            throw UsageError("SHARD", shards[k], "a shard of the same method, parameters, seed and columns");
    }
    std::uint64_t count = next - merged["first"].get<std::uint64_t>();
    merged["count"] = count;
    merged["shape"][0] = count;
    return merged;
}

void merge_npy(const std::vector<std::string>& shards, const std::string& out, std::uint64_t rows, std::size_t columns)
{
    NpyWriter writer(out, rows, columns);
    std::vector<float> chunk;  // 8 MiB at a time: shards may be larger than memory
    const std::uint64_t chunk_rows = std::max<std::uint64_t>(1, (8u << 20) / sizeof(float) / std::max<std::size_t>(1, columns));
    for (const std::string& shard : shards) {
        NpyRowReader reader(shard);
        if (reader.columns() != columns)
            throw UsageError("SHARD", shard, "a shard of the sidecar's " + std::to_string(columns) + " columns");
        while (reader.next(chunk, chunk_rows))
            writer.append(chunk);
    }
    writer.commit();
}

void merge_csv(const std::vector<std::string>& shards, const std::string& out)
{
    AtomicFile file(out);
    for (std::size_t k = 0; k < shards.size(); ++k) {
        std::ifstream in(shards[k]);
        std::string line;
        bool header = true;
        while (std::getline(in, line)) {
            if (!header || k == 0) {
                line += "\n";
                file.write(line.data(), line.size());
            }
            header = false;
        }
    }
    file.commit();
}

// The shards' one format, .npy or .csv.
Format shard_format(const std::vector<std::string>& shards)
{
    Format format = format_of("SHARD", shards.front());
    for (const std::string& shard : shards)
        if (format_of("SHARD", shard) != format || format == Format::ply)
            throw UsageError("SHARD", shard, "shards of one format, .npy or .csv");
    return format;
}

// Checks the output and the shards' formats: both .npy, or both .csv.
Format check_formats(const std::vector<std::string>& shards, const std::string& out)
{
    Format format = shard_format(shards);
    if (format_of("--out", out) != format)
        throw UsageError("--out", out, "the shards' format, .npy or .csv");
    return format;
}

void run_merge(const std::vector<std::string>& shards, const std::string& out, Format format)
{
    check_writable_folder("--out", out);
    nlohmann::json sidecar = merged_sidecar(shards, read_sidecars(shards));
    AtomicFile json_file(sidecar_path(out));
    if (format == Format::npy)
        merge_npy(shards, out, sidecar["count"].get<std::uint64_t>(), sidecar["columns"].size());
    else
        merge_csv(shards, out);
    std::string text = sidecar.dump(2) + "\n";
    json_file.write(text.data(), text.size());
    json_file.commit();
    std::cout << out << ": " << sidecar["count"] << " samples from " << shards.size() << " shards\n";
}

// The merged sidecar plus "shards": each shard's file (relative to the
// manifest's folder), first index and count, in order.  Nothing is copied.
void write_manifest(const std::vector<std::string>& shards, const std::string& manifest)
{
    check_writable_folder("--manifest", manifest);
    const std::vector<nlohmann::json> parts = read_sidecars(shards);
    nlohmann::json doc = merged_sidecar(shards, parts);
    doc["shards"] = nlohmann::json::array();
    for (std::size_t k = 0; k < shards.size(); ++k)
        doc["shards"].push_back(
            {{"file", relative_to(shards[k], manifest)}, {"first", parts[k]["first"]}, {"count", parts[k]["count"]}});
    write_text_file(manifest, doc.dump(2) + "\n");
    std::cout << manifest << ": " << doc["count"] << " samples in " << shards.size() << " shards, left in place\n";
}

} // namespace

Prepare add_merge_command(CLI::App& app)
{
    auto shards = std::make_shared<std::vector<std::string>>();
    auto out = std::make_shared<std::string>(), manifest = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand("merge", "Join shards of consecutive --first ranges into one file (.npy or .csv), "
                                                "or list them in a manifest");
    CLI::Option* out_option = cmd->add_option("--out", *out, "merged output, same extension as the shards");
    cmd->add_option("--manifest", *manifest,
                    "instead of --out: a .json listing the shards in order (checked like a merge), nothing copied")
        ->excludes(out_option);
    cmd->add_option("shards", *shards, "shard files in order of --first")->required();
    return [cmd, shards, out, manifest]() -> std::optional<Work> {
        if (!*cmd)
            return std::nullopt;
        if (!manifest->empty()) {
            if (std::filesystem::path(*manifest).extension() != ".json")
                throw UsageError("--manifest", *manifest, "a path ending in .json");
            shard_format(*shards);
            return Work{[shards, manifest] { write_manifest(*shards, *manifest); }, {}};
        }
        if (out->empty())
            throw UsageError("--out", "(none)", "the merged file, or --manifest FILE.json");
        Format format = check_formats(*shards, *out);
        return Work{[shards, out, format] { run_merge(*shards, *out, format); }, {}};
    };
}

} // namespace ggxapp
