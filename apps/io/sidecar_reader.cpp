// sidecar_reader.cpp - parse and check a shard's JSON sidecar.
#include "sidecar_reader.hpp"

#include "cli_values.hpp"

namespace ggxapp {

nlohmann::json parse_sidecar(std::istream& in, const std::string& shard)
{
    const std::string needed = "a shard whose .json sidecar is an object with first and count (whole numbers) "
                               "and columns (names), as `ggx sample` writes it";
    nlohmann::json doc = nlohmann::json::parse(in, nullptr, false);  // no exceptions: discarded on error
    if (doc.is_discarded() || !doc.is_object())
        throw UsageError("SHARD", shard, needed);
    for (const char* key : {"first", "count"})
        if (!doc.contains(key) || !doc[key].is_number_unsigned())
            throw UsageError("SHARD", shard, needed);
    if (!doc.contains("columns") || !doc["columns"].is_array())
        throw UsageError("SHARD", shard, needed);
    for (const nlohmann::json& column : doc["columns"])
        if (!column.is_string())
            throw UsageError("SHARD", shard, needed);
    if (doc["count"].get<std::uint64_t>() > ~std::uint64_t(0) - doc["first"].get<std::uint64_t>())
        throw UsageError("SHARD", shard, needed);
    return doc;
}

} // namespace ggxapp
