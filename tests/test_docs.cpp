// The documentation inside the repository is a contract, kept true by these tests: docs/ids.md
// is what `rotbench list --markdown` prints, and docs/cli.md has a section for every verb.
// (The probe scheme and scene of a ROTBENCH_PROBES build are not documented: their sections
// are dropped from the generated text before the comparison.)
#include "harness/cli/verb.hpp"
#include "schemes/scheme.hpp"
#include "tests/cli_helpers.hpp"

#include <catch2/catch.hpp>
#include <cstdio>

using namespace rotbench;
using namespace rotbench::test;

namespace {

bool is_probe(const std::string& line) { return line.find("(tests/probes/") != std::string::npos || line.find("`aaa_probe") != std::string::npos; }

// The standard output of the real binary (whose registries hold no test-only scheme).
std::string binary_output(const std::string& arguments) {
    std::string out;
    FILE* pipe = ::popen((std::string(ROTBENCH_EXE) + " " + arguments).c_str(), "r");
    REQUIRE(pipe);
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
    REQUIRE(::pclose(pipe) == 0);
    return out;
}

// The generated text without the probes: their table rows, and their scene sections.
std::string without_probes(const std::string& text) {
    std::istringstream in(text);
    std::string out, line;
    bool skipping = false;
    while (std::getline(in, line)) {
        if (line.rfind("### ", 0) == 0) skipping = is_probe(line);
        if (!skipping && !is_probe(line)) out += line + "\n";
    }
    return out;
}

}  // namespace

TEST_CASE("docs/ids.md is the output of rotbench list --markdown") {
    const std::string committed = read(fs::path(ROTBENCH_SOURCE_DIR) / "docs" / "ids.md");
    INFO("regenerate with: build/rotbench list --markdown > docs/ids.md");
    CHECK(without_probes(binary_output("list --markdown")) == committed);
}

TEST_CASE("docs/cli.md documents every verb") {
    const std::string cli_md = read(fs::path(ROTBENCH_SOURCE_DIR) / "docs" / "cli.md");
    for (const auto& verb : user_verbs()) {
        INFO(verb);
        CHECK_THAT(cli_md, Catch::Contains("## `rotbench " + verb));
    }
}
