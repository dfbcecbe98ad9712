// covopt: the command-line front end. Everything but the process lives in covopt_cli_lib.
#include <iostream>

#include "app.hpp"

int main(int argc, char** argv) {
  return covopt::cli::RunCli(argc, argv, std::cout, std::cerr);
}
