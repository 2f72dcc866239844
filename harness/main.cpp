// rotbench: dispatches to the verbs of harness/cli/, one file each.
#include "harness/cli/cli.hpp"

#include <iostream>

int main(int argc, char** argv) { return rotbench::run_cli(argc, argv, std::cout, std::cerr); }
