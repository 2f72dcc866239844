// Inputs an adversary would try (issue 20): devices and FIFOs where a file is expected (a read
// that never ends, an open that never returns), nesting deep enough to overflow a recursive
// parser, files larger than any input, line breaks in arguments, and shell metacharacters in
// paths. Each is refused with exit 2 and one line, before anything is written, or (the paths)
// simply works, with no shell ever started.
#include "tests/cli_helpers.hpp"

#include <catch2/catch.hpp>
#include <sys/stat.h>

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
            "an argument holds a line break: '" + (dir / "o").string() + "\\nut'", dir);
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
