// What a run ran: each scheme's description and claims, and where it came from (a plug-in's
// path, content hash and build; a client's program), kept in an output folder's schemes.json
// beside its runs, so that `report`, `compare` and `merge` describe a plug-in's runs without
// `--plugin` (docs/outputs.md).
#pragma once

#include "harness/store/output_dir.hpp"
#include "schemes/scheme.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rotbench {

struct SchemeInfo {
    std::string id, summary, source, notes;
    SchemeClaims claims;
    bool client = false;           // run by a program outside rotbench (harness/store/client.hpp)
    std::string counterpart;       // a client's: the built-in scheme it should equal (empty: none)
    std::string counterpart_note;  // why it is not that scheme's map, where it is not
    std::string plugin_path, plugin_hash, plugin_build;  // a plug-in's (harness/store/plugin.hpp); empty otherwise
    std::string client_file, client_hash, program_hash;  // a client's file, its hash and its program's files' hash
};
using SchemeInfos = std::map<std::string, SchemeInfo>;

SchemeInfo scheme_info(const std::string& id);  // of a scheme registered in this process

// The schemes of `ids`: as registered in this process, else as `recorded` (an earlier command's
// schemes.json); a scheme in neither is left out.
SchemeInfos describe_schemes(const std::vector<std::string>& ids, const SchemeInfos& recorded);

std::string schemes_json(const SchemeInfos& schemes);
SchemeInfos parse_schemes_json(const std::string& text, const std::string& name);  // InputError
// A folder's schemes.json, or nothing when it has none.
SchemeInfos read_schemes(const std::filesystem::path& dir);

}  // namespace rotbench
