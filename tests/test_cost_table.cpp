// The report's cost section and the work-precision plots' instruction panel, from a cost.csv
// as benchmarks/cost.sh writes it.
#include "reports/convergence_plots.hpp"
#include "reports/cost_table.hpp"
#include "harness/io/output_files.hpp"

#include <catch2/catch.hpp>
#include <unistd.h>

using namespace rotbench;

namespace {

std::filesystem::path fresh_dir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// Two schemes; the numbers are chosen so that every derived figure is a round one.
const char* cost_csv =
    "scheme,ns_batched,ns_batched_spread,ns_alone,ns_alone_spread,speedup,instr_batched,instr_alone,ns_ratio_to_direct,"
    "instr_ratio_to_direct,libm_instr_alone,memory_share,speedup_runs_differ,ns_ratio_runs_differ\n"
    "load_store,10,0.01,,,,,,,,,,,\n"
    "direct,20,0.02,80,0.03,4,150,600,1,1,150,0.5,0.012,0\n"
    "zvw,40,0.05,120,0.01,3,200,900,2,1.3333,300,0.25,0.004,0.021\n";

}  // namespace

TEST_CASE("the cost section shows for every scheme its times and instructions and limits and ratios and the repeatability") {
    const auto dir = fresh_dir("rotbench_cost_table");
    write_file_atomically(dir / "cost.csv", cost_csv);
    const std::string md = cost_section(dir);
    // libm share 150/600 = 25 %, memory share 50 %.
    CHECK(md.find("| direct | 20.0 | 2.0 % | 80.0 | 3.0 % | 4.00x | 150 | 600 | 25 % | 50 % | 1.00 | 1.00 |") != std::string::npos);
    CHECK(md.find("| zvw | 40.0 | 5.0 % | 120.0 | 1.0 % | 3.00x | 200 | 900 | 33 % | 25 % | 2.00 | 1.33 |") != std::string::npos);
    CHECK(md.find("| load_store | 10.0 | 1.0 % |") != std::string::npos);
    CHECK(md.find("Largest spread of a time over its repetitions: 5.0 % (zvw).") != std::string::npos);
    CHECK(md.find("agree within 1.2 % on every speed-up (largest difference: direct) and within 2.1 % on every "
                  "ns / direct (largest: zvw)") != std::string::npos);
    CHECK(instructions_per_body_step(dir) == std::map<std::string, double>{{"direct", 600.0}, {"zvw", 900.0}});
    std::filesystem::remove_all(dir);
}

TEST_CASE("without cost.csv the report says how to measure it and the plots have no instruction panel") {
    const auto dir = fresh_dir("rotbench_cost_absent");
    CHECK(cost_section(dir).find("`benchmarks/cost.sh BUILD ") != std::string::npos);
    CHECK(instructions_per_body_step(dir).empty());
    std::filesystem::remove_all(dir);
}

TEST_CASE("the work-precision data carry the scheme instructions of each run: per body-step count times body-steps") {
    const auto dir = fresh_dir("rotbench_cost_plot");
    auto run = [](const char* scheme, double dt, double steps, double error) {
        RunResult r{{"asymmetric_free", scheme, dt, 0.0}, {}, {}};
        r.metrics = {{"omega_err_max", error}, {"cpu_seconds", 1e-3}, {"force_evals", steps + 1}, {"steps", steps}};
        return r;
    };
    const RunResult a = run("direct", 1e-2, 100, 1e-3), b = run("zvw", 1e-2, 100, 1e-5);
    const OutputDir out = OutputDir::open(dir, {"run", "", {}});
    convergence_plots("asymmetric_free", 1, {&a, &b}, out, {{"direct", 600.0}, {"zvw", 900.0}});
    const auto data = read_file(dir / "plots" / "runs_asymmetric_free.dat");
    REQUIRE(data);
    CHECK(data->find("0.01 0.001 0.001 101 60000\n") != std::string::npos);   // one body, 100 steps, 600 per step
    CHECK(data->find("0.01 1e-05 0.001 101 90000\n") != std::string::npos);
    const auto script = read_file(dir / "plots" / "work_precision_asymmetric_free.gp");
    REQUIRE(script);
    CHECK(script->find("titles = 'direct(1.00x) zvw(1.50x)'") != std::string::npos);
    CHECK(script->find("using 5:2") != std::string::npos);
    // A scheme without a count: no instruction panel, rather than a panel that leaves it out.
    convergence_plots("asymmetric_free", 1, {&a, &b}, out, {{"direct", 600.0}});
    CHECK(read_file(dir / "plots" / "work_precision_asymmetric_free.gp")->find("using 5:2") == std::string::npos);
    std::filesystem::remove_all(dir);
}
