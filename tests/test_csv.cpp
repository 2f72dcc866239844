// The CSV writer and reader (harness/store/csv.hpp) and the run files built on them: whatever a
// field holds comes back as written, and a file that was cut, edited or mistyped is refused
// with its file and line, never read as results.
#include "harness/store/csv.hpp"
#include "harness/store/results_csv.hpp"
#include "harness/store/run_record.hpp"

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

TEST_CASE("run files: runs with any failure text and parameters come back from the store, and its CSVs are exports of it") {
    RunResult r;
    r.spec = {"dipole_top", "direct", 0.01, 10.0, {{"field", {0.0, 0.0, 2.5}}, {"q0", {1.0, 0.0, 0.0, 0.0}}}, RunKind::trajectory};
    r.failure = "threw: a message, with \"quotes\"\nand a line break";
    r.metrics = {{"omega_err_max", 1.25e-3}, {"unstable", 1.0}};
    r.timing_samples = {0.5, 0.25};
    RunResult twin = r;  // the same scene, scheme and dt: told apart by their order
    twin.spec.t_end = 5.0;
    twin.failure.clear();
    twin.metrics = {{"omega_err_max", 2.5e-3}};
    const auto back = parse_run_store(run_store({r, twin}), "dir/runs.jsonl");
    REQUIRE(back.size() == 2);
    CHECK(back[0].spec == r.spec);
    CHECK(back[0].failure == r.failure);
    CHECK(back[0].metrics == r.metrics);
    CHECK(back[0].timing_samples == r.timing_samples);
    CHECK(back[1].spec == twin.spec);
    CHECK(back[1].metrics == twin.metrics);
    CHECK(results_csv(back) == results_csv({r, twin}));
    CHECK(runs_csv(back) == runs_csv({r, twin}));
}

TEST_CASE("run files: a cut, empty, reordered or forged store is refused with the file and the run") {
    RunResult r;
    r.spec = {"dipole_top", "direct", 0.01, 10.0, {}, RunKind::trajectory};
    r.metrics = {{"omega_err_max", 1.25e-3}, {"unstable", 0.0}};
    const std::string store = run_store({r, r});
    const auto refused = [&](const std::string& text) { return error_of([&] { parse_run_store(text, "d/runs.jsonl"); }); };
    CHECK_THAT(refused(""), Catch::Contains("d/runs.jsonl: no run in the store"));
    CHECK_THAT(refused(store.substr(0, store.size() - 10)), Catch::Contains("d/runs.jsonl: cut short or not a run store after 1 runs"));
    CHECK_THAT(refused(store + "scene,scheme\n"), Catch::Contains("cut short or not a run store after 2 runs"));
    CHECK_THAT(refused(run_record(1, r)), Catch::Contains("d/runs.jsonl: run 1 where run 0 is due"));
    std::string wrong_value = store;
    wrong_value.replace(wrong_value.find("0.00125"), 7, "\"lots\"");
    CHECK_THAT(refused(wrong_value), Catch::Contains("the record of run 0 is malformed: not a number: \"lots\""));
    std::string wrong_kind = store;
    wrong_kind.replace(wrong_kind.find("trajectory"), 10, "sideways");
    CHECK_THAT(refused(wrong_kind), Catch::Contains("unknown run kind 'sideways'"));
    std::string not_an_id = store;
    not_an_id.replace(not_an_id.find("dipole_top"), 10, "dipole top");
    CHECK_THAT(refused(not_an_id), Catch::Contains("d/runs.jsonl: run 0: a scene or scheme id that is not one"));
    std::string negative_dt = store;
    negative_dt.replace(negative_dt.find("\"dt\":0.01"), 9, "\"dt\":-0.01");
    CHECK_THAT(refused(negative_dt), Catch::Contains("dt or t_end out of range"));
}
