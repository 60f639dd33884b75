// Runs the real `maquette` program (as a user would) and captures its output and exit code.
#pragma once

#include <string>

namespace maquette::test {

struct CliResult {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

// Runs `maquette ARGS` through /bin/sh (so ARGS may quote), with `env` ("NAME=value ...")
// added to the environment.
CliResult run_maquette(const std::string& args, const std::string& env = "");

// `WRAPPER maquette ARGS`: the program run by another, e.g. "prlimit --as=N" (a memory cap) or
// "setpriv --reuid=65534 ..." (another user).
CliResult run_maquette_under(const std::string& wrapper, const std::string& args);

// Why `maquette` cannot be run under an address-space cap (prlimit --as) here, or "" when it can:
// no prlimit, or a sanitizer build (its shadow memory reserves terabytes of address space at
// start, so any cap fails it before main).
std::string address_space_cap_unavailable();

// Why a peak resident set size of `maquette` says nothing of the program's own, or "" when it
// does: a sanitizer build adds shadow memory in proportion to what the program touches, and
// AddressSanitizer keeps freed blocks resident in its quarantine (256 MiB).
std::string resident_memory_unmeasurable();

// `maquette ARGS` as run_maquette, stopped with SIGINT if still running after `seconds` (for a
// command that may not return, such as a server): exit code 124 then.
CliResult run_maquette_limited(const std::string& args, int seconds);

// `maquette ARGS` with the dynamic loader's trace (LD_DEBUG=files) in `err`: it names every
// library the process loads (a plug-in as "file=" + plugin_path(its file)).
CliResult run_maquette_traced(const std::string& args);

// The loader's trace of a plain start (`maquette --version`, traced as above), for tests of what
// every command loads. Throws std::runtime_error if the program fails or leaves no trace.
std::string start_trace();

// Where the program finds its plug-in `file`: PREFIX/lib/file for PREFIX/bin/maquette.
std::string plugin_path(const std::string& file);

// An install of the program without its plug-ins under `prefix`: bin/maquette (a copy) and
// lib/libmaquette.so (a link to the build's). Returns the program's path.
std::string install_without_plugins(const std::string& prefix);

// Starts `maquette ARGS` (output discarded) and returns its process id, for tests that kill it.
int spawn_maquette(const std::string& args, const std::string& env = "");

// The standard output of a shell command (an oracle such as cs2cs or ogrinfo).
std::string shell_output(const std::string& command);

// A fresh empty directory under the system temp dir, removed at process exit.
std::string temp_dir();

// SHA-256-free content fingerprint of a file (size + FNV-1a of bytes), "" when missing.
std::string file_fingerprint(const std::string& path);

}  // namespace maquette::test
