// The cost judge on a loaded machine: a scheme and direct timed in turn (RunKind::cost), judged
// failing only when the median ratio's interval lies wholly above the bound. Run with both
// cores of the machine kept busy by this test, as a shared CI runner would be.
#include "tests/cli_helpers.hpp"

#include <atomic>
#include <catch2/catch.hpp>
#include <thread>

using namespace rotbench::test;

namespace {

// Spins on every core while alive.
class BusyMachine {
public:
    BusyMachine() {
        for (unsigned i = 0; i < std::max(2u, std::thread::hardware_concurrency()); ++i)
            threads_.emplace_back([this] {
                volatile double x = 1.0;
                while (!stop_) x = x * 1.0000001 + 1e-9;
            });
    }
    ~BusyMachine() {
        stop_ = true;
        for (auto& t : threads_) t.join();
    }

private:
    std::atomic<bool> stop_{false};
    std::vector<std::thread> threads_;
};

}  // namespace

TEST_CASE("cost: a copy of direct passes and the same kernel made twice fails, with every core busy") {
    const fs::path dir = fresh_dir("cost_claims");
    fs::create_directories(dir);
    // 1.5 lies between the two true ratios: 1 (the same code) and about 2 (each kernel made twice).
    write(dir / "cost.toml", "[[check]]\nname = \"cost\"\nscene = \"cylinder_free\"\nschemes = [\"plugin_direct\", "
                             "\"plugin_direct_slowed\"]\nmax_cost_ratio = 1.5\ndt = 1e-4\n");
    const BusyMachine busy;
    const Cli r = binary({"gate", (dir / "cost.toml").string(), "--plugin", PLUGIN_COSTED_DIRECT});
    INFO(r.out << r.err);
    CHECK(r.status == 1);
    CHECK_THAT(r.out, Catch::Contains("PASS cylinder_free/plugin_direct: "));
    CHECK_THAT(r.out, Catch::Contains("FAIL cylinder_free/plugin_direct_slowed: "));
    CHECK_THAT(r.out, Catch::Contains("the whole interval is above"));
    fs::remove_all(dir);
}

TEST_CASE("cost: the default gate's cost checks pass on a sound build with every core busy, plug-ins included") {
    const fs::path dir = fresh_dir("cost_default");
    fs::create_directories(dir);
    const std::string checks = default_gate_checks(true);
    REQUIRE(checks.find("max_cost_ratio") != std::string::npos);
    write(dir / "cost.toml", checks);
    const BusyMachine busy;
    const Cli r = binary({"gate", (dir / "cost.toml").string(), "--plugin", PLUGIN_COSTED_DIRECT});
    INFO(r.out << r.err);
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("PASS cylinder_free/plugin_direct: "));  // "*" covers plug-ins
    CHECK_THAT(r.out, Catch::Contains("0 failed"));
    fs::remove_all(dir);
}

TEST_CASE("cost: a plug-in built unoptimised or with assertions is flagged at load and its cost not judged") {
    const fs::path dir = fresh_dir("cost_unoptimised");
    fs::create_directories(dir);
    write(dir / "cost.toml", "[[check]]\nname = \"cost\"\nscene = \"cylinder_free\"\nschemes = [\"plugin_direct\"]\n"
                             "max_cost_ratio = 8\ndt = 1e-4\n");
    const Cli r = binary({"gate", (dir / "cost.toml").string(), "--plugin", PLUGIN_UNOPTIMISED});
    INFO(r.out << r.err);
    CHECK(r.status == 1);
    CHECK_THAT(r.err, Catch::Contains("rotbench: warning: plug-in ") && Catch::Contains("was built unoptimised, assertions on"));
    CHECK_THAT(r.out, Catch::Contains("FAIL cylinder_free/plugin_direct: plugin_direct: cost on cylinder_free: not judged: plug-in "));
    // Built as the built-in schemes are: no warning.
    const Cli same = binary({"gate", (dir / "cost.toml").string(), "--plugin", PLUGIN_COSTED_DIRECT});
    CHECK(same.status == 0);
    CHECK_THAT(same.err, !Catch::Contains("warning"));
    fs::remove_all(dir);
}
