#include "harness/cli.hpp"

#include <iostream>

int main(int argc, char** argv) { return rotbench::run_cli(argc, argv, std::cout, std::cerr); }
