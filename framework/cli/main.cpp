#include <iostream>

#include "antipode/config.hpp"

int main() {
  std::cout << "antipode " << ANTIPODE_VERSION << "\n";
  return 0;
}
