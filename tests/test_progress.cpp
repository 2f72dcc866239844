// Progress of the long verbs: counts, the item in flight, the time left; nothing when quiet.
#include "harness/store/progress.hpp"

#include <catch2/catch.hpp>
#include <sstream>

using namespace rotbench;

TEST_CASE("progress on a terminal shows the counts, the item running and, after a tenth of the work, the time left") {
    std::ostringstream err, out;
    {
        Progress p(err, Progress::Mode::terminal, "run", {1.0, 1.0, 8.0});
        p.started(0, "asymmetric_free direct dt=0.1");
        CHECK_THAT(err.str(), Catch::Contains("run: 0 of 3 done, running asymmetric_free direct dt=0.1"));
        CHECK_THAT(err.str(), !Catch::Contains("left"));  // nothing done: no estimate
        p.finished(0);
        p.note(out, "asymmetric_free direct trajectory dt=0.1 FAILED: blew up");
        CHECK(out.str() == "asymmetric_free direct trajectory dt=0.1 FAILED: blew up\n");
        CHECK_THAT(err.str(), Catch::Contains("run: 1 of 3 done, about "));  // 1 of 10 weights done: an estimate
        CHECK_THAT(err.str(), Catch::Contains(" s left"));
    }
    CHECK(err.str().substr(err.str().size() - 4) == "\r\033[K");  // the status line cleared at the end
}

TEST_CASE("quiet progress writes nothing, and a log gets no line before 5 s have passed") {
    std::ostringstream quiet_err, log_err, out;
    {
        Progress quiet(quiet_err, Progress::Mode::quiet, "run", {1.0});
        quiet.started(0, "x");
        quiet.finished(0, true);
        Progress log(log_err, Progress::Mode::lines, "stability", {1.0, 1.0});
        log.started(0, "x");
        log.finished(0);
    }
    CHECK(quiet_err.str().empty());
    CHECK(log_err.str().empty());
    CHECK(Progress::mode_for(quiet_err, false) == Progress::Mode::lines);  // not the process's stderr
    CHECK(Progress::mode_for(quiet_err, true) == Progress::Mode::quiet);
}
