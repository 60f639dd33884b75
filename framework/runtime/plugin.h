// Plug-ins: shared libraries of the program itself, opened only by the command that needs them,
// so that what they link (MPI, the HTTP server) is not loaded by every start of the program. They
// live in <directory of the program>/../lib, beside libmaquette, in the build tree as installed.
#pragma once

#include <filesystem>
#include <string>

namespace maquette {

// The directory above the program's (PREFIX for PREFIX/bin/maquette), from /proc/self/exe.
std::filesystem::path program_prefix();

// The address of `symbol` in plug-in `file` (a file name in program_prefix()/lib), opened with
// dlopen and never closed: its code may run until the process ends. Throws maquette::Error naming
// the path looked for when the file cannot be opened or lacks the symbol.
void* plugin_symbol(const std::string& file, const char* symbol);

// plugin_symbol as a function of type `Function`.
template <class Function>
Function* plugin_function(const std::string& file, const char* symbol) {
  return reinterpret_cast<Function*>(plugin_symbol(file, symbol));
}

}  // namespace maquette
