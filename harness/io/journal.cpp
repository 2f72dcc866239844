#include "harness/io/journal.hpp"

#include "harness/io/parse.hpp"
#include "harness/io/plugin.hpp"
#include "harness/io/output_files.hpp"
#include "harness/io/run_record.hpp"

#include <fmt/format.h>
#include <sstream>
#include <stdexcept>

namespace rotbench {
namespace fs = std::filesystem;

namespace {

fs::path journal_dir(const fs::path& out_dir) { return out_dir / "partial"; }

std::string read_text(const fs::path& path) { return read_input_file(path, "cannot read"); }

std::string plugins_text() {
    std::string text;
    for (const auto& p : loaded_plugins()) text += p.hash + "\t" + p.path + "\n";
    return text;
}

std::string plan_line(const std::string& plan_id, std::size_t plan_size) { return fmt::format("{} {}\n", plan_id, plan_size); }

// The records of the runs file that are whole, and the length they span: a kill while a
// record was being appended leaves a cut one at the end, which is dropped (and cut off
// the file when the run is resumed).
struct Records {
    std::map<std::size_t, RunResult> runs;
    std::size_t whole_length = 0;
};

Records read_records(const fs::path& file, const std::vector<RunSpec>& plan) {
    Records found;
    const std::string text = fs::exists(file) ? read_input_file(file, "the journal") : "";
    RunRecords records = parse_run_records(text, file.string());
    for (auto& [index, run] : records.runs) {
        const RunSpec& got = run.spec;
        if (index >= plan.size())
            throw InputError(fmt::format("{}: a record of run {}, and the plan has {} runs", file.string(), index, plan.size()));
        const RunSpec& want = plan[index];
        if (got.scene != want.scene || got.scheme != want.scheme || got.kind != want.kind || got.dt != want.dt)
            throw InputError(fmt::format("{}: the record of run {} is of {} {} dt={}, the plan has {} {} dt={} there", file.string(),
                                         index, got.scene, got.scheme, format_number(got.dt), want.scene, want.scheme,
                                         format_number(want.dt)));
        if (found.runs.count(index)) throw InputError(fmt::format("{}: run {} is recorded twice", file.string(), index));
        found.runs.emplace(index, std::move(run));
    }
    found.whole_length = records.whole_length;
    return found;
}

}  // namespace

bool Journal::exists(const fs::path& out_dir) { return fs::exists(journal_dir(out_dir) / "plan"); }

Journal Journal::start(const OutputDir& out, const std::vector<std::string>& arguments, const std::string& plan_id,
                       const std::vector<RunSpec>& plan) {
    std::string command;
    for (const auto& a : arguments) {
        if (a.find('\n') != std::string::npos) throw InputError("an argument holds a line break");  // the CLI refuses them first
        command += a + "\n";
    }
    out.write("partial/command", command);
    out.write("partial/cwd", fs::current_path().string());
    out.write("partial/plugins", plugins_text());
    out.claim("partial/runs.jsonl");
    out.write("partial/plan", plan_line(plan_id, plan.size()));  // last: its presence marks a journal
    return Journal(out, plan);
}

Journal Journal::reopen(const OutputDir& out, const std::string& plan_id, const std::vector<RunSpec>& plan) {
    const fs::path out_dir = out.path(), dir = journal_dir(out_dir);
    if (!exists(out_dir)) throw InputError("--resume " + out_dir.string() + ": no interrupted run there (no partial/plan)");
    if (read_text(dir / "plan") != plan_line(plan_id, plan.size()))
        throw InputError("--resume " + out_dir.string() + ": the sweep its command describes is not the one that was " +
                         "interrupted (a scheme, scene or plug-in changed); run it again with --overwrite");
    if (fs::exists(dir / "plugins") && read_text(dir / "plugins") != plugins_text())
        throw InputError("--resume " + out_dir.string() + ": a plug-in has changed since the run was interrupted (partial/plugins "
                         "names each with its hash); run it again with --overwrite");
    // A record cut short by a kill would sit between the runs appended from now on: cut it off.
    const fs::path runs = out.claim("partial/runs.jsonl");
    if (fs::exists(runs)) {
        const std::size_t whole = read_records(runs, plan).whole_length;
        if (whole != fs::file_size(runs)) fs::resize_file(runs, whole);
    }
    return Journal(out, plan);
}

std::vector<std::string> Journal::arguments(const fs::path& out_dir) {
    if (!exists(out_dir)) throw InputError("--resume " + out_dir.string() + ": no interrupted run there (no partial/plan)");
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

std::map<std::size_t, RunResult> Journal::finished() const { return read_records(journal_dir(out_.path()) / "runs.jsonl", plan_).runs; }

void Journal::record(std::size_t plan_index, const RunResult& result) const {
    append_to_file(journal_dir(out_.path()) / "runs.jsonl", run_record(plan_index, result));
}

void Journal::discard(const fs::path& out_dir) {
    std::error_code ec;
    for (const char* f : {"plan", "runs.jsonl", "command", "cwd", "plugins"}) fs::remove(journal_dir(out_dir) / f, ec);
    fs::remove(journal_dir(out_dir), ec);  // when empty
}

}  // namespace rotbench
