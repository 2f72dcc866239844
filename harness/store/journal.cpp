#include "harness/store/journal.hpp"

#include "harness/store/parse.hpp"
#include "harness/store/client.hpp"
#include "harness/store/plugin.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/run_record.hpp"

#include <fmt/format.h>
#include <sstream>
#include <stdexcept>

namespace rotbench {
namespace fs = std::filesystem;

namespace {

fs::path journal_dir(const fs::path& out_dir) { return out_dir / "partial"; }

bool journal_exists(const fs::path& out_dir) { return fs::exists(journal_dir(out_dir) / "command"); }

std::string read_text(const fs::path& path) { return read_input_file(path, "cannot read"); }

std::string plugins_text() {
    std::string text;
    for (const auto& p : loaded_plugins()) text += p.hash + "\t" + p.path + "\n";
    for (const auto& c : loaded_clients()) text += c.hash + "\t" + c.path + "\n";
    return text;
}

// The records of the runs file that are whole, and the length they span: a kill while a
// record was being appended leaves a cut one at the end, which is dropped (and cut off
// the file when the run is resumed).
struct Records {
    std::map<RunSpec, RunResult> runs;
    std::size_t count = 0, whole_length = 0;
};

Records read_records(const fs::path& file) {
    Records found;
    if (!fs::exists(file)) return found;
    std::ifstream in = open_input_stream(file, "the journal");
    RunRecords records = parse_run_records(in, file.string());
    for (auto& [index, run] : records.runs) {
        const RunSpec key = run.spec;
        if (!found.runs.emplace(key, std::move(run)).second)
            throw InputError(fmt::format("{}: record {} is of {} {} {} dt={}, which is recorded already", file.string(), index, key.scene,
                                         key.scheme, kind_name(key.kind), format_number(key.dt)));
    }
    found.count = records.runs.size();
    found.whole_length = records.whole_length;
    return found;
}

}  // namespace

Journal Journal::start(const OutputDir& out, const std::vector<std::string>& arguments) {
    std::string command;
    for (const auto& a : arguments) {
        if (a.find('\n') != std::string::npos) throw InputError("an argument holds a line break");  // the CLI refuses them first
        command += a + "\n";
    }
    out.claim("partial/runs.jsonl");
    out.write("partial/plugins", plugins_text());
    out.write("partial/cwd", fs::current_path().string());
    out.write("partial/command", command);  // last: its presence marks a journal
    return Journal(out, 0);
}

Journal Journal::reopen(const OutputDir& out) {
    const fs::path out_dir = out.path(), dir = journal_dir(out_dir);
    if (!journal_exists(out_dir)) throw InputError("--resume " + out_dir.string() + ": no interrupted run there (no partial/command)");
    if (fs::exists(dir / "plugins") && read_text(dir / "plugins") != plugins_text())
        throw InputError("--resume " + out_dir.string() +
                         ": a plug-in or client file has changed since the run was interrupted "
                         "(partial/plugins names each with its hash); run it again with --overwrite");
    // A record cut short by a kill would sit between the runs appended from now on: cut it off.
    const fs::path runs = out.claim("partial/runs.jsonl");
    std::size_t count = 0;
    if (fs::exists(runs)) {
        const Records found = read_records(runs);
        if (found.whole_length != fs::file_size(runs)) fs::resize_file(runs, found.whole_length);
        count = found.count;
    }
    return Journal(out, count);
}

std::vector<std::string> Journal::arguments(const fs::path& out_dir) {
    if (!journal_exists(out_dir)) throw InputError("--resume " + out_dir.string() + ": no interrupted run there (no partial/command)");
    auto lines = split_on(read_text(journal_dir(out_dir) / "command"), '\n');
    lines.pop_back();  // after the last line break
    return lines;
}

fs::path Journal::working_directory(const fs::path& out_dir) {
    const fs::path cwd = read_text(journal_dir(out_dir) / "cwd");
    if (!fs::is_directory(cwd))
        throw InputError("--resume " + out_dir.string() + ": the run was started in " + cwd.string() + ", which is gone");
    return cwd;
}

std::map<RunSpec, RunResult> Journal::finished() const { return read_records(journal_dir(out_.path()) / "runs.jsonl").runs; }

void Journal::record(const RunResult& result) const {
    append_to_file(journal_dir(out_.path()) / "runs.jsonl", run_record((*records_)++, result));
}

void Journal::discard(const fs::path& out_dir) {
    std::error_code ec;
    for (const char* f : {"command", "runs.jsonl", "cwd", "plugins"}) fs::remove(journal_dir(out_dir) / f, ec);
    fs::remove(journal_dir(out_dir), ec);  // when empty
}

}  // namespace rotbench
