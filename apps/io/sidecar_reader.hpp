// sidecar_reader.hpp - reading the JSON sidecar of a sample file (what
// `ggx merge` needs of it): it must be a JSON object with `first` and
// `count` as unsigned integers and `columns` as an array of strings;
// anything else throws UsageError naming the shard and what is needed.
#pragma once

#include <istream>
#include <string>

#include <nlohmann/json.hpp>

namespace ggxapp {

nlohmann::json parse_sidecar(std::istream& in, const std::string& shard);

} // namespace ggxapp
