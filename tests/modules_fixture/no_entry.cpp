// A shared library without the module entry point: the loader must refuse it, naming the file.
extern "C" __attribute__((visibility("default"))) int not_a_maquette_module() { return 1; }
