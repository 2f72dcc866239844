// libFuzzer target: an output folder's bookkeeping, which may come from someone else (a CI
// artifact, a tarball): its manifest, its lock and its journal, forged. Opening it to resume,
// to overwrite or to write beside must end in success or an InputError, and must leave the
// file beside the folder as it was: rotbench touches nothing outside its output folder.
// Input: the manifest, the lock and the journal's records, separated by NUL bytes.
#include "harness/store/journal.hpp"
#include "harness/store/output_dir.hpp"
#include "harness/store/output_files.hpp"
#include "tests/fuzz/fuzz_input.hpp"
#include "tests/removed_at_exit.hpp"

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace rotbench;
namespace fs = std::filesystem;

namespace {

const fs::path root = fs::temp_directory_path() / ("rotbench_fuzz_output_dir_" + std::to_string(::getpid()));
const fs::path out = root / "out", beside = root / "precious";

// libFuzzer ends by exit(): the scratch folder goes with the fuzzer.
const test::RemovedAtExit scratch{root};

void put(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

std::string get(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string input = fuzz::text(data, size);
    const std::size_t first = input.find('\0'), second = first == std::string::npos ? first : input.find('\0', first + 1);
    const std::string manifest = input.substr(0, first);
    const std::string lock = first == std::string::npos ? "" : input.substr(first + 1, second - first - 1);
    const std::string journal = second == std::string::npos ? "" : input.substr(second + 1);
    std::error_code ec;
    fs::remove_all(root, ec);
    fs::create_directories(out / ".rotbench");
    fs::create_directories(out / "partial");
    put(beside, "keep me\n");
    put(out / ".rotbench" / "manifest", manifest);
    put(out / ".rotbench" / "lock", lock);
    put(out / "partial" / "runs.jsonl", "{\"journal\": {\"command\": [\"run\"], \"cwd\": \"/\", \"files\": []}}\n" + journal);
    for (const bool resuming : {true, false}) {
        fuzz::parse_or_input_error([&] {
            const OutputDir dir = OutputDir::open(out, {"run", "results.csv", {"results.csv", "runs.jsonl"}, !resuming, resuming});
            if (resuming) (void)Journal::reopen(dir).finished();
            dir.write("results.csv", "scene,scheme,dt,metric,value\n");
        });
        std::size_t entries = 0;
        for ([[maybe_unused]] const auto& e : fs::directory_iterator(root)) ++entries;
        if (get(beside) != "keep me\n" || entries != 2) __builtin_trap();  // something outside the folder was touched
    }
    return 0;
}
