#include "harness/journal.hpp"

#include "harness/parse.hpp"
#include "reports/energy_series.hpp"
#include "reports/output_files.hpp"
#include "reports/results_csv.hpp"

#include <atomic>
#include <fmt/format.h>
#include <unistd.h>

namespace rotbench {
namespace fs = std::filesystem;

namespace {

fs::path journal_dir(const fs::path& out_dir) { return out_dir / "partial"; }

std::string read_text(const fs::path& path) {
    auto text = read_file(path);
    if (!text) throw InputError("cannot read " + path.string());
    return std::move(*text);
}

std::string plan_line(const std::string& plan_id, std::size_t plan_size) { return fmt::format("{} {}\n", plan_id, plan_size); }

bool is_run_directory(const fs::path& p) {
    const std::string name = p.filename().string();
    return !name.empty() && name.find_first_not_of("0123456789") == std::string::npos;
}

}  // namespace

bool Journal::exists(const fs::path& out_dir) { return fs::exists(journal_dir(out_dir) / "plan"); }

Journal Journal::start(const fs::path& out_dir, const std::vector<std::string>& arguments, const std::string& plan_id,
                       std::size_t plan_size) {
    std::string command;
    for (const auto& a : arguments) {
        if (a.find('\n') != std::string::npos) throw InputError("an argument holds a line break: '" + a + "'");
        command += a + "\n";
    }
    const fs::path dir = journal_dir(out_dir);
    fs::remove_all(dir);
    fs::create_directories(dir);
    write_file_atomically(dir / "command", command);
    write_file_atomically(dir / "cwd", fs::current_path().string());
    write_file_atomically(dir / "plan", plan_line(plan_id, plan_size));  // last: its presence marks a journal
    return Journal(dir);
}

Journal Journal::reopen(const fs::path& out_dir, const std::string& plan_id, std::size_t plan_size) {
    const fs::path dir = journal_dir(out_dir);
    if (!exists(out_dir)) throw InputError("--resume " + out_dir.string() + ": no interrupted run there (no partial/plan)");
    if (read_text(dir / "plan") != plan_line(plan_id, plan_size))
        throw InputError("--resume " + out_dir.string() + ": the sweep its command describes is not the one that was " +
                         "interrupted (a scheme, scene or plug-in changed); run it again with --overwrite");
    return Journal(dir);
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

std::map<std::size_t, RunResult> Journal::finished() const {
    std::map<std::size_t, RunResult> runs;
    for (const auto& entry : fs::directory_iterator(dir_)) {
        if (!entry.is_directory()) continue;
        if (!is_run_directory(entry.path())) {  // a run whose writing was cut short
            fs::remove_all(entry.path());
            continue;
        }
        auto results = read_results(entry.path());
        if (results.size() != 1) throw InputError(entry.path().string() + ": expected one run");
        runs.emplace(std::stoul(entry.path().filename().string()), std::move(results.front()));
    }
    return runs;
}

void Journal::record(std::size_t plan_index, const RunResult& result) const {
    static std::atomic<unsigned long> serial{0};
    const fs::path temporary = dir_ / fmt::format(".{}.{}.{}.tmp", plan_index, ::getpid(), serial++);
    fs::create_directories(temporary);
    write_file_atomically(temporary / "results.csv", results_csv({result}));
    write_file_atomically(temporary / "runs.csv", runs_csv({result}));
    write_energy_series({result}, temporary);
    fs::rename(temporary, dir_ / fmt::format("{:06}", plan_index));
}

void Journal::remove() const { fs::remove_all(dir_); }

}  // namespace rotbench
