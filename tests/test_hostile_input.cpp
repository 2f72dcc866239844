// Inputs an adversary would try (issue 20): devices and FIFOs where a file is expected (a read
// that never ends, an open that never returns), nesting deep enough to overflow a recursive
// parser, files larger than any input, line breaks in arguments, and shell metacharacters in
// paths. Each is refused with exit 2 and one line, before anything is written, or (the paths)
// simply works, with no shell ever started.
#include "tests/cli_helpers.hpp"
#include "harness/store/results_csv.hpp"

#include <catch2/catch.hpp>
#include <functional>
#include <sys/stat.h>
#include <tuple>

using namespace rotbench::test;

namespace {

// The real binary: a FIFO or a device must not hang it (the test would time out instead).
void refused(const std::vector<std::string>& args, const std::string& message, const fs::path& never_written) {
    const Cli r = binary(args);
    std::string shown;
    for (const auto& a : args) shown += a + " ";
    INFO(shown << "-> " << r.err);
    CHECK(r.status == 2);
    CHECK(one_line(r.err));
    CHECK_THAT(r.err, Catch::Contains(message));
    CHECK_FALSE(fs::exists(never_written));
}

}  // namespace

TEST_CASE("hostile inputs: devices, FIFOs, deep nesting and oversized files are refused in one line") {
    const fs::path dir = fresh_dir("hostile");
    fs::create_directories(dir);
    const fs::path fifo = dir / "fifo", out = dir / "out";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    // toml++ parses nested arrays and inline tables recursively; 200000 levels would take
    // the stack down if the depth were not bounded first.
    write(dir / "deep_arrays.toml", "[run]\nscenes = " + std::string(200000, '[') + std::string(200000, ']') + "\n");
    std::string tables = "[dipole_top]\nfield = ";
    for (int i = 0; i < 100000; ++i) tables += "{x=";
    write(dir / "deep_tables.toml", tables + "1" + std::string(100000, '}') + "\n");
    // So does a dotted key: a table a part, in a header or before '='.
    std::string dotted = "a";
    for (int i = 0; i < 200000; ++i) dotted += ".a";
    write(dir / "dotted_header.toml", "[" + dotted + "]\n");
    write(dir / "dotted_key.toml", dotted + " = 1\n");
    write(dir / "big.toml", "");
    fs::resize_file(dir / "big.toml", 2u << 20);  // sparse: 2 MiB of zeros, over the 1 MiB a config may have
    const std::string gate_out = (dir / "gate_out").string();
    for (const auto& [args, message] : std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"run", "--config", "/dev/zero", "--out", out}, "/dev/zero: not a regular file"},
             {{"run", "--config", fifo, "--out", out}, fifo.string() + ": not a regular file"},
             {{"gate", "/dev/zero", "--out", gate_out}, "not a regular file"},
             {{"gate", fifo, "--out", gate_out}, "not a regular file"},
             {{"--plugin", "/dev/zero", "run", "--out", out}, "--plugin /dev/zero: not a regular file"},
             {{"--plugin", fifo, "run", "--out", out}, "not a regular file"},
             {{"run", "--config", (dir / "deep_arrays.toml").string(), "--out", out}, "deep_arrays.toml:2:"},
             {{"run", "--config", (dir / "deep_tables.toml").string(), "--out", out}, "nested more than 64 levels deep"},
             {{"run", "--config", (dir / "dotted_header.toml").string(), "--out", out}, "dotted_header.toml:1:131: a key of more than 64 dotted parts"},
             {{"run", "--config", (dir / "dotted_key.toml").string(), "--out", out}, "dotted_key.toml:1:130: a key of more than 64 dotted parts"},
             {{"run", "--config", (dir / "big.toml").string(), "--out", out}, "more than the 1048576 this input may have"},
             {{"report", fifo}, "cannot read"},
             {{"merge", fifo, fifo, "--out", out}, "cannot read"},
         })
        refused(args, message, args.front() == "gate" ? fs::path(gate_out) : out);
    fs::remove_all(dir);
}

TEST_CASE("hostile inputs: an argument with a line break is refused in one line, before any directory is made") {
    const fs::path dir = fresh_dir("line_break");
    const std::string out = (dir / "o\nut").string();
    refused({"run", "--scenes", "dipole_top", "--schemes", "direct", "--dt", "1e-2", "--out", out},
            "an argument holds a line break: '" + (dir / "o").string() + "\\x0Aut'", dir);
    refused({"run", "--scenes", "dipole_top\r", "--out", (dir / "o").string()}, "line break", dir);
}

TEST_CASE("hostile inputs: shell metacharacters in a path are just characters") {
    const fs::path dir = fresh_dir("metacharacters");
    const fs::path out = dir / "a b;touch pwned;'$(touch pwned)'`touch pwned`&|*?";
    const Cli r = binary({"run", "--scenes", "fibre_bounce", "--schemes", "direct", "--dt", "1e-6", "--t-end", "2e-4", "--out", out});
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(fs::exists(out / "results.csv"));
    CHECK(fs::exists(out / "report.md"));
    int plots = 0;
    for (const auto& e : fs::directory_iterator(out / "plots")) plots += e.path().extension() == ".svg";
    CHECK(plots > 0);  // gnuplot did run
    // The energy plot goes through gnuplot, the one program rotbench starts: with an argument
    // vector, so no "pwned" appears anywhere a shell would have created it.
    CHECK_FALSE(fs::exists("pwned"));
    CHECK_FALSE(fs::exists(dir / "pwned"));
    CHECK_FALSE(fs::exists(out / "pwned"));
    fs::remove_all(dir);
}

TEST_CASE("hostile inputs: a slice's forged place in the plan is refused before anything is sized by it") {
    const fs::path dir = fresh_dir("forged_shards");
    for (const char* k : {"1", "2"})
        REQUIRE(cli({"run", "--scenes", "dipole_top", "--schemes", "direct", "--dt", "1e-2,5e-3,2.5e-3", "--shard", std::string(k) + "/2",
                     "--out", (dir / k).string()})
                    .status == 0);
    REQUIRE(cli({"merge", (dir / "1").string(), (dir / "2").string(), "--out", (dir / "merged").string()}).status == 0);
    const std::string store = read(dir / "1" / "runs.jsonl");
    // The second record's place: {"id":...,"index":2,"shard":1,"shards":2,"size":3}
    const auto forged = [&](const std::string& key, const std::string& value) {
        const std::size_t record = store.find('\n') + 1;
        const std::size_t begin = store.find("\"" + key + "\":", store.find("\"plan\":", record)) + key.size() + 3;
        const std::size_t end = store.find_first_of(",}", begin);
        fs::remove_all(dir / "forged");
        fs::copy(dir / "1", dir / "forged", fs::copy_options::recursive);
        write(dir / "forged" / "runs.jsonl", store.substr(0, begin) + value + store.substr(end));
        return std::vector<std::string>{"merge", (dir / "forged").string(), (dir / "2").string(), "--out", (dir / "out").string()};
    };
    for (const auto& [key, value, message] : std::vector<std::tuple<std::string, std::string, std::string>>{
             {"size", "1000000000000000000", "in a plan of 1000000000000000000 runs cannot hold 2 runs"},
             {"size", "1e300", "plan size 1e+300 is not a count"},
             {"size", "-1", "plan size -1 is not a count"},
             {"size", "\"nan\"", "is not a count"},
             {"shards", "99999999999", "cannot hold"},
             {"shards", "3", "a slice of another sweep (plan"},  // the first record says 2
             {"shard", "0", "cannot hold"},
             {"shard", "2", "is not a place of shard 1 of 2"},
             {"index", "99999999999", "plan index 99999999999 is not a place of shard 1 of 2"},
             {"index", "1", "plan index 1 is not a place of shard 1 of 2"},  // shard 2's
             {"index", "0", "plan index 0 is not a place of shard 1 of 2"},  // the first record's
         }) {
        const auto args = forged(key, value);
        const Cli r = cli(args);
        INFO(key << " " << value << " -> " << r.err);
        CHECK(r.status == 2);
        CHECK(one_line(r.err));
        CHECK_THAT(r.err, Catch::Contains(message));
        CHECK_FALSE(fs::exists(dir / "out"));
    }
    // A run store edited to hold another duration, step or parameters than the plan its runs name:
    // the merged folder would differ from the unsharded run's, so it is refused.
    for (const auto& edit : std::vector<std::function<void(rotbench::RunSpec&)>>{
             [](rotbench::RunSpec& s) { s.t_end = 2.0 * s.t_end; }, [](rotbench::RunSpec& s) { s.dt = s.dt / 2; },
             [](rotbench::RunSpec& s) { s.params = {{"field", {0.0, 0.0, 2.0}}}; }}) {
        fs::remove_all(dir / "forged");
        fs::copy(dir / "1", dir / "forged", fs::copy_options::recursive);
        rotbench::StoredRuns stored = rotbench::read_run_store(dir / "forged");
        edit(stored.runs.front().spec);
        std::vector<rotbench::PlanPlace> places;
        for (const auto& place : stored.places) places.push_back(place.value());
        write(dir / "forged" / "runs.jsonl", rotbench::run_store(stored.runs, places));
        const Cli r = cli({"merge", (dir / "forged").string(), (dir / "2").string(), "--out", (dir / "out").string()});
        CHECK(r.status == 2);
        CHECK_THAT(r.err, Catch::Contains("the slices' runs do not make the plan they name"));
        CHECK_FALSE(fs::exists(dir / "out"));
    }
    fs::remove_all(dir);
}
