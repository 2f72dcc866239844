// The CSV writer and reader (harness/io/csv.hpp) and the run files built on them: whatever a
// field holds comes back as written, and a file that was cut, edited or mistyped is refused
// with its file and line, never read as results.
#include "harness/io/csv.hpp"
#include "harness/io/results_csv.hpp"

#include <catch2/catch.hpp>

using namespace rotbench;

namespace {

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("csv: any field comes back as it was written (RFC 4180 quoting)") {
    const std::vector<std::string> fields = {"plain", "", "a,b", "say \"hi\"", "two\nlines", "cr\r\nlf", ",", "\"", "end,"};
    const auto records = parse_csv(csv_record(fields) + csv_record({"x"}), "t.csv");
    REQUIRE(records.size() == 2);
    CHECK(records[0].fields == fields);
    CHECK(records[1].fields == std::vector<std::string>{"x"});
    CHECK(records[1].line == 4);  // the quoted line breaks count
}

TEST_CASE("csv: malformed text is refused with the file and line") {
    CHECK_THAT(error_of([] { parse_csv("a,\"b\n", "t.csv"); }), Catch::Contains("t.csv:1: a quoted field is not closed"));
    CHECK_THAT(error_of([] { parse_csv("a\n\"b\"c\n", "t.csv"); }), Catch::Contains("t.csv:2: text after a closing quote"));
    CHECK_THAT(error_of([] { parse_csv("a\nb\"c\n", "t.csv"); }), Catch::Contains("t.csv:2: a quote inside an unquoted field"));
    CHECK_THAT(error_of([] { read_csv(std::string(""), "t.csv", "a,b"); }), Catch::Contains("t.csv: the file is empty"));
    CHECK_THAT(error_of([] { read_csv(std::string("a,c\n"), "t.csv", "a,b"); }), Catch::Contains("t.csv:1: expected the header 'a,b'"));
    CHECK_THAT(error_of([] { read_csv(std::string("a,b\n1,2\n3\n"), "t.csv", "a,b"); }), Catch::Contains("t.csv:3: expected 2 fields, found 1"));
    CHECK_THAT(error_of([] { read_csv(std::string("a,b\n1,2\n3,4"), "t.csv", "a,b"); }), Catch::Contains("t.csv:3: the file ends in the middle"));
    CHECK(read_csv(std::string("a,b\n1,\"2,3\"\n"), "t.csv", "a,b").front().fields == std::vector<std::string>{"1", "2,3"});
}

TEST_CASE("run files: a run with any failure text and parameters round-trips through runs.csv and results.csv") {
    RunResult r;
    r.spec = {"dipole_top", "direct", 0.01, 10.0, {{"field", {0.0, 0.0, 2.5}}, {"q0", {1.0, 0.0, 0.0, 0.0}}}, RunKind::trajectory};
    r.failure = "threw: a message, with \"quotes\"\nand a line break";
    r.metrics = {{"omega_err_max", 1.25e-3}, {"unstable", 1.0}};
    r.timing_samples = {0.5, 0.25};
    RunResult twin = r;  // the same scene, scheme and dt: told apart by the order of the files
    twin.spec.t_end = 5.0;
    twin.failure.clear();
    twin.metrics = {{"omega_err_max", 2.5e-3}};
    const auto back = parse_results(results_csv({r, twin}), runs_csv({r, twin}), {}, "dir");
    REQUIRE(back.size() == 2);
    CHECK(back[0].spec.params == r.spec.params);
    CHECK(back[0].failure == r.failure);
    CHECK(back[0].metrics == r.metrics);
    CHECK(back[0].timing_samples == r.timing_samples);
    CHECK(back[1].spec.t_end == 5.0);
    CHECK(back[1].metrics == twin.metrics);
}

TEST_CASE("run files: truncated, header-only and mistyped files are refused with file and line") {
    RunResult r;
    r.spec = {"dipole_top", "direct", 0.01, 10.0, {}, RunKind::trajectory};
    r.metrics = {{"omega_err_max", 1.25e-3}, {"unstable", 0.0}};
    const std::string results = results_csv({r}), runs = runs_csv({r});
    const auto refused = [&](const std::string& res, const std::string& run) { return error_of([&] { parse_results(res, run, {}, "d"); }); };
    CHECK_THAT(refused(results, runs.substr(0, runs.find('\n') + 1)), Catch::Contains("d/runs.csv: no run in the file"));
    CHECK_THAT(refused(results.substr(0, results.size() - 10), runs), Catch::Contains("d/results.csv:3: the file ends in the middle"));
    CHECK_THAT(refused(results.substr(0, results.rfind("dipole_top")), runs), Catch::Contains("d/results.csv: ends before the metrics of run 1"));
    CHECK_THAT(refused(results + "dipole_top,direct,0.01,extra,1\n", runs), Catch::Contains("d/results.csv:4: a row that no run"));
    std::string wrong_value = results;
    wrong_value.replace(wrong_value.find("0.00125"), 7, "lots");
    CHECK_THAT(refused(wrong_value, runs), Catch::Contains("d/results.csv:2: 'lots' is not a number"));
    std::string wrong_kind = runs;
    wrong_kind.replace(wrong_kind.find("trajectory"), 10, "sideways");
    CHECK_THAT(refused(results, wrong_kind), Catch::Contains("unknown run kind 'sideways'"));
    std::string wrong_count = runs;
    wrong_count.replace(wrong_count.find(",2,"), 3, ",x,");
    CHECK_THAT(refused(results, wrong_count), Catch::Contains("d/runs.csv:2: 'metrics' is not a count"));
    std::string other_run = results;
    other_run.replace(other_run.find("direct"), 6, "zvw000");
    CHECK_THAT(refused(other_run, runs), Catch::Contains("d/results.csv:2: a row of another run"));
}
