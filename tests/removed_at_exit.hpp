// A scratch file or folder shared by the tests (or the fuzzer inputs) of one process, removed
// when the process ends: a static one's destructor runs at exit(), libFuzzer's included.
#pragma once

#include <filesystem>
#include <system_error>

namespace rotbench::test {

struct RemovedAtExit {
    std::filesystem::path path;
    ~RemovedAtExit() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
};

}  // namespace rotbench::test
