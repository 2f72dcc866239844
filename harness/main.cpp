// rotbench: dispatches to the verbs of harness/cli/, one file each. Its own executable is the
// worker that plug-in runs are isolated in (harness/exec/isolation.hpp).
#include "harness/cli/cli.hpp"
#include "harness/exec/isolation.hpp"

#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
    std::error_code ec;
    rotbench::set_worker_executable(std::filesystem::read_symlink("/proc/self/exe", ec).string());
    const int status = rotbench::run_cli(argc, argv, std::cout, std::cerr);
    // What a verb printed and the terminal, a pipe or a full disk did not take is a lost output.
    if (!(std::cout << std::flush)) {
        std::cerr << "rotbench: could not write to the standard output\n";
        return status == 0 || status == 1 ? 3 : status;
    }
    return status;
}
