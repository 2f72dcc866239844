// Clients (docs/clients.md): a scheme run by a program outside rotbench is swept, gated and judged
// like a built-in one; a program that writes garbage, hangs or crashes is one failed run; a bad
// client file is refused in one line. The program of these tests is rotbench itself, behind
// tests/clients/rotbench_client.py, so its runs must equal the built-in's bit for bit.
#include "cli_helpers.hpp"
#include "harness/analysis/scheme_verdicts.hpp"
#include "harness/store/results_csv.hpp"
#include "harness/exec/client_run.hpp"
#include "harness/exec/executor.hpp"
#include "harness/store/client.hpp"

#include <catch2/catch.hpp>
#include <regex>
#include <unistd.h>
#include <chrono>
#include <thread>
#include <sys/wait.h>
#include <csignal>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <sstream>

using namespace rotbench;
using namespace rotbench::test;

namespace {

const std::string script = std::string(ROTBENCH_SOURCE_DIR) + "/tests/clients/rotbench_client.py";

// A client file for rotbench's own `scheme` behind the test script, with a fault when given.
fs::path client_file(const fs::path& dir, const std::string& id, const std::string& scheme, const std::string& fault = "",
                     const std::string& extra = "claims = \"no_squish\"\n") {
    fs::create_directories(dir);
    const fs::path file = dir / (id + ".toml");
    std::string program = "\"python3\", \"" + script + "\", \"" + ROTBENCH_EXE + "\", \"" + scheme + "\"";
    if (!fault.empty()) program += ", \"" + fault + "\"";
    write(file, "id = \"" + id + "\"\nprogram = [" + program + "]\nscenes = [\"asymmetric_free\", \"dipole_top\", \"torqued_cylinder\"]\n" + extra);
    return file;
}

}  // namespace

TEST_CASE("clients: a client whose program is rotbench's own scheme gives the built-in's metrics, bit for bit") {
    const fs::path dir = fresh_dir("client_same");
    load_client(client_file(dir, "client_no_squish", "no_squish").string());
    for (const RunSpec& spec : {RunSpec{"asymmetric_free", "no_squish", 0.05, 0.0}, RunSpec{"dipole_top", "no_squish", 0.01, 0.0},
                                RunSpec{"torqued_cylinder", "no_squish", 0.01, 0.0}, RunSpec{"dipole_top", "no_squish", 0.01, 0.0, {}, RunKind::horizon}}) {
        RunSpec through = spec;
        through.scheme = "client_no_squish";
        const RunResult a = made(spec), b = made(through);
        INFO(spec.scene << " " << kind_name(spec.kind) << ": " << b.failure);
        REQUIRE(b.failure.empty());
        std::size_t compared = 0;
        for (const auto& [name, value] : a.metrics) {
            if (is_timing_metric(name)) continue;
            INFO(name << " " << value << " " << b.value(name));
            CHECK(b.has(name));
            CHECK((value == b.value(name) || (std::isnan(value) && std::isnan(b.value(name)))));
            ++compared;
        }
        CHECK(compared >= (spec.kind == RunKind::horizon ? 2u : 10u));
    }
    fs::remove_all(dir);
}

TEST_CASE("clients: a program that writes garbage, a short or non-finite trajectory, hangs or crashes is one failed run") {
    const fs::path dir = fresh_dir("client_faults");
    const fs::path scratch = dir / "tmp";
    fs::create_directories(scratch);
    ::setenv("TMPDIR", scratch.c_str(), 1);
    const std::vector<std::pair<std::string, std::string>> faults = {
        {"--garbage", "its trajectory is malformed: its trajectory.csv:1: expected the header 't,qw,qx,qy,qz,wx,wy,wz'"},
        {"--short", "its trajectory has 200 rows; 201 are due, one at every step t = k dt, k = 0 ... 200"},
        {"--huge", "its trajectory.csv is larger than 201 rows of 8 numbers can make it (107008 bytes)"},  // 4096 + 64 x 8 x 201: not read
        {"--nan", "its trajectory.csv:102:6 (wx): a value that is not finite (nan)"},  // line and column
        {"--crash", "crashed: signal 11 (Segmentation fault) in its program process"},
    };
    for (const auto& [fault, message] : faults) {
        const std::string id = "client" + std::string(fault.begin() + 2, fault.end());
        load_client(client_file(dir, id, "direct", fault).string());
        const RunResult r = made({"asymmetric_free", id, 0.1, 0.0});
        INFO(fault);
        CHECK_THAT(r.failure, Catch::StartsWith(message));
        CHECK(r.value(metric::unstable) == 1.0);
    }
    load_client(client_file(dir, "client_hang", "direct", "--hang").string());
    std::ostringstream out, err;
    Executor executor(out, err, {.run = {.measure_time = false, .run_timeout = 1.5}, .quiet = true});
    CHECK(executor.run(RunSpec{"asymmetric_free", "client_hang", 0.1, 0.0}).failure ==
          "exceeded the run time limit of 1.5 s (--run-timeout); its program was killed");
    // A scene the client file does not list, and a kind a client does not make.
    CHECK_THAT(made({"cylinder_free", "client_hang", 0.1, 0.0}).failure, Catch::StartsWith("client client_hang does not take scene cylinder_free"));
    CHECK(made({"asymmetric_free", "client_hang", 0.1, 0.0, {}, RunKind::reversal}).failure ==
          "a client makes runs of kind trajectory and horizon, not reversal");
    CHECK(fs::is_empty(scratch));  // every scratch directory is gone, with what the programs left there
    ::unsetenv("TMPDIR");
    fs::remove_all(dir);
}

TEST_CASE("clients: SIGHUP stops a sweep whose client hangs, and leaves no scratch folder behind, and nohup keeps it ignored") {
    const fs::path dir = fresh_dir("client_hangup");
    const fs::path scratch = dir / "tmp";
    fs::create_directories(scratch);
    const fs::path file = client_file(dir, "client_hangup", "direct", "--hang");
    const auto start = [&](bool nohup) {
        const pid_t pid = ::fork();
        if (pid == 0) {
            if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)) _exit(126);
            if (nohup) ::signal(SIGHUP, SIG_IGN);  // as nohup(1) starts a program
            ::setenv("TMPDIR", scratch.c_str(), 1);
            execl(ROTBENCH_EXE, ROTBENCH_EXE, "--client", file.c_str(), "run", "--schemes", "client_hangup", "--scenes", "asymmetric_free",
                  "--dt", "0.05", "--run-timeout", "600", "--out", (dir / "out").c_str(), "--overwrite", nullptr);
            _exit(127);
        }
        const auto started = std::chrono::steady_clock::now();
        while (fs::is_empty(scratch) && std::chrono::steady_clock::now() - started < std::chrono::seconds(60))
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the program started in it
        return pid;
    };
    const auto ended_by = [](pid_t pid, int signal) {
        ::kill(pid, signal);
        int status = 0;
        ::waitpid(pid, &status, 0);
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    };
    CHECK(ended_by(start(false), SIGHUP) == 128 + SIGHUP);
    CHECK(fs::is_empty(scratch));
    const pid_t ignoring = start(true);
    ::kill(ignoring, SIGHUP);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // it looks at signals every 0.1 s
    CHECK(::waitpid(ignoring, nullptr, WNOHANG) == 0);            // still running
    CHECK(ended_by(ignoring, SIGTERM) == 128 + SIGTERM);
    CHECK(fs::is_empty(scratch));
    fs::remove_all(dir);
}

TEST_CASE("clients: the scene spec holds the body, its initial state in both frames and its torque law") {
    const auto scene = make_scene("dipole_top", {{"field", {0.0, 0.5, 1.0}}});
    const auto spec = nlohmann::json::parse(client_scene_json(*scene, {"dipole_top", "x", 0.01, 10.0}, 10.0, 1000));
    const Bodies b = scene->initial_state();
    const Quat q0 = b.orientation[0];
    CHECK(spec.at("steps") == 1000);
    CHECK(spec.at("columns") == "t,qw,qx,qy,qz,wx,wy,wz");
    CHECK(spec.at("q0") == std::vector<double>{q0.w(), q0.x(), q0.y(), q0.z()});
    CHECK(spec.at("torque").at("law") == "dipole");
    CHECK(spec.at("torque").at("field_world") == std::vector<double>{0.0, 0.5, 1.0});
    // L0 in the world frame is the body-frame L0 rotated by q0, which is I' times the body-frame w0.
    const auto v = [&](const char* key) {
        const auto a = spec.at(key).get<std::vector<double>>();
        return Vec3(a[0], a[1], a[2]);
    };
    CHECK((to_world(q0, v("L0_body")) - v("L0_world")).norm() < 1e-15 * v("L0_world").norm());  // one rotation's round-off
    CHECK(v("L0_body") == v("inertia_body").cwiseProduct(v("omega0_body")));
    CHECK_THROWS_WITH(client_scene_json(*make_scene("fibre_bounce"), {"fibre_bounce", "x", 1e-5, 0.0}, 1e-3, 100),
                      Catch::Contains("not one body under a torque law a client can take"));
}

TEST_CASE("clients: every scene that states its torque law gives, by that law, the torque it applies") {
    for (const auto& id : SceneRegistry::instance().ids()) {
        const auto scene = make_scene(id);
        const auto law = scene->torque_law();
        if (!law) continue;
        INFO(id);
        Bodies b = scene->initial_state();
        REQUIRE(b.size() == 1);
        b.orientation.set(0, Quat(0.8, 0.1, -0.5, 0.3).normalized());  // away from the initial orientation
        scene->evaluate_forces(b, 0.0);
        Vec3 expected = Vec3::Zero();
        const auto parameter = [&](const std::string& name) {
            for (const auto& [n, value] : law->parameters)
                if (n == name) return value;
            FAIL("no parameter " << name);
            return Vec3();
        };
        if (law->law == "body_constant") expected = to_world(b.orientation[0], parameter("torque_body"));
        else if (law->law == "dipole") expected = to_world(b.orientation[0], parameter("dipole_body")).cross(parameter("field_world"));
        else REQUIRE(law->law == "none");
        CHECK((b.torque[0] - expected).norm() <= 1e-15 * std::max(1.0, expected.norm()));
    }
}

TEST_CASE("clients: a bad client file is refused in one line naming the file, line and column") {
    const fs::path dir = fresh_dir("client_bad");
    fs::create_directories(dir);
    const auto refused = [&](const std::string& text) {
        write(dir / "c.toml", text);
        const Cli r = cli({"--client", (dir / "c.toml").string(), "list"});
        CHECK(r.status == 2);
        CHECK(one_line(r.err));
        return r.err;
    };
    const std::string ok = "id = \"c\"\nprogram = [\"true\"]\nscenes = [\"asymmetric_free\"]\n";
    CHECK_THAT(refused("id = \"c\"\n"), Catch::Contains("c.toml:1:1: the client file has no 'program'"));
    CHECK_THAT(refused(ok + "claims = \"rk4\"\n"), Catch::Contains("c.toml:4:10: claims = 'rk4': not a built-in scheme"));
    CHECK_THAT(refused(ok + "claims = \"fincham\"\ncolour = 1\n"), Catch::Contains("c.toml:5:10: unknown key 'colour'"));
    CHECK_THAT(refused(ok + "claims = \"fincham\"\nsound = false\n"), Catch::Contains("sound = false needs an unsound_reason"));
    CHECK_THAT(refused(ok + "[claims]\norder_with_torque = 9\n"), Catch::Contains("'order_with_torque' must be an order from 0 to 8"));
    CHECK_THAT(refused("id = \"direct\"\nprogram = [\"true\"]\nscenes = [\"asymmetric_free\"]\nclaims = \"direct\"\n"),
               Catch::Contains("c.toml:1:6: scheme 'direct' is already registered"));
    CHECK_THAT(refused(ok + "claims = \"fincham\"\nscenes2 = 1\n"), Catch::Contains("unknown key 'scenes2'"));
    CHECK_THAT(refused("id = \"c\"\nprogram = [\"true\"]\nscenes = [\"asymmetric_fre\"]\nclaims = \"direct\"\n"),
               Catch::Contains("unknown scene 'asymmetric_fre'"));
    // A folder whose path holds "{dir}": substituted once, not again and again (it never ended).
    const fs::path odd = dir / "x{dir}y";
    fs::create_directories(odd);
    write(odd / "c.toml", "id = \"c_odd\"\nprogram = [\"{dir}/run.sh\"]\nscenes = [\"asymmetric_free\"]\nclaims = \"direct\"\n");
    write(odd / "run.sh", "#!/bin/sh\n");
    fs::permissions(odd / "run.sh", fs::perms::owner_all);
    const Cli odd_dir = cli({"--client", (odd / "c.toml").string(), "list"});
    CHECK(odd_dir.status == 0);
    // The same client file through a symlink is the same client, loaded once; {dir} its real folder.
    fs::create_symlink(odd / "c.toml", dir / "link.toml");
    const Cli linked = cli({"--client", (odd / "c.toml").string(), "--client", (dir / "link.toml").string(), "list"});
    CHECK(linked.status == 0);
    // A program that cannot be started is refused at load, by its path, not found out as "status 127" per run.
    CHECK_THAT(refused("id = \"c\"\nprogram = [\"no_such_program_here\"]\nscenes = [\"asymmetric_free\"]\nclaims = \"direct\"\n"),
               Catch::Contains("c.toml:2:11: program 'no_such_program_here' is not found on PATH"));
    CHECK_THAT(refused("id = \"c\"\nprogram = [\"{dir}/missing.py\"]\nscenes = [\"asymmetric_free\"]\nclaims = \"direct\"\n"),
               Catch::Contains("program '" + (fs::absolute(dir) / "missing.py").lexically_normal().string() + "' cannot be executed: no such file"));
    write(dir / "data.txt", "not a program\n");
    CHECK_THAT(refused("id = \"c\"\nprogram = [\"{dir}/data.txt\"]\nscenes = [\"asymmetric_free\"]\nclaims = \"direct\"\n"),
               Catch::Contains("data.txt' cannot be executed: not an executable file"));
    // An id is part of file names: a long one would fail the outputs once the runs are made.
    const std::string long_id(max_id_length + 1, 'c');
    CHECK_THAT(refused("id = \"" + long_id + "\"\nprogram = [\"true\"]\nscenes = [\"asymmetric_free\"]\nclaims = \"direct\"\n"),
               Catch::Contains("c.toml:1:6: id '" + long_id + "' is not 1 to 64 letters, digits and underscores"));
    fs::remove_all(dir);
}

TEST_CASE("clients: a program that passes the load check but cannot be executed says why, not \"status 127\"") {
    const fs::path dir = fresh_dir("client_exec_fails");
    fs::create_directories(dir);
    write(dir / "bad.sh", "#!/nonexistent/interpreter\n");  // executable, but execve finds no interpreter
    fs::permissions(dir / "bad.sh", fs::perms::owner_all);
    write(dir / "c.toml", "id = \"c_exec\"\nprogram = [\"{dir}/bad.sh\"]\nscenes = [\"asymmetric_free\"]\nclaims = \"direct\"\n");
    const Cli r = cli({"--client", (dir / "c.toml").string(), "run", "--scenes", "asymmetric_free", "--schemes", "c_exec", "--quick",
                       "--out", (dir / "out").string()});
    CHECK(r.status == 0);  // every run recorded as failed, the sweep goes on
    const std::string runs = read(dir / "out" / "runs.csv");
    CHECK_THAT(runs, Catch::Contains("could not start its program '" + (fs::absolute(dir) / "bad.sh").lexically_normal().string() +
                                     "': No such file or directory"));
    CHECK_THAT(runs, !Catch::Contains("status 127"));
    fs::remove_all(dir);
}

TEST_CASE("clients: `run --client` sweeps a client beside the built-ins and says which scenes it skips") {
    const fs::path dir = fresh_dir("client_run");
    const fs::path file = client_file(dir, "client_no_squish", "no_squish");
    const Cli r = cli({"--client", file.string(), "run", "--scenes", "asymmetric_free,cylinder_free", "--schemes", "no_squish,client_no_squish",
                       "--quick", "--quiet", "--out", (dir / "out").string()});
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("skipped: client client_no_squish does not take scene cylinder_free"));
    const std::string orders = read(dir / "out" / "orders.csv");
    CHECK_THAT(orders, Catch::Contains("asymmetric_free,client_no_squish,omega_err_max,fit,2.00"));
    // Alone, a client's runs have no CPU time: a convergence plot, and no work-precision plot to fail.
    REQUIRE(cli({"--client", file.string(), "run", "--scenes", "asymmetric_free", "--schemes", "client_no_squish", "--quick", "--quiet",
                 "--out", (dir / "alone").string()})
                .status == 0);
    const std::string report = read(dir / "alone" / "report.md");
    CHECK_THAT(report, Catch::Contains("(plots/convergence_asymmetric_free.svg)"));
    CHECK_THAT(report, !Catch::Contains("plots not drawn") && !Catch::Contains("work_precision"));
    fs::remove_all(dir);
}

TEST_CASE("clients: the example client, the midpoint rule in Python, holds its claimed order 2 in the default gate") {
    const Cli r = cli({"--client", std::string(ROTBENCH_SOURCE_DIR) + "/examples/clients/python_rk2/client.toml", "gate", DEFAULT_GATE,
                       "--schemes", "python_rk2"});
    INFO(r.out << r.err);
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("PASS dipole_top/python_rk2: python_rk2: order_with_torque on dipole_top: observed order 2.00"));
    CHECK_THAT(r.out, Catch::Contains("4 checks: 4 passed, 0 failed"));
    CHECK_THAT(r.out, Catch::Contains("WARNING client python_rk2 does not take scene sphere_pair"));
}

TEST_CASE("clients: each client run records its program's CPU and wall time, a built-in run none") {
    const fs::path dir = fresh_dir("client_time");
    const fs::path file = client_file(dir, "client_timed", "no_squish");
    const Cli r = cli({"--client", file.string(), "run", "--scenes", "asymmetric_free", "--schemes", "no_squish,client_timed", "--dt",
                       "0.05", "--quiet", "--out", (dir / "out").string()});
    INFO(r.err);
    REQUIRE(r.status == 0);
    for (const RunResult& run : read_results((dir / "out").string())) {
        INFO(run.spec.scheme << " " << kind_name(run.spec.kind));
        if (run.spec.scheme == "client_timed") {
            // The program is python3 running `rotbench trajectory`: at least the interpreter's start.
            CHECK(run.value(metric::client_wall_seconds) > 0.0);
            CHECK(run.value(metric::client_cpu_seconds) > 0.0);
        } else {
            CHECK_FALSE(run.has(metric::client_wall_seconds));
        }
    }
    // The verdicts' cost column: the client's own figure, marked, beside the built-in's CPU time.
    const std::string md = read(dir / "out" / "report.md");
    const auto row = md.find("| `client_timed` |");
    REQUIRE(row != std::string::npos);
    CHECK(md.substr(row, md.find('\n', row) - row).find("(client, wall) |") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("clients: `client scene` writes the scene.json a run hands over, the user's parameters last") {
    const Cli r = cli({"client", "scene", "dipole_top", "--dt", "0.01", "--set", "q0=1,0,0,0"});
    REQUIRE(r.status == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["format"] == "rotbench-client-scene 1");
    CHECK(j["steps"] == 1000);  // 10 s at 0.01 s
    CHECK(j["q0"] == nlohmann::json::array({1.0, 0.0, 0.0, 0.0}));
    CHECK(r.out.find("\"params\"") > r.out.find("\"columns\""));  // a scanner meets the scene's own q0 first
    const Cli horizon = cli({"client", "scene", "dipole_top", "--dt", "0.01", "--horizon"});
    CHECK(nlohmann::json::parse(horizon.out)["steps"] == 8000);  // the horizon run: 8 times the duration
    const Cli coarsest = cli({"client", "scene", "asymmetric_free"});
    CHECK(nlohmann::json::parse(coarsest.out)["dt"] == 0.1);  // the scene's coarsest step
}

TEST_CASE("clients: `client check` runs a program once and names what is wrong with its output, line and column") {
    const fs::path dir = fresh_dir("client_check");
    const Cli good = cli({"client", "check", client_file(dir, "client_checked", "no_squish", "", "claims = \"no_squish\"\ncounterpart = \"no_squish\"\n").string()});
    INFO(good.out << good.err);
    CHECK(good.status == 0);
    CHECK_THAT(good.out, Catch::Contains("ok: its output read") && Catch::Contains("against no_squish: largest |dw| 0 rad/s"));
    const Cli bad = cli({"client", "check", client_file(dir, "client_nan", "no_squish", "--nan").string()});
    CHECK(bad.status == 1);
    CHECK_THAT(bad.out, Catch::Contains("FAIL: its trajectory.csv:") && Catch::Contains("(wx): a value that is not finite"));
    fs::remove_all(dir);
}

TEST_CASE("clients: a program that exits 3 declines a scene: skipped with its reason in run, report and gate, not failed") {
    const fs::path dir = fresh_dir("client_decline");
    const fs::path file = client_file(dir, "client_decliner", "no_squish", "--decline-torque");
    const Cli r = cli({"--client", file.string(), "run", "--scenes", "asymmetric_free,dipole_top", "--schemes", "client_decliner", "--quick",
                       "--out", (dir / "out").string()});
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("skipped: dipole_top client_decliner trajectory dt=0.01: client declined: rotbench_client.py: "
                                      "this client takes no torque"));
    CHECK(r.out.find("FAILED") == std::string::npos);
    const std::string md = read(dir / "out" / "report.md");
    CHECK_THAT(md, Catch::Contains("- Skipped: client `client_decliner` on `dipole_top` at dt = 0.01 (trajectory run), declined: "
                                   "rotbench_client.py: this client takes no torque"));
    CHECK_THAT(md, Catch::Contains(", 0 of them unstable or failed"));  // the declined runs are in no table
    const std::string orders = read(dir / "out" / "orders.csv");
    CHECK(orders.find("asymmetric_free,client_decliner") != std::string::npos);
    CHECK(orders.find("dipole_top,client_decliner") == std::string::npos);
    // The gate: the torque claim not judged, a warning saying why; the free claims judged and passed.
    const Cli g = cli({"--client", file.string(), "gate", DEFAULT_GATE, "--schemes", "client_decliner"});
    INFO(g.out);
    CHECK(g.status == 0);
    CHECK_THAT(g.out, Catch::Contains("WARNING client client_decliner declined scene dipole_top (declined: rotbench_client.py: this client "
                                      "takes no torque): not judged there"));
    CHECK_THAT(g.out, Catch::Contains("PASS asymmetric_free/client_decliner"));
    fs::remove_all(dir);
}

TEST_CASE("clients: compare says when a client's program files changed between two folders") {
    const fs::path dir = fresh_dir("client_changed");
    const fs::path file = client_file(dir, "client_versioned", "no_squish");
    const Cli r = cli({"--client", file.string(), "run", "--scenes", "asymmetric_free", "--schemes", "client_versioned", "--dt", "0.05",
                       "--quiet", "--out", (dir / "a").string()});
    REQUIRE(r.status == 0);
    // Folder b: the same runs, recorded with another hash of the program's files (its adapter edited).
    fs::copy(dir / "a", dir / "b", fs::copy_options::recursive);
    auto schemes = nlohmann::json::parse(read(dir / "b" / "schemes.json"));
    const std::string before = schemes["client_versioned"]["client_files"]["program_hash"];
    CHECK(before.size() == 16);  // FNV-1a of python3 and the script, hex
    schemes["client_versioned"]["client_files"]["program_hash"] = "0000000000000000";
    write(dir / "b" / "schemes.json", schemes.dump());
    const Cli c = cli({"compare", (dir / "a").string(), (dir / "b").string(), "--cost-tolerance", "100"});
    INFO(c.out << c.err);
    CHECK(c.status == 0);  // the same results: no regression, but the reader is told
    CHECK_THAT(c.out, Catch::Contains("WARNING client client_versioned: its program's files changed (FNV-1a " + before + " -> 0000000000000000)"));
    fs::remove_all(dir);
}

TEST_CASE("clients: a descendant that leaves the program's process group (setsid) does not outlive the run") {
    const fs::path dir = fresh_dir("client_setsid");
    fs::create_directories(dir);
    // The program forks; the child calls setsid and forks a grandchild that sleeps, writing its
    // pid; the program waits for that pid and exits 1 (a failed run), its group killed as usual.
    const fs::path pids = dir / "pids";
    write(dir / "escape.py", "import os, sys, time\n"
                             "if os.fork() == 0:\n"
                             "    os.setsid()\n"
                             "    if os.fork() == 0:\n"
                             "        open(" + std::string("'") + pids.string() + "', 'a').write('%d\\n' % os.getpid())\n"
                             "        time.sleep(120)\n"
                             "    os._exit(0)\n"
                             "while not os.path.exists('" + pids.string() + "'): time.sleep(0.01)\n"
                             "time.sleep(0.1)\n"
                             "sys.exit(1)\n");
    write(dir / "escape.toml", "id = \"client_escape\"\nprogram = [\"python3\", \"" + (dir / "escape.py").string() +
                                   "\"]\nscenes = [\"asymmetric_free\"]\nclaims = \"direct\"\n");
    load_client((dir / "escape.toml").string());
    const RunResult r = made({"asymmetric_free", "client_escape", 0.1, 0.0});
    CHECK_THAT(r.failure, Catch::Contains("exited with status 1"));
    REQUIRE(fs::exists(pids));
    const pid_t escaped = std::stoi(read(pids));
    // Killed: gone, or a zombie its new parent has not reaped yet; never still sleeping.
    const auto alive = [&] {
        const auto stat = read_file(fs::path("/proc") / std::to_string(escaped) / "stat");
        return stat && stat->find(") Z ") == std::string::npos;
    };
    for (int i = 0; i < 100 && alive(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));  // SIGKILL is delivered at once, reaped soon
    CHECK_FALSE(alive());
    if (alive()) ::kill(escaped, SIGKILL);
    fs::remove_all(dir);
}

TEST_CASE("clients: two versions of one code side by side, the later one compared with the earlier as with a counterpart") {
    const fs::path dir = fresh_dir("client_versions");
    // Version 1 is richardson's map; version 2 the same code again; version 3 a change that keeps
    // the order but leaves the map (no_squish's). Each later version names version 1 its counterpart.
    const fs::path v1 = client_file(dir, "code_v1", "richardson", "", "claims = \"richardson\"\n");
    const fs::path v2 = client_file(dir, "code_v2", "richardson", "", "claims = \"richardson\"\ncounterpart = \"code_v1\"\n");
    const fs::path v3 = client_file(dir, "code_v3", "no_squish", "", "claims = \"richardson\"\ncounterpart = \"code_v1\"\n");
    const std::vector<std::string> clients = {"--client", v1.string(), "--client", v2.string(), "--client", v3.string()};
    auto args = clients;
    args.insert(args.end(), {"run", "--scenes", "asymmetric_free", "--schemes", "code_v1,code_v2,code_v3", "--dt", "0.05,0.025,0.0125",
                             "--out", (dir / "run").string()});
    const Cli r = cli(args);
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    const std::string report = read(dir / "run" / "report.md");
    CHECK(std::regex_search(report, std::regex(R"(\| `code_v2` \| `code_v1` \| `asymmetric_free` \| 0 \(dt 0.05\) \| 0 \| 0.0125 \| 0 \| the same, to round-off \|)")));
    CHECK(std::regex_search(report, std::regex(R"(\| `code_v3` \| `code_v1` \| `asymmetric_free` \| [0-9.e-]+ \(dt 0.05\) .*\| another map: the difference falls as dt\^2\.)")));
    // A counterpart client whose program fails: said, not taken for another map.
    const fs::path broken = client_file(dir, "code_broken", "richardson", "--crash", "claims = \"richardson\"\n");
    const fs::path v4 = client_file(dir, "code_v4", "richardson", "", "claims = \"richardson\"\ncounterpart = \"code_broken\"\n");
    const Cli against_broken = cli({"--client", broken.string(), "--client", v4.string(), "run", "--scenes", "asymmetric_free", "--schemes",
                                    "code_v4", "--dt", "0.05,0.025", "--out", (dir / "broken").string()});
    REQUIRE(against_broken.status == 0);
    CHECK_THAT(read(dir / "broken" / "report.md"), Catch::Contains("| `code_v4` | `code_broken` | `asymmetric_free` | nan") &&
                                                       Catch::Contains("not compared: its counterpart gave no trajectory here"));
    // Nor does one whose file does not take the scene: its program is never run there.
    const fs::path narrow = client_file(dir, "code_narrow", "richardson", "", "claims = \"richardson\"\n");
    std::string text = read(narrow);
    text.replace(text.find("scenes = ["), text.find('\n', text.find("scenes = [")) - text.find("scenes = ["), "scenes = [\"asymmetric_free\"]");
    write(narrow, text);
    const fs::path v5 = client_file(dir, "code_v5", "richardson", "", "claims = \"richardson\"\ncounterpart = \"code_narrow\"\n");
    REQUIRE(cli({"--client", narrow.string(), "--client", v5.string(), "run", "--scenes", "dipole_top", "--schemes", "code_v5", "--dt",
                 "0.01,0.005", "--out", (dir / "narrow").string()})
                .status == 0);
    CHECK_THAT(read(dir / "narrow" / "report.md"), Catch::Contains("| `code_v5` | `code_narrow` | `dipole_top` | nan") &&
                                                       Catch::Contains("not compared: its counterpart gave no trajectory here"));
    // The same in a gate: same_map_as may name a client.
    write(dir / "gate.toml", "[[check]]\nscene = \"asymmetric_free\"\nschemes = [\"code_v2\", \"code_v3\"]\nsame_map_as = \"code_v1\"\n"
                             "dt = [0.05]\n");
    auto gate = clients;
    gate.insert(gate.end(), {"gate", (dir / "gate.toml").string()});
    const Cli g = cli(gate);
    CHECK(g.status == 1);
    CHECK_THAT(g.out, Catch::Contains("PASS asymmetric_free/code_v2") && Catch::Contains("FAIL asymmetric_free/code_v3"));
    // A counterpart must be loaded first (in a process of its own: this one holds code_v1 already).
    const Cli bad = binary({"--client", v2.string(), "--client", v1.string(), "list"});
    CHECK(bad.status == 2);
    CHECK_THAT(bad.err, Catch::Contains("counterpart 'code_v1' is neither a built-in scheme nor a client loaded before this one"));
    fs::remove_all(dir);
}

TEST_CASE("clients: a gate's same_map_as passes the counterpart's own map and fails another second-order one") {
    const fs::path dir = fresh_dir("client_map_same_map");
    const fs::path same = client_file(dir, "client_map_same", "richardson", "", "claims = \"richardson\"\ncounterpart = \"richardson\"\n");
    // no_squish is second order too: a change that keeps the order but leaves richardson's map.
    const fs::path other = client_file(dir, "client_map_other", "no_squish", "", "claims = \"richardson\"\ncounterpart = \"richardson\"\n");
    write(dir / "gate.toml",
          "[[check]]\nname = \"same map as richardson\"\nscene = \"asymmetric_free\"\nschemes = [\"client_map_same\", \"client_map_other\"]\n"
          "same_map_as = \"richardson\"\ndt = [0.05, 0.025]\n");
    const Cli r = cli({"--client", same.string(), "--client", other.string(), "gate", (dir / "gate.toml").string(), "--junit",
                       (dir / "junit.xml").string()});
    INFO(r.out << r.err);
    CHECK(r.status == 1);
    // JUnit's time: the client's program's wall time, not 0.
    const std::string junit = read(dir / "junit.xml");
    const auto testcase = junit.find("<testcase classname=\"rotbench.gate.client_map_same\"");
    REQUIRE(testcase != std::string::npos);
    const auto time = junit.find("time=\"", testcase);
    CHECK(std::stod(junit.substr(time + 6)) > 0.0);
    CHECK_THAT(r.out, Catch::Contains("PASS asymmetric_free/client_map_same: client_map_same: same map as richardson on asymmetric_free: largest "
                                      "difference from richardson"));
    CHECK_THAT(r.out, Catch::Contains("for the angular velocity): the same map"));
    CHECK_THAT(r.out, Catch::Contains("FAIL asymmetric_free/client_map_other"));
    CHECK_THAT(r.out, Catch::Contains("another map"));
    // Only a client measured against that counterpart can be judged so.
    write(dir / "bad.toml", "[[check]]\nscene = \"asymmetric_free\"\nschemes = [\"no_squish\"]\nsame_map_as = \"richardson\"\ndt = [0.05]\n");
    const Cli bad = cli({"gate", (dir / "bad.toml").string()});
    CHECK(bad.status == 2);
    CHECK_THAT(bad.err, Catch::Contains("same_map_as = 'richardson' judges clients whose counterpart it is; 'no_squish' is not a client"));
    fs::remove_all(dir);
}

TEST_CASE("clients: the report says whether a client is its counterpart's map, to round-off, or another and why") {
    const fs::path dir = fresh_dir("client_report");
    const fs::path same = client_file(dir, "client_same", "no_squish", "", "claims = \"no_squish\"\ncounterpart = \"no_squish\"\n");
    const fs::path other = client_file(dir, "client_other", "fincham", "",
                                       "claims = \"fincham\"\ncounterpart = \"no_squish\"\ncounterpart_note = \"it is fincham, not no_squish\"\n");
    const Cli r = cli({"--client", same.string(), "--client", other.string(), "run", "--scenes", "asymmetric_free", "--schemes",
                       "client_same,client_other", "--quick", "--quiet", "--out", (dir / "out").string()});
    INFO(r.err);
    REQUIRE(r.status == 0);
    const std::string md = read(dir / "out" / "report.md");
    CHECK_THAT(md, Catch::Contains("| `client_same` | `no_squish` | `asymmetric_free` | 0 (dt 0.1) |"));
    CHECK_THAT(md, Catch::Contains("| the same, to round-off |"));
    // fincham against no_squish: two second-order maps, so their difference falls as dt^2.
    CHECK_THAT(md, Catch::Contains("another map: the difference falls as dt^2.0") && Catch::Contains("it is fincham, not no_squish |"));
    // The judgement itself, from the run store: the same map for one, another of order 2 for the other.
    const auto verdicts = counterpart_verdicts(describe(read_results(dir / "out"), read_schemes(dir / "out")));
    REQUIRE(verdicts.size() == 2);
    for (const auto& v : verdicts) {
        INFO(v.client);
        CHECK(v.same_map == (v.client == "client_same"));
        if (!v.same_map) CHECK(v.order == Approx(2.0).margin(0.1));
    }
    fs::remove_all(dir);
}

TEST_CASE("clients: the Yade adapter leaves nothing outside its working directory", "[slow]") {
    // Yade makes /tmp/yade-XXXXXX whatever TMPDIR says and keeps an IPython profile in ~/.ipython.
    const fs::path dir = fresh_dir("yade_leaves_nothing");
    fs::create_directories(dir / "work");
    fs::create_directories(dir / "home");
    write(dir / "work" / "scene.json", client_scene_json(*make_scene("dipole_top"), {"dipole_top", "x", 0.01, 0.1}, 0.1, 10));
    const std::string adapter = std::string(ROTBENCH_SOURCE_DIR) + "/examples/clients/yade/yade_newton.py";
    REQUIRE(run_program({"/usr/bin/env", "-C", (dir / "work").string(), "HOME=" + (dir / "home").string(), "python3", adapter, "exact",
                         "scene.json", "trajectory.csv"}) == 0);
    const std::string rows = read(dir / "work" / "trajectory.csv");
    CHECK(std::count(rows.begin(), rows.end(), '\n') == 12);  // the header, t = 0 and ten steps
    const std::string yade_tmp = read(dir / "work" / "yade_tmp");
    CHECK_THAT(yade_tmp, Catch::StartsWith("/tmp/yade-"));  // named by Yade itself ...
    CHECK_FALSE(fs::exists(yade_tmp));                       // ... and gone
    CHECK(fs::is_empty(dir / "home"));
    fs::remove_all(dir);
}

TEST_CASE("clients: control characters in a client file's words do not reach the terminal through `list`") {
    const fs::path dir = fresh_dir("client_controls");
    const fs::path file = client_file(dir, "client_controls", "no_squish", "", "claims = \"no_squish\"\nsummary = \"a\\u001b[2Jb\"\n");
    const Cli r = cli({"--client", file.string(), "list"});
    REQUIRE(r.status == 0);
    CHECK(r.out.find('\x1b') == std::string::npos);
    CHECK_THAT(r.out, Catch::Contains("a\\x1B[2Jb"));
    fs::remove_all(dir);
}
