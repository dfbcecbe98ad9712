// The start-up floor covopt's `--version` is measured against (bench/startup/measure.sh):
// a C++ program that links libstdc++ and prints one line with it.
#include <iostream>

int main() {
  std::cout << "hello, world\n";
  return 0;
}
