// contact-suite: a verification test suite for finite-element contact mechanics.

#include "apps/command_line.hpp"

int main(int argc, char** argv) {
  return cs::apps::run_command_line(argc, argv);
}
