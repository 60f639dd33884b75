// runtime_kill_child PIPELINE MODULE_DIR [--resume]: runs a pipeline with the modules of one
// directory, on 2 threads, quietly. kill_test.cpp kills it at various moments.
#include <cstring>
#include <iostream>

#include "core/error.h"
#include "runtime/runner.h"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: runtime_kill_child PIPELINE MODULE_DIR [--resume]\n";
    return 2;
  }
  try {
    const auto registry = maquette::OperatorRegistry::load({argv[2]});
    const auto pipeline = maquette::load_pipeline(argv[1], registry);
    maquette::RunOptions options;
    options.threads = 2;
    options.quiet = true;
    options.resume = argc > 3 && std::strcmp(argv[3], "--resume") == 0;
    maquette::run_pipeline(pipeline, options);
  } catch (const maquette::Error& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
