// maze_mapper_controller: the executable a real Webots launches from
// controllers/maze_mapper_controller/ (built with MAZE_MAPPER_WEBOTS=ON). Webots passes the
// robot's controllerArgs as argv; robot::console_main has the contract.

#include <iostream>
#include <string>
#include <vector>

#include "robot/console_main.hpp"

int main(int argc, char **argv) {
  const std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
  return robot::console_main(args, std::cout, std::cerr);
}
