#include "harness/store/journal.hpp"

#include "harness/store/parse.hpp"
#include "harness/store/client.hpp"
#include "harness/store/plugin.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/run_record.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace rotbench {
namespace fs = std::filesystem;

namespace {

using json = nlohmann::json;

fs::path journal_file(const fs::path& out_dir) { return out_dir / "partial" / "runs.jsonl"; }

// The plug-ins and client files loaded now, each with its hash: a changed one is another scheme.
json loaded_files() {
    json files = json::array();
    for (const auto& p : loaded_plugins()) files.push_back({p.hash, p.path});
    for (const auto& c : loaded_clients()) files.push_back({c.hash, c.path});
    return files;
}

// The journal file, open for reading; InputError when out_dir holds none.
std::ifstream open_journal(const fs::path& out_dir) {
    const fs::path file = journal_file(out_dir);
    if (!fs::exists(fs::symlink_status(file)))
        throw InputError("--resume " + out_dir.string() + ": no interrupted run there (no partial/runs.jsonl)");
    return open_input_stream(file, "the journal");
}

// The journal's first line, what the command was: {"journal": {"command": [...], "cwd": "...",
// "files": [[hash, path], ...]}}, read from `in`, left at the first record. InputError naming
// `file` when it is not one.
struct Header {
    json fields;
    std::size_t length = 0;  // with its line break
};
Header read_header(std::istream& in, const fs::path& file) {
    std::string line;
    const bool whole = static_cast<bool>(std::getline(in, line)) && !in.eof();
    const json j = whole ? json::parse(line, nullptr, false) : json();
    const bool valid = j.is_object() && j.contains("journal") && j["journal"].is_object() && j["journal"].contains("command") &&
                       j["journal"]["command"].is_array() && j["journal"].contains("cwd") && j["journal"]["cwd"].is_string() &&
                       j["journal"].contains("files") && j["journal"]["files"].is_array() &&
                       std::all_of(j["journal"]["command"].begin(), j["journal"]["command"].end(), [](const json& a) { return a.is_string(); });
    if (!valid) throw InputError(file.string() + ":1: not the journal of a rotbench command; the folder's bookkeeping was changed by something else");
    return {j["journal"], line.size() + 1};
}
Header read_header(const fs::path& out_dir) {
    std::ifstream in = open_journal(out_dir);
    return read_header(in, journal_file(out_dir));
}

// The header and the runs recorded after it, and the bytes the header and the whole records
// span: a kill while a record was being appended leaves a cut one at the end, which is dropped
// (and cut off the file when the command is resumed).
struct Records {
    Header header;
    std::map<RunSpec, RunResult> runs;
    std::size_t count = 0, whole_length = 0;
};
Records read_records(const fs::path& out_dir) {
    const fs::path file = journal_file(out_dir);
    std::ifstream in = open_journal(out_dir);
    Records found{read_header(in, file)};
    RunRecords records = parse_run_records(in, file.string());
    for (auto& [index, run] : records.runs) {
        const RunSpec key = run.spec;
        if (!found.runs.emplace(key, std::move(run)).second)
            throw InputError(fmt::format("{}: record {} is of {} {} {} dt={}, which is recorded already", file.string(), index, key.scene,
                                         key.scheme, kind_name(key.kind), format_number(key.dt)));
    }
    found.count = records.runs.size();
    found.whole_length = found.header.length + records.whole_length;
    return found;
}

}  // namespace

Journal Journal::start(const OutputDir& out, const std::vector<std::string>& arguments) {
    const json header = {{"journal", {{"command", arguments}, {"cwd", fs::current_path().string()}, {"files", loaded_files()}}}};
    out.write("partial/runs.jsonl", header.dump(-1, ' ', false, json::error_handler_t::replace) + "\n");
    return Journal(out, 0);
}

Journal Journal::reopen(const OutputDir& out) {
    const fs::path out_dir = out.path();
    const Records found = read_records(out_dir);
    if (found.header.fields.at("files") != loaded_files())
        throw InputError("--resume " + out_dir.string() +
                         ": a plug-in or client file has changed since the run was interrupted "
                         "(partial/runs.jsonl names each with its hash); run it again with --overwrite");
    // A record cut short by a kill would sit between the runs appended from now on: cut it off.
    const fs::path runs = out.claim("partial/runs.jsonl");
    if (found.whole_length != fs::file_size(runs)) fs::resize_file(runs, found.whole_length);
    return Journal(out, found.count);
}

std::vector<std::string> Journal::arguments(const fs::path& out_dir) {
    return read_header(out_dir).fields.at("command").get<std::vector<std::string>>();
}

fs::path Journal::working_directory(const fs::path& out_dir) {
    const fs::path cwd = read_header(out_dir).fields.at("cwd").get<std::string>();
    if (!fs::is_directory(cwd))
        throw InputError("--resume " + out_dir.string() + ": the run was started in " + cwd.string() + ", which is gone");
    return cwd;
}

std::map<RunSpec, RunResult> Journal::finished() const { return read_records(out_.path()).runs; }

void Journal::record(const RunResult& result) const { append_to_file(journal_file(out_.path()), run_record((*records_)++, result)); }

void Journal::discard(const fs::path& out_dir) {
    std::error_code ec;
    fs::remove(journal_file(out_dir), ec);
    fs::remove(out_dir / "partial", ec);  // when empty
}

}  // namespace rotbench
